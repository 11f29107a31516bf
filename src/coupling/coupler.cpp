#include "sandflow/coupling/coupler.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "coupler_detail.hpp"
#include "sandflow/core/parallel.hpp"
#include "sandflow/core/prefetch.hpp"
#include "sandflow/dem/shape.hpp"

namespace sf::coupling {
namespace {

using Clock = Profile::Clock;

Grid gridOf(const lb::Lattice& lattice) {
  const lb::ResolvedLattice& p = lattice.params();
  Grid g;
  g.origin = p.def.origin;
  g.h = p.h;
  g.nx = p.nx;
  g.ny = p.ny;
  g.periodicX = p.def.sides[lb::left].kind == lb::SideKind::periodic;
  g.periodicY = p.def.sides[lb::bottom].kind == lb::SideKind::periodic;
  return g;
}

bool covers(const dem::Bodies& b, int s) {
  return !b.ghost[s] && b.shape[s]->type() != dem::ShapeType::wall;
}

// True when a solid of this centre and reach lies wholly beyond a side that
// is not periodic, a cell clear of it: it covers no cell (elements that
// wait above a lattice cost no coverage pass).
bool beyondWalls(const Grid& g, const Vec2& x, double reach) {
  const Vec2 lo = g.origin - Vec2::Constant(g.h);
  const Vec2 hi = g.origin + Vec2((g.nx + 1) * g.h, (g.ny + 1) * g.h);
  const bool outX = x.x() + reach < lo.x() || x.x() - reach > hi.x();
  const bool outY = x.y() + reach < lo.y() || x.y() - reach > hi.y();
  return (!g.periodicX && outX) || (!g.periodicY && outY);
}

}  // namespace

namespace detail {

// Static buoyancy of slot s on the immersed area: the element's own area when
// the lattice holds all of it, `submerged` cells' area when it sticks out.
Vec2 buoyancyOf(const dem::Bodies& b, int s, double submerged, const lb::Lattice& lattice,
                const Vec2& gravity) {
  if (submerged == 0) return Vec2::Zero();
  const lb::ResolvedLattice& p = lattice.params();
  const Grid grid = gridOf(lattice);
  const Vec2 lo = p.def.origin, hi = lo + Vec2(p.nx * p.h, p.ny * p.h);
  const dem::Box box = b.shape[s]->bounds(b.x[s], b.angle[s]);
  const bool within = (grid.periodicX || (box.lo.x() >= lo.x() && box.hi.x() <= hi.x())) &&
                      (grid.periodicY || (box.lo.y() >= lo.y() && box.hi.y() <= hi.y()));
  const double area = within ? b.shape[s]->area() : submerged * p.h * p.h;
  return Vec2::Zero() - p.def.density * area * gravity;  // no -0 without gravity
}

}  // namespace detail

bool Coupler::needed(const lb::Lattice& lattice, const dem::Assembly& assembly) {
  if (!lattice.circles().empty()) return true;
  // Elements all beyond the walls: no pass at all (their fluid force is zero
  // either way), so that they cost what they cost without a lattice.
  const Grid grid = gridOf(lattice);
  const dem::Bodies& b = assembly.bodies();
  for (int s = 0; s < b.size(); ++s)
    if (!beyondWalls(grid, b.x[s], b.reach[s]) && covers(b, s))
      return true;  // the cheap test first
  return false;
}

bool Coupler::stale(const Cached& c, int id, const Vec2& x, double angle, double area, double reach,
                    double radius, bool outside, bool turns) const {
  return c.id != id || c.x != x || (turns && c.angle != angle) || c.area != area ||
         c.reach != reach || c.radius != radius || c.outside != outside;
}

void Coupler::prepare(lb::Lattice& lattice, const dem::Assembly& assembly, const Settings& settings,
                      const Vec2& gravity) {
  const auto t0 = Clock::now();
  const int threads = threads_.get();
  Grid grid = gridOf(lattice);
  const dem::Bodies& b = assembly.bodies();
  const int n = b.size();
  const std::vector<lb::CircleObstacle>& circles = lattice.circles();
  const bool remeasure =
      lattice.topologyVersion() != topology_ || settings.subcells != measuredWith_.subcells;
  topology_ = lattice.topologyVersion();
  measuredWith_ = settings;
  if (remeasure || rebuildEveryStep_) elements_.clear(), circles_.clear(), listKept_ = false;
  const std::size_t ownersBefore = elements_.size() + circles_.size();
  if (remeasure || open_.size() != std::size_t(grid.nx) * grid.ny) {
    open_.assign(std::size_t(grid.nx) * grid.ny, 0);
    openChunks_.assign(std::size_t(grid.openChunksPerRow()) * grid.ny, 1);
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i) {
        const bool fluid = lattice.kind(i, j) == lb::NodeKind::fluid;
        open_[std::size_t(j) * grid.nx + i] = fluid;
        if (!fluid) openChunks_[grid.openChunk(i, j)] = 0;
      }
  }
  grid.open = open_.data();
  grid.openChunks = openChunks_.data();
  elements_.resize(n);
  circles_.resize(circles.size());

  // 1. Coverage of whatever moved (or changed shape) since it was measured,
  //    kept to the cells that hold bulk fluid.
  // Each solid's cells, then their runs of consecutive nodes while the cells
  // are still in cache.
  auto measure = [&](Cached& c, const Footprint& f, const Vec2& reference) {
    cover(f, reference, grid, settings.subcells, c.cells);
    c.overlap = selfOverlap(f, grid);
    c.runs.clear();
    // (c.before holds the runs of the pose before, compared below.)
    // Consecutive nodes are the next cell of the same row (a row's last cell
    // and the next row's first have the padding between them).
    const std::size_t count = c.cells.size();
    for (std::size_t m = 0, end; m < count; m = end) {
      const int i = c.cells[m].i, j = c.cells[m].j;
      for (end = m + 1; end < count && c.cells[end].j == j && c.cells[end].i == i + int(end - m);)
        ++end;
      // Nodes fit 32 bits (the lattice's size limit is far below).
      c.runs.push_back(
          {std::uint32_t(lattice.nodeIndex(i, j)), std::int32_t(m), std::int32_t(end - m)});
    }
  };
  // A solid measured again keeps the list as it was when its runs (nodes,
  // cells) are those of its pose before: a small move changes only ratios.
  auto remeasured = [](Cached& c) { c.before.swap(c.runs), c.runs.clear(), c.measuredNow = true; };
  auto settle = [](Cached& c) {
    c.runsChanged =
        !std::equal(c.runs.begin(), c.runs.end(), c.before.begin(), c.before.end(),
                    [](const Run& x, const Run& y) {
                      return x.node == y.node && x.first == y.first && x.length == y.length;
                    });
  };
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads) if (n >= parallel::kCoverSolids)
  for (int s = 0; s < n; ++s) {
    Cached& c = elements_[s];
    c.runsChanged = false, c.measuredNow = false;
    if (!covers(b, s)) {
      if (c.id >= 0 || !c.runs.empty()) c = Cached{};  // (runsChanged)
      continue;
    }
    const dem::Shape& shape = *b.shape[s];
    // A disc's cells do not depend on its angle: one that only turns keeps them.
    const bool turns = shape.type() != dem::ShapeType::disc;
    if (!stale(c, b.id[s], b.x[s], b.angle[s], shape.area(), b.reach[s], 0, false, turns)) continue;
    // The new pose; the cells and runs vectors keep their capacity.
    c.id = b.id[s], c.x = b.x[s], c.angle = b.angle[s], c.area = shape.area();
    c.reach = b.reach[s], c.radius = 0, c.outside = false;
    c.cells.clear(), remeasured(c), c.overlap = 0;
    if (!beyondWalls(grid, b.x[s], b.reach[s]))  // else no cells: spares the footprint
      if (const auto f = footprintOf(shape, b.x[s], b.angle[s])) measure(c, *f, b.x[s]);
    settle(c);
  }
  for (std::size_t k = 0; k < circles.size(); ++k) {
    const lb::CircleObstacle& o = circles[k];
    Cached& c = circles_[k];
    c.runsChanged = false, c.measuredNow = false;
    if (!stale(c, o.id, o.centre, 0, 0, 0, o.radius, o.outside, false)) continue;
    c.id = o.id, c.x = o.centre, c.angle = 0, c.area = 0, c.reach = 0, c.radius = o.radius;
    c.outside = o.outside, c.cells.clear(), remeasured(c), c.overlap = 0;
    measure(c, *circleFootprint(o.centre, o.radius, o.outside), o.centre);
    settle(c);
  }

  overlap_ = SelfOverlap{};
  for (std::size_t o = 0; o < elements_.size() + circles_.size(); ++o) {
    const int axes = coverOf(std::int32_t(o)).overlap;
    if (axes == 0 || overlap_.count++ > 0) continue;  // the first names them
    overlap_.axes = axes;
    if (o < elements_.size())
      overlap_.element = b.id[o];
    else
      overlap_.obstacle = circles[o - elements_.size()].id;
  }

  Profile& profile = profile_.get();
  const auto t1 = profile.lap(Stage::coverageMeasure, t0);
  // 2. The pieces (each solid's cells, solid by solid: the order the force
  //    sums keep) in node order, and each node's pieces made a cell. Kept
  //    from the last step when every solid's runs are as they were.
  const int owners = n + int(circles.size());
  bool keep = listKept_ && std::size_t(owners) == ownersBefore;
  counts_ = CellCounts{};
  for (int o = 0; o < owners; ++o) {
    const Cached& c = coverOf(o);
    keep = keep && !c.runsChanged;
    if (c.measuredNow) counts_.remeasured += c.cells.size();
  }
  if (!keep) {
    pieceStart_.assign(owners + 1, 0);
    runs_.clear(), runOwner_.clear();
    runStart_.assign(owners + 1, 0);
    for (int o = 0; o < owners; ++o) {
      const Cached& c = coverOf(o);
      pieceStart_[o + 1] = pieceStart_[o] + c.cells.size();
      runStart_[o + 1] = runStart_[o] + std::int32_t(c.runs.size());
      runs_.insert(runs_.end(), c.runs.begin(), c.runs.end());
      runOwner_.insert(runOwner_.end(), c.runs.size(), o);
    }
    groupRuns();
  }
  listKept_ = !rebuildEveryStep_;
  const auto t2 = profile.lap(Stage::coverageSort, t1);
  // Rigid velocities (vx, vy, w) of the owners: elements as they are, or
  // solved with the exchange they will cause; circles as prescribed.
  velocity_.resize(n);
  for (int s = 0; s < n; ++s) velocity_[s] = Vec3(b.v[s].x(), b.v[s].y(), b.w[s]);
  const double toLattice = lattice.params().dt / lattice.params().h;
  std::vector<lb::CoveredCell>& cells = cellsBuffer_;  // reused: no fresh pages per step
  const bool blendNow = !settings.implicit;
  fillCells(circles, toLattice, blendNow, cells);
  const std::size_t total = cells.size();
  if (!blendNow) {
    solveVelocities(lattice, assembly, settings, cells, gravity);
    blendVelocities(lattice, circles, cells);
    // The first fastest cell of each chunk of cells.
    const std::ptrdiff_t cellChunks =
        (std::ptrdiff_t(total) + parallel::kCellChunk - 1) / parallel::kCellChunk;
    chunkFastest_.assign(cellChunks, Fastest{});
#pragma omp parallel for schedule(static) num_threads(threads) if (cellChunks > 1)
    for (std::ptrdiff_t c = 0; c < cellChunks; ++c) {
      Fastest best;
      for (std::ptrdiff_t k = c * parallel::kCellChunk;
           k < std::min(std::ptrdiff_t(total), (c + 1) * parallel::kCellChunk); ++k) {
        const double u2 = cells[k].ux * cells[k].ux + cells[k].uy * cells[k].uy;
        if (!cells[k].interior && u2 > best.u2) best = {u2, pieceOwner_[order_[cellStart_[k]]]};
      }
      chunkFastest_[c] = best;
    }
  }
  // The fastest surface that the fluid sees (interior cells move no fluid):
  // of the chunks' fastest, the first.
  fastest_ = SolidSpeed{};
  double fastest2 = 0;
  for (const Fastest& f : chunkFastest_) {
    if (!(f.u2 > fastest2)) continue;
    fastest2 = f.u2;
    fastest_.element = f.owner < n ? b.id[f.owner] : -1;
    fastest_.obstacle = f.owner >= n ? circles[f.owner - n].id : -1;
  }
  fastest_.mach = std::sqrt(fastest2);
  cells_ = total;
  for (const CellCounts& k : taskCounts_)
    counts_.partial += k.partial, counts_.interior += k.interior;
  // Ours now holds the old list; the new one ascends by node (groupRuns).
  lattice.swapCoveredCells(cells, settings.equilibriumInterior, true);
  profile.lap(Stage::coverageCells, t2);
}

[[gnu::always_inline]] inline Coupler::Motion Coupler::ownerMotion(
    std::int32_t owner, const std::vector<lb::CircleObstacle>& circles) const {
  const std::int32_t n = std::int32_t(elements_.size());
  if (owner < n) {
    const Vec3& v = velocity_[owner];
    return {Vec2(v.x(), v.y()), v.z()};
  }
  const lb::CircleObstacle& o = circles[owner - n];
  return {o.velocity, o.spin};
}

// The rigid velocity of an owner at arm from its reference point.
[[gnu::always_inline]] inline Vec2 Coupler::ownerVelocity(
    std::int32_t owner, const Vec2& arm, const std::vector<lb::CircleObstacle>& circles) const {
  const Motion m = ownerMotion(owner, circles);
  return m.v + spin(m.w, arm);
}

// Each cell's solid velocity: the coverage-weighted mean of its owners' rigid
// velocities at the cell centre, in lattice units.
[[gnu::always_inline]] inline Vec2 Coupler::cellVelocity(
    std::ptrdiff_t first, std::ptrdiff_t last, double epsSum,
    const std::vector<lb::CircleObstacle>& circles, double toLattice) const {
  double ux = 0, uy = 0;
  for (std::ptrdiff_t k = first; k < last; ++k) {
    const std::int32_t g = order_[k];
    const CellCover& p = piece(g);
    const Vec2 v = ownerVelocity(pieceOwner_[g], p.arm, circles);
    const double weight = p.eps / epsSum * toLattice;
    ux += weight * v.x();
    uy += weight * v.y();
  }
  return Vec2(ux, uy);
}

void Coupler::blendVelocities(const lb::Lattice& lattice,
                              const std::vector<lb::CircleObstacle>& circles,
                              std::vector<lb::CoveredCell>& cells) const {
  const double toLattice = lattice.params().dt / lattice.params().h;
  const std::ptrdiff_t count = std::ptrdiff_t(cells.size());
  // Cell by cell over its pieces in a fixed order: any thread count, same sums.
#pragma omp parallel for schedule(static) \
    num_threads(threads_.get()) if (count >= parallel::kBlendCells)
  for (std::ptrdiff_t c = 0; c < count; ++c) {
    const Vec2 u = cellVelocity(cellStart_[c], cellStart_[c + 1], epsSum_[c], circles, toLattice);
    cells[c].ux = u.x();
    cells[c].uy = u.y();
  }
}

// Stable LSD radix sort of `keys` (11 bits a pass): `order` lists their
// indices by key, equal keys in index order. Keys are nodes, which fit 32 bits
// (the lattice's size limit is far below).
void Coupler::radixSort(std::vector<std::uint32_t>& keys, std::vector<std::int32_t>& order) {
  constexpr int kBits = 11, kBuckets = 1 << kBits;
  const std::size_t count = keys.size();
  keysScratch_.resize(count);
  order.resize(count), orderScratch_.resize(count);
  std::uint32_t top = 0;
  for (std::size_t k = 0; k < count; ++k) {
    order[k] = std::int32_t(k);
    top = std::max(top, keys[k]);
  }
  std::vector<std::int32_t>& start = bucketStart_;
  start.resize(kBuckets + 1);
  for (int shift = 0; shift == 0 || (top >> shift) > 0; shift += kBits) {
    std::fill(start.begin(), start.end(), 0);
    for (std::uint32_t key : keys) ++start[((key >> shift) & (kBuckets - 1)) + 1];
    for (int d = 0; d < kBuckets; ++d) start[d + 1] += start[d];
    for (std::size_t k = 0; k < count; ++k) {
      const std::int32_t to = start[(keys[k] >> shift) & (kBuckets - 1)]++;
      keysScratch_[to] = keys[k];
      orderScratch_[to] = order[k];
    }
    keys.swap(keysScratch_);
    order.swap(orderScratch_);
    if (shift + kBits >= 32) break;
  }
}

// The runs in node order, laid end to end: a run that overlaps no other is a
// group of its own, whose cells are its pieces; runs that overlap (cells that
// several solids share) form one group, whose pieces are sorted one by one by
// node and piece. Each group's first cell and first entry of order_ are
// counted here, so that fillCells can fill the groups in parallel.
void Coupler::groupRuns() {
  const std::size_t runs = runs_.size();
  runKeys_.resize(runs);
  for (std::size_t r = 0; r < runs; ++r) runKeys_[r] = runs_[r].node;
  radixSort(runKeys_, runOrder_);  // stable: equal first nodes in owner order
  groups_.clear(), groupPieces_.clear();
  runCell_.assign(runs, -1);
  pieceOwner_.resize(pieceStart_.back());
  std::int32_t cellCount = 0, entries = 0;
  auto lastNode = [&](std::int32_t run) { return runs_[run].node + runs_[run].length - 1; };
  for (std::size_t q = 0; q < runs;) {
    std::size_t end = q + 1;
    std::uint32_t reach = lastNode(runOrder_[q]);
    while (end < runs && runKeys_[end] <= reach)
      reach = std::max(reach, lastNode(runOrder_[end++]));
    const Run& first = runs_[runOrder_[q]];
    if (end == q + 1) {
      groups_.push_back({runOrder_[q], first.length, cellCount, entries});
      runCell_[runOrder_[q]] = cellCount;
      cellCount += first.length, entries += first.length;
    } else {
      // The pieces of the overlapping runs, by node, equal nodes by piece.
      const std::size_t from = groupPieces_.size();
      for (std::size_t k = q; k < end; ++k) {
        const std::int32_t r = runOrder_[k];
        const std::int32_t g0 = std::int32_t(pieceStart_[runOwner_[r]]) + runs_[r].first;
        for (std::int32_t t = 0; t < runs_[r].length; ++t) {
          groupPieces_.push_back({runs_[r].node + std::uint32_t(t), g0 + t});
          pieceOwner_[g0 + t] = runOwner_[r];
        }
      }
      std::sort(groupPieces_.begin() + from, groupPieces_.end());
      std::int32_t distinct = 0;
      for (std::size_t k = from; k < groupPieces_.size(); ++k)
        distinct += k == from || groupPieces_[k].first != groupPieces_[k - 1].first;
      const auto keyed = groupPieces_.size() - from;
      groups_.push_back({-1 - std::int32_t(from), std::int32_t(keyed), cellCount, entries});
      cellCount += distinct, entries += std::int32_t(keyed);
    }
    q = end;
  }
  groups_.push_back({0, 0, cellCount, entries});  // the end
}

// The covered cells, group by group in parallel (any thread count, the same
// list): node, solid ratio, and, explicitly coupled, the solid velocity; each
// task notes its first fastest cell.
void Coupler::fillCells(const std::vector<lb::CircleObstacle>& circles, double toLattice,
                        bool blendNow, std::vector<lb::CoveredCell>& cells) {
  const std::ptrdiff_t groups = std::ptrdiff_t(groups_.size()) - 1;
  const std::size_t total = std::size_t(groups_.back().firstCell);
  const std::size_t pieces = pieceStart_.back();
  cells.resize(total), epsSum_.resize(total), cellStart_.resize(total + 1);
  cellStart_[total] = std::int32_t(pieces);
  order_.resize(pieces), pieceCell_.resize(pieces);
  const bool indexAll = !blendNow;  // the implicit coupling reads every piece's index
  // Every piece's owner (groupRuns gave shared groups' pieces theirs).
  const std::int32_t owners = std::int32_t(pieceStart_.size()) - 1;
  for (std::int32_t o = 0; o < owners && indexAll; ++o)
    std::fill(pieceOwner_.begin() + pieceStart_[o], pieceOwner_.begin() + pieceStart_[o + 1], o);
  // Tasks of a quarter chunk, taken as threads come free: the cores of a
  // shared machine do not keep the same speed (fluid_node.cpp's sweep).
  const std::ptrdiff_t tasks =
      std::max<std::ptrdiff_t>(1, std::ptrdiff_t(total) / (parallel::kCellChunk / 4));
  chunkFastest_.assign(tasks, Fastest{});
  taskCounts_.assign(tasks, CellCounts{});
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads_.get()) if (tasks > 1)
  for (std::ptrdiff_t t = 0; t < tasks; ++t) {
    Fastest best;
    std::size_t partialCells = 0, interiorCells = 0;
    const std::ptrdiff_t qEnd = groups * (t + 1) / tasks;
    for (std::ptrdiff_t q = groups * t / tasks; q < qEnd; ++q) {
      constexpr std::ptrdiff_t kAhead = 8;  // groups: about two hundred cells
      if (q + kAhead < qEnd && groups_[q + kAhead].run >= 0) {
        const std::int32_t r = groups_[q + kAhead].run;
        // The runs are in node order, their cells solid by solid.
        prefetchForRead(coverOf(runOwner_[r]).cells.data() + runs_[r].first,
                        std::size_t(runs_[r].length) * sizeof(CellCover));
      }
      const Group& grp = groups_[q];
      std::int32_t cell = grp.firstCell, entry = grp.firstEntry;
      if (grp.run >= 0) {
        // A run alone: each piece its own cell.
        const Run& run = runs_[grp.run];
        const std::int32_t o = runOwner_[grp.run];
        const CellCovers& from = coverOf(o).cells;
        const std::int32_t g0 = std::int32_t(pieceStart_[o]) + run.first;
        const Motion motion = ownerMotion(o, circles);  // once for the run
        for (std::int32_t k = 0; k < run.length; ++k, ++cell, ++entry) {
          const CellCover& p = from[run.first + k];
          // A lone cell's pieces are looked up only with the implicit
          // coupling; its run's first entry also ends a shared cell before it.
          if (indexAll || k == 0) cellStart_[cell] = entry;
          if (indexAll) {
            order_[entry] = g0 + k;
            pieceCell_[g0 + k] = cell;
            epsSum_[cell] = p.eps;
          }
          // Field by field, each once (as a whole the record was built on
          // the stack and copied; zeroed, then given its velocity, it took
          // two stores more).
          lb::CoveredCell& to = cells[cell];
          const bool interior = p.interior;
          to.node = std::int32_t(run.node + k), to.interior = interior;
          to.eps = std::min(1.0, p.eps);
          partialCells += to.eps < 1, interiorCells += interior;
          if (blendNow) {
            const Vec2 v = motion.v + spin(motion.w, p.arm);
            // cellVelocity's sum for one piece: its weight eps / eps is 1 exactly.
            const double ux = 0 + toLattice * v.x(), uy = 0 + toLattice * v.y();
            to.ux = ux, to.uy = uy;
            const double u2 = ux * ux + uy * uy;
            if (!interior && u2 > best.u2) best = {u2, o};
          } else {
            to.ux = 0.0, to.uy = 0.0;
          }
        }
        continue;
      }
      // Shared cells: each node's pieces in piece order.
      const std::pair<std::uint32_t, std::int32_t>* g = groupPieces_.data() + (-1 - grp.run);
      for (std::int32_t k = 0; k < grp.pieces;) {
        const std::uint32_t node = g[k].first;
        std::int32_t end = k;
        double sum = 0;
        for (; end < grp.pieces && g[end].first == node; ++end) {
          order_[entry + end - k] = g[end].second;
          pieceCell_[g[end].second] = cell;
          sum += piece(g[end].second).eps;
        }
        const bool interior = end - k == 1 && piece(g[k].second).interior;
        cellStart_[cell] = entry;
        epsSum_[cell] = sum;
        cells[cell] = {std::int32_t(node), interior, std::min(1.0, sum), 0.0, 0.0};
        partialCells += sum < 1, interiorCells += interior;
        if (blendNow) {
          const Vec2 u = cellVelocity(entry, entry + (end - k), sum, circles, toLattice);
          cells[cell].ux = u.x(), cells[cell].uy = u.y();
          if (!interior && u.squaredNorm() > best.u2)
            best = {u.squaredNorm(), pieceOwner_[g[k].second]};
        }
        entry += end - k, ++cell, k = end;
      }
    }
    chunkFastest_[t] = best;
    taskCounts_[t] = {partialCells, interiorCells, 0};
  }
}

void Coupler::collect(lb::Lattice& lattice, dem::Assembly& assembly, const Settings& settings,
                      const Vec2& gravity) {
  const auto t0 = Clock::now();
  const dem::Bodies& b = assembly.bodies();
  const lb::ResolvedLattice& p = lattice.params();
  // Lattice momentum per step to force per unit thickness: h^2 rho h/dt per dt.
  const double scale = p.h * p.h * p.h / (p.dt * p.dt);
  const std::vector<Vec2>& exchange = lattice.coveredExchange();
  const std::vector<lb::CircleObstacle>& circles = lattice.circles();
  std::vector<Vec2> circleForce(circles.size(), Vec2::Zero());
  std::vector<double> circleTorque(circles.size(), 0.0);
  std::vector<double> submerged(b.size(), 0.0);
  // Owner by owner over its pieces, in their order: the sums do not depend on
  // the thread count.
  const int n = b.size(), owners = n + int(circles.size());
#pragma omp parallel for schedule(dynamic, 16) \
    num_threads(threads_.get()) if (owners >= parallel::kLoadOwners)
  for (int o = 0; o < owners; ++o) {
    Vec2 force = Vec2::Zero();
    double torque = 0, area = 0;
    const CellCovers& from = coverOf(o).cells;
    // Run by run, piece by piece: a lone run's pieces have its cells to
    // themselves (share 1), a shared run's look theirs up.
    for (std::int32_t r = runStart_[o]; r < runStart_[o + 1]; ++r) {
      // The records and exchanges of a run ahead: the lattice's sweep has
      // evicted both since they were written.
      constexpr std::int32_t kAhead = 4;  // runs
      // (Into the next owners' runs too: the runs lie owner after owner, and
      // an owner's first runs would otherwise wait.)
      if (const std::size_t ahead = std::size_t(r + kAhead); ahead < runs_.size()) {
        const Run& next = runs_[ahead];
        prefetchForRead(coverOf(runOwner_[ahead]).cells.data() + next.first,
                        std::size_t(next.length) * sizeof(CellCover));
        if (runCell_[ahead] >= 0)
          prefetchForRead(exchange.data() + runCell_[ahead],
                          std::size_t(next.length) * sizeof(Vec2));
      }
      const Run& run = runs_[r];
      const std::int32_t lone = runCell_[r];
      for (std::int32_t k = 0; k < run.length; ++k) {
        const CellCover& piece = from[run.first + k];
        double share = 1.0;
        std::int32_t c = lone + k;
        if (lone < 0) {
          c = pieceCell_[pieceStart_[o] + run.first + k];
          share = settings.share == Share::equal ? 1.0 / sharing(c) : piece.eps / epsSum_[c];
        }
        const Vec2 F = -share * scale * exchange[c];  // the solid gets the opposite
        force += F;
        torque += cross(piece.arm, F);
        area += piece.eps;
      }
    }
    if (o < n) {
      assembly.setFluidLoad(o, force, torque), submerged[o] = area;
    } else {
      circleForce[o - n] = force, circleTorque[o - n] = torque;
    }
  }
  for (std::size_t k = 0; k < circles.size(); ++k)
    lattice.setCircleLoad(k, circleForce[k], circleTorque[k], circles_[k].cells.size());
  for (int s = 0; s < b.size(); ++s)
    assembly.setBuoyancy(s, settings.buoyancy
                                ? detail::buoyancyOf(b, s, submerged[s], lattice, gravity)
                                : Vec2::Zero());
  profile_.get().lap(Stage::fluidForces, t0);
}

void Coupler::clear(dem::Assembly& assembly) {
  elements_.clear();
  circles_.clear();
  open_.clear();
  openChunks_.clear();
  topology_ = 0;  // a lattice's versions start above 0: the next one is measured afresh
  pieceOwner_.clear();
  pieceCell_.clear();
  runStart_.clear();
  runCell_.clear();
  order_.clear();
  cellStart_.clear();
  epsSum_.clear();
  cells_ = 0;
  counts_ = CellCounts{};
  listKept_ = false;
  fastest_ = SolidSpeed{};
  assembly.clearFluidLoads();
}

}  // namespace sf::coupling
