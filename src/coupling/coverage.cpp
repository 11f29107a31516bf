#include "sandflow/coupling/coverage.hpp"

#include <algorithm>
#include <cmath>

#include "sandflow/core/prefetch.hpp"

namespace sf::coupling {
namespace {

// Wraps a cell index on a periodic axis; -1 when it lies beyond a wall.
int wrap(int k, int n, bool periodic) {
  if (k >= 0 && k < n) return k;
  if (!periodic) return -1;
  return ((k % n) + n) % n;
}

double measure(const Footprint& f, const Vec2& lo, double h, int subcells) {
  if (subcells == kExact) return std::clamp(f.cellArea(lo, h) / (h * h), 0.0, 1.0);
  const double d = h / subcells;
  int in = 0;
  for (int b = 0; b < subcells; ++b)
    for (int a = 0; a < subcells; ++a) in += f.inside(lo + Vec2((a + 0.5) * d, (b + 0.5) * d));
  return double(in) / (subcells * subcells);
}

// A convex footprint row by row: each row's touched and fully held cells are
// intervals (Footprint::band), so only the cells at a row's two ends are
// measured. So are the cells measured as 1 (all subcell centres inside: for a
// convex shape, the full interval grown by a few cells), and a cell is
// interior when those intervals of its row and of the rows above and below
// reach past it on both sides. Gives the cells, in the order and with the
// classification, of the cell-by-cell pass.
bool coverByRows(const Footprint& f, const Vec2& reference, const Grid& g, int subcells, int i0,
                 int i1, int j0, int j1, CellCovers& out) {
  const int hgt = j1 - j0 + 1;
  struct Row {
    int lo = 1, hi = 0;          // touched cells, clipped to [i0, i1]; empty: lo > hi
    int fullLo = 1, fullHi = 0;  // cells that hold the band
    int oneLo = 1, oneHi = 0;    // cells whose ratio is 1 (a superset)
    std::size_t at = 0;          // the row's ratios in `eps`, from cell lo
  };
  thread_local std::vector<Row> rows;  // with an empty row above and below
  thread_local std::vector<double> eps;
  rows.assign(std::size_t(hgt + 2), Row{});
  eps.clear();
  const double h = g.h, ox = g.origin.x();
  auto cellLo = [&](int i) { return ox + i * h; };
  for (int b = 0; b < hgt; ++b) {
    Footprint::Band band;
    if (!f.band(g.origin.y() + (j0 + b) * h, g.origin.y() + (j0 + b + 1) * h, band)) return false;
    Row& r = rows[b + 1];
    if (band.lo > band.hi) continue;
    // A band's ends may lie far beyond the lattice (an element at x = 1e23):
    // brought to a cell or two past the clip first, so that they convert to
    // int and the searches below stay short. Which cells in [i0, i1] the band
    // touches or holds does not change.
    const double left = cellLo(i0 - 2), right = cellLo(i1 + 3);
    band.lo = std::clamp(band.lo, left, right), band.hi = std::clamp(band.hi, left, right);
    band.fullLo = std::clamp(band.fullLo, left, right);
    band.fullHi = std::clamp(band.fullHi, left, right);
    r.lo = std::max(i0, int(std::floor((band.lo - ox) / h)));
    r.hi = std::min(i1, int(std::floor((band.hi - ox) / h)));
    if (r.lo > r.hi) continue;
    if (band.fullLo <= band.fullHi) {
      // Cell i holds the band when cellLo(i) >= fullLo and cellLo(i + 1) <= fullHi.
      int a = int(std::ceil((band.fullLo - ox) / h));
      int z = int(std::floor((band.fullHi - ox) / h)) - 1;
      while (cellLo(a) < band.fullLo) ++a;
      while (cellLo(a - 1) >= band.fullLo) --a;
      while (cellLo(z + 1) > band.fullHi) --z;
      while (cellLo(z + 2) <= band.fullHi) ++z;
      r.fullLo = std::max(a, r.lo), r.fullHi = std::min(z, r.hi);
    }
    r.at = eps.size();
    eps.resize(r.at + (r.hi - r.lo + 1), 1.0);
    // The cells left and right of the full ones (or all, when none is full).
    const int leftEnd = r.fullLo <= r.fullHi ? r.fullLo - 1 : r.hi;
    const int rightStart = r.fullLo <= r.fullHi ? r.fullHi + 1 : r.hi + 1;
    const double y0 = g.origin.y() + (j0 + b) * h;
    if (subcells == kExact) {
      auto ratios = [&](int first, int last) {
        if (first > last) return;
        double* out = eps.data() + r.at + (first - r.lo);
        f.rowAreas(ox, y0, h, first, last, out);
        for (int i = first; i <= last; ++i)
          out[i - first] = std::clamp(out[i - first] / (h * h), 0.0, 1.0);
      };
      ratios(r.lo, leftEnd);
      ratios(rightStart, r.hi);
    } else {
      for (int i = r.lo; i <= r.hi; ++i)
        if (i <= leftEnd || i >= rightStart)
          eps[r.at + (i - r.lo)] = measure(f, Vec2(cellLo(i), y0), h, subcells);
    }
    auto one = [&](int i) { return eps[r.at + (i - r.lo)] >= 1; };
    r.oneLo = r.fullLo, r.oneHi = r.fullHi;
    if (r.oneLo > r.oneHi) {
      r.oneLo = r.lo;
      while (r.oneLo <= r.hi && !one(r.oneLo)) ++r.oneLo;
      r.oneHi = r.oneLo;
      if (r.oneLo > r.hi) r.oneLo = 1, r.oneHi = 0;
    }
    if (r.oneLo <= r.oneHi) {
      while (r.oneLo > r.lo && one(r.oneLo - 1)) --r.oneLo;
      while (r.oneHi < r.hi && one(r.oneHi + 1)) ++r.oneHi;
    }
  }
  const double rx = reference.x(), ry = reference.y();
  for (int b = 0; b < hgt; ++b) {
    const Row &r = rows[b + 1], &below = rows[b], &above = rows[b + 2];
    if (r.lo > r.hi) continue;
    const int j = wrap(j0 + b, g.ny, g.periodicY);
    if (j < 0) continue;
    const bool inner = below.oneLo <= below.oneHi && above.oneLo <= above.oneHi;
    const int innerLo = inner ? std::max({r.oneLo, below.oneLo, above.oneLo}) + 1 : 1;
    const int innerHi = inner ? std::min({r.oneHi, below.oneHi, above.oneHi}) - 1 : 0;
    // The row's cells into slots taken at once (prefetched in cover) through
    // pointers held in registers: per cell, a slot taken one at a time and
    // the scratch ratios reached through their thread-local vector cost more
    // than writing the record. The arm, the cell's centre less the reference
    // point, is worked out component by component as the cell-by-cell pass
    // has it.
    const double* rowEps = eps.data() + r.at;
    const double armY = (g.origin.y() + (j0 + b + 0.5) * h) - ry;
    const std::size_t start = out.size();
    out.resize(start + std::size_t(r.hi - r.lo + 1));
    CellCover* to = out.data() + start;
    // Most rows lie inside the lattice and wholly in open chunks: no test a cell.
    const bool plain = r.lo >= 0 && r.hi < g.nx && g.rowOpen(r.lo, r.hi, j);
    for (int i = r.lo; i <= r.hi; ++i) {
      const double e = rowEps[i - r.lo];
      if (e <= 0) continue;
      int wi = i;
      if (!plain) {
        wi = wrap(i, g.nx, g.periodicX);
        if (wi < 0 || !g.isOpen(wi, j)) continue;
      }
      to->arm = Vec2((ox + (i + 0.5) * h) - rx, armY);
      to->eps = e, to->i = wi, to->j = j;
      to->interior = i >= innerLo && i <= innerHi;
      ++to;
    }
    out.resize(std::size_t(to - out.data()));
  }
  return true;
}

// The cell that coordinate x lies in along an axis, unwrapped. An element may
// be anywhere (x = 1e23), and an int ends at 2^31: so far out, a clamped index
// still touches no cell of its footprint.
int cellOf(double x, double origin, double h) {
  return int(std::floor(std::clamp((x - origin) / h, -1e9, 1e9)));
}

}  // namespace

int selfOverlap(const Footprint& f, const Grid& g) {
  if (f.everywhere) return 0;
  const double h = g.h;
  const bool x =
      g.periodicX &&
      cellOf(f.box.hi.x(), g.origin.x(), h) - cellOf(f.box.lo.x(), g.origin.x(), h) >= g.nx;
  const bool y =
      g.periodicY &&
      cellOf(f.box.hi.y(), g.origin.y(), h) - cellOf(f.box.lo.y(), g.origin.y(), h) >= g.ny;
  return (x ? 1 : 0) | (y ? 2 : 0);
}

void cover(const Footprint& f, const Vec2& reference, const Grid& g, int subcells,
           CellCovers& out) {
  // The cells to visit, unwrapped: the footprint's box, or the whole lattice.
  int i0 = 0, i1 = g.nx - 1, j0 = 0, j1 = g.ny - 1;
  if (!f.everywhere) {
    i0 = cellOf(f.box.lo.x(), g.origin.x(), g.h), i1 = cellOf(f.box.hi.x(), g.origin.x(), g.h);
    j0 = cellOf(f.box.lo.y(), g.origin.y(), g.h), j1 = cellOf(f.box.hi.y(), g.origin.y(), g.h);
    // A box wider than a periodic lattice would visit cells twice; the cells
    // where it meets its own image are then covered wrongly (selfOverlap).
    if (g.periodicX) i1 = std::min(i1, i0 + g.nx - 1);
    if (g.periodicY) j1 = std::min(j1, j0 + g.ny - 1);
    if (!g.periodicX) i0 = std::max(i0, 0), i1 = std::min(i1, g.nx - 1);
    if (!g.periodicY) j0 = std::max(j0, 0), j1 = std::min(j1, g.ny - 1);
  }
  if (i0 > i1 || j0 > j1) return;
  const int w = i1 - i0 + 1, hgt = j1 - j0 + 1;
  // The slots this solid's cells will most likely take (`out` keeps its
  // capacity from the last step), asked for ahead of the area work: the
  // lattice's sweep has evicted them since.
  prefetchForWrite(out.data() + out.size(), (out.capacity() - out.size()) * sizeof(CellCover));
  if (!f.everywhere && coverByRows(f, reference, g, subcells, i0, i1, j0, j1, out)) return;
  // Coverage on the visited block, with a ring of zeros for the interior test.
  thread_local std::vector<double> eps;  // scratch, reused: no allocation per element
  eps.assign(std::size_t(w + 2) * (hgt + 2), 0.0);
  auto at = [&](int a, int b) -> double& { return eps[std::size_t(b + 1) * (w + 2) + (a + 1)]; };
  // Where a cell's centre is seen from the reference point: a container, which
  // spans the lattice, is seen at the nearest periodic image.
  const Vec2 period(g.nx * g.h, g.ny * g.h);
  auto offset = [&](int a, int b) {
    Vec2 d = g.origin + Vec2((i0 + a + 0.5) * g.h, (j0 + b + 0.5) * g.h) - reference;
    if (f.everywhere && g.periodicX) d.x() -= period.x() * std::round(d.x() / period.x());
    if (f.everywhere && g.periodicY) d.y() -= period.y() * std::round(d.y() / period.y());
    return d;
  };
  const double halfDiagonal = g.h * std::sqrt(0.5);
  const Vec2 half(0.5 * g.h, 0.5 * g.h);
  for (int b = 0; b < hgt; ++b)
    for (int a = 0; a < w; ++a) {
      const Vec2 centre = reference + offset(a, b);
      const double d = f.distance(centre);
      // The cell's corner as the row-by-row pass has it; a container's cell
      // at its image nearest the reference.
      const Vec2 lo =
          f.everywhere ? Vec2(centre - half) : g.origin + Vec2((i0 + a) * g.h, (j0 + b) * g.h);
      at(a, b) = d <= -halfDiagonal            ? 1.0
                 : d - f.slack >= halfDiagonal ? 0.0
                                               : measure(f, lo, g.h, subcells);
    }
  // A container's block is the whole lattice: its ring continues periodically,
  // and beyond a wall it is solid.
  if (f.everywhere)
    for (int b = -1; b <= hgt; ++b)
      for (int a = -1; a <= w; ++a) {
        if (a >= 0 && a < w && b >= 0 && b < hgt) continue;
        const int wa = wrap(a, w, g.periodicX), wb = wrap(b, hgt, g.periodicY);
        at(a, b) = (wa < 0 || wb < 0) ? 1.0 : at(wa, wb);
      }
  for (int b = 0; b < hgt; ++b)
    for (int a = 0; a < w; ++a) {
      const double e = at(a, b);
      if (e <= 0) continue;
      const int i = wrap(i0 + a, g.nx, g.periodicX), j = wrap(j0 + b, g.ny, g.periodicY);
      if (i < 0 || j < 0 || !g.isOpen(i, j)) continue;
      bool interior = e >= 1;
      for (int db = -1; db <= 1 && interior; ++db)
        for (int da = -1; da <= 1 && interior; ++da) interior = at(a + da, b + db) >= 1;
      out.push_back({offset(a, b), e, i, j, interior});
    }
}

}  // namespace sf::coupling
