// The lattice layer of a picture: scalar fields per node under a colour map,
// node kinds, velocity arrows and streamlines.
#include <algorithm>
#include <cmath>
#include <limits>

#include "sandflow/core/error.hpp"
#include "sandflow/lb/lattice.hpp"
#include "scene_parts.hpp"

namespace sf::render {
namespace {

using lb::NodeKind;

bool holdsFluid(NodeKind k) {
  return k == NodeKind::fluid || k == NodeKind::velocity || k == NodeKind::pressure;
}

// Velocities, and which nodes hold fluid, over a window of nodes; a node
// outside it (a neighbour across a periodic seam) is read off the lattice.
struct VelocityWindow {
  const lb::Lattice& lattice;
  int i0, j0, width, height;
  std::vector<Vec2> u;
  std::vector<std::uint8_t> fluid;

  VelocityWindow(const lb::Lattice& l, int ia, int ja, int ib, int jb)
      : lattice(l), i0(ia), j0(ja), width(ib - ia), height(jb - ja) {
    const std::size_t n = std::size_t(std::max(0, width)) * std::max(0, height);
    u.assign(n, Vec2::Zero());
    fluid.assign(n, 0);
#pragma omp parallel for schedule(dynamic, 8)
    for (int b = 0; b < height; ++b)
      for (int a = 0; a < width; ++a) {
        const std::size_t k = std::size_t(b) * width + a;
        fluid[k] = holdsFluid(lattice.kind(i0 + a, j0 + b));
        if (fluid[k]) u[k] = lattice.velocity(i0 + a, j0 + b);
      }
  }
  // False where (i, j) holds no fluid.
  bool at(int i, int j, Vec2& out) const {
    const int a = i - i0, b = j - j0;
    if (a >= 0 && b >= 0 && a < width && b < height) {
      const std::size_t k = std::size_t(b) * width + a;
      if (fluid[k]) out = u[k];
      return fluid[k];
    }
    if (!holdsFluid(lattice.kind(i, j))) return false;
    out = lattice.velocity(i, j);
    return true;
  }
};

// d(field)/d(axis) at a node by central differences between fluid neighbours
// (one-sided next to walls, across periodic edges where the lattice wraps).
struct Gradient {
  const VelocityWindow& u;
  int nx, ny;
  bool periodic[2];

  int wrap(int k, int n, int axis, bool& ok) const {
    if (k >= 0 && k < n) return k;
    ok = periodic[axis];
    return (k + n) % n;
  }
  // Derivative of component c along axis at fluid node (i, j), per node spacing.
  double operator()(int i, int j, int axis, int c) const {
    auto at = [&](int di, int dj, bool& ok) {
      ok = true;
      const int ii = wrap(i + di, nx, 0, ok), jj = wrap(j + dj, ny, 1, ok);
      Vec2 v = Vec2::Zero();
      ok = ok && u.at(ii, jj, v);
      return ok ? v[c] : 0.0;
    };
    bool okPlus = false, okMinus = false, okHere = false;
    const double plus = axis == 0 ? at(1, 0, okPlus) : at(0, 1, okPlus);
    const double minus = axis == 0 ? at(-1, 0, okMinus) : at(0, -1, okMinus);
    const double here = at(0, 0, okHere);
    if (okPlus && okMinus) return 0.5 * (plus - minus);
    if (okPlus) return plus - here;
    if (okMinus) return here - minus;
    return 0.0;
  }
};

std::array<double, 2> finiteRange(const std::vector<double>& v) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double x : v)
    if (std::isfinite(x)) {
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  if (lo > hi) return {0, 0};
  return {lo, hi};
}

// Below a billionth of the lattice speed h/dt the fluid is still: at rest it
// holds rounding noise (1e-17 of h/dt) in random directions, which no scale
// should blow up into colours or arrows.
double stillSpeed(const lb::Lattice& lattice) {
  return 1e-9 * lattice.params().h / lattice.params().dt;
}

// The first and last node of a grid's column or row list ({0, -1} if empty).
std::array<int, 2> nodeSpan(const std::vector<int>& nodes) {
  if (nodes.empty()) return {0, -1};
  const auto [lo, hi] = std::minmax_element(nodes.begin(), nodes.end());
  return {*lo, *hi};
}

// One axis of viewGrid: the lattice's nodes [0, n) of size h from `origin`;
// world coordinate w maps to pixel p0 + (w - w0) * scale; the viewport spans
// pixels [v0, v1).
void gridAxis(double origin, double h, int n, double w0, double p0, double scale, double v0,
              double v1, bool pixels, std::vector<int>& nodes, double& lo, double& hi) {
  const double a = std::max(p0 + (origin - w0) * scale, v0);
  const double b = std::min(p0 + (origin + n * h - w0) * scale, v1);
  lo = hi = origin;
  if (!(b > a)) return;
  auto worldAt = [&](double pixel) { return w0 + (pixel - p0) / scale; };
  auto nodeAt = [&](double x) {
    return int(std::clamp(std::floor((x - origin) / h), 0.0, n - 1.0));
  };
  if (h * scale >= 1) {  // nodes of a pixel or more: those in view
    const int i0 = nodeAt(worldAt(a));
    const int i1 = int(std::clamp(std::ceil((worldAt(b) - origin) / h), i0 + 1.0, double(n)));
    for (int i = i0; i < i1; ++i) nodes.push_back(i);
    lo = origin + i0 * h;
    hi = origin + i1 * h;
  } else if (pixels) {
    // Smaller nodes, on the final pixels: a texel per pixel whose centre lies
    // on the lattice (those GL fills for a quad over it), the node under
    // that centre.
    const double first = std::ceil(a - 0.5), last = std::ceil(b - 0.5);
    for (double x = first; x < last; ++x) nodes.push_back(nodeAt(worldAt(x + 0.5)));
    lo = worldAt(first);
    hi = worldAt(last);
  } else {
    // Smaller nodes, at a scale the final one may fall short of: texels of
    // about a pixel tiling the lattice in view, each the node under its centre.
    lo = worldAt(a);
    hi = worldAt(b);
    const int count = int(std::ceil(b - a - 1e-9));
    for (int k = 0; k < count; ++k) nodes.push_back(nodeAt(lo + (k + 0.5) * (hi - lo) / count));
  }
}

// A texel of `f` per point of the grid.
void sizeFor(const detail::FieldGrid& grid, FieldValues& f) {
  f.nx = grid.width();
  f.ny = grid.height();
  f.value.resize(std::size_t(f.nx) * f.ny);
  f.fluid.resize(f.value.size());
}

// Sizes `f` to the grid and fills it: value(i, j, fluid) at each texel's
// node (NaN where the field has none). Texels on the node of the one before
// them (pixels smaller than nodes) take its value: each node is read once.
// Rows go a few at a time as threads come free: on a shared machine one
// thread may stall.
template <class Value>
void sampleGrid(const lb::Lattice& lattice, const detail::FieldGrid& grid, FieldValues& f,
                const Value& value) {
  sizeFor(grid, f);
#pragma omp parallel for schedule(dynamic, 8)
  for (int b = 0; b < f.ny; ++b) {
    const int j = grid.row[std::size_t(b)];
    if (b > 0 && grid.row[std::size_t(b) - 1] == j) continue;
    for (int a = 0; a < f.nx; ++a) {
      const int i = grid.col[std::size_t(a)];
      const std::size_t k = std::size_t(b) * f.nx + a;
      if (a > 0 && grid.col[std::size_t(a) - 1] == i) {
        f.fluid[k] = f.fluid[k - 1];
        f.value[k] = f.value[k - 1];
      } else {
        f.fluid[k] = holdsFluid(lattice.kind(i, j));
        f.value[k] = value(i, j, f.fluid[k] != 0);
      }
    }
  }
  for (int b = 1; b < f.ny; ++b)
    if (grid.row[std::size_t(b) - 1] == grid.row[std::size_t(b)]) {
      const auto above = std::ptrdiff_t(b - 1) * f.nx, row = std::ptrdiff_t(b) * f.nx;
      std::copy_n(f.fluid.begin() + above, f.nx, f.fluid.begin() + row);
      std::copy_n(f.value.begin() + above, f.nx, f.value.begin() + row);
    }
}

// sampleGrid for the fields of a node's moments: value(rho, u) at fluid
// nodes, a row's texels at a time (Lattice::rowFields at the grid's columns).
template <class Value>
void sampleMoments(const lb::Lattice& lattice, const detail::FieldGrid& grid, FieldValues& f,
                   const Value& value) {
  sizeFor(grid, f);
  const double nan = std::numeric_limits<double>::quiet_NaN();
#pragma omp parallel
  {
    std::vector<double> rho(std::size_t(f.nx));
    std::vector<Vec2> u(std::size_t(f.nx));
#pragma omp for schedule(dynamic, 8)
    for (int b = 0; b < f.ny; ++b) {
      const int j = grid.row[std::size_t(b)];
      lattice.rowFields(j, grid.col.data(), f.nx, rho.data(), u.data());
      for (int a = 0; a < f.nx; ++a) {
        const std::size_t k = std::size_t(b) * f.nx + a;
        f.fluid[k] = holdsFluid(lattice.kind(grid.col[std::size_t(a)], j));
        f.value[k] = f.fluid[k] ? value(rho[std::size_t(a)], u[std::size_t(a)]) : nan;
      }
    }
  }
}

}  // namespace

FieldValues sampleField(const lb::Lattice& lattice, Field field,
                        const std::optional<std::array<double, 2>>& range) {
  return detail::sampleField(
      lattice, field == Field::solid ? detail::solidRatios(lattice) : std::vector<float>(), field,
      range, detail::wholeLattice(lattice));
}

namespace detail {

FieldGrid wholeLattice(const lb::Lattice& lattice) {
  FieldGrid g;
  for (int i = 0; i < lattice.nx(); ++i) g.col.push_back(i);
  for (int j = 0; j < lattice.ny(); ++j) g.row.push_back(j);
  const Window w = latticeWindow(lattice);
  g.x0 = w.x0;
  g.y0 = w.y0;
  g.x1 = w.x1;
  g.y1 = w.y1;
  return g;
}

FieldGrid viewGrid(const lb::Lattice& lattice, const WorldMap& world, const Rect& viewport,
                   bool pixels) {
  const auto& p = lattice.params();
  FieldGrid g;
  gridAxis(p.def.origin.x(), p.h, p.nx, world.wx0, world.px0, world.pixelsPerUnit, viewport.x0,
           viewport.x1, pixels, g.col, g.x0, g.x1);
  gridAxis(p.def.origin.y(), p.h, p.ny, world.wy0, world.py0, world.pixelsPerUnit, viewport.y0,
           viewport.y1, pixels, g.row, g.y0, g.y1);
  if (g.col.empty() || g.row.empty()) g = FieldGrid{};
  return g;
}

FieldValues sampleField(const lb::Lattice& lattice, const std::vector<float>& eps, Field field,
                        const std::optional<std::array<double, 2>>& range, const FieldGrid& grid) {
  if (field == Field::none || field == Field::nodes)
    throw Error("VALUE FIELD", "not a scalar field");
  FieldValues f;
  const int nx = lattice.nx();
  const double cs2 = lattice.params().soundSpeed() * lattice.params().soundSpeed();
  const double p0 = cs2 * lattice.params().def.density;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  switch (field) {
    case Field::solid:
      sampleGrid(lattice, grid, f, [&](int i, int j, bool fluid) {
        return fluid ? double(eps[std::size_t(j) * nx + i]) : 1.0;
      });
      break;
    case Field::density:
      sampleMoments(lattice, grid, f, [](double rho, const Vec2&) { return rho; });
      break;
    case Field::pressure:  // as Lattice::pressure, less the reference
      sampleMoments(lattice, grid, f, [&](double rho, const Vec2&) { return cs2 * rho - p0; });
      break;
    case Field::velocity:
      sampleMoments(lattice, grid, f, [](double, const Vec2& u) { return u.norm(); });
      break;
    default: {  // vorticity: the velocities of the nodes in view and their neighbours, once each
      const auto [i0, i1] = nodeSpan(grid.col);
      const auto [j0, j1] = nodeSpan(grid.row);
      const VelocityWindow window(lattice, std::max(0, i0 - 1), std::max(0, j0 - 1),
                                  std::min(nx, i1 + 2), std::min(lattice.ny(), j1 + 2));
      const auto& sides = lattice.params().def.sides;
      const Gradient grad{window,
                          nx,
                          lattice.ny(),
                          {sides[lb::left].kind == lb::SideKind::periodic,
                           sides[lb::bottom].kind == lb::SideKind::periodic}};
      const double h = lattice.params().h;
      sampleGrid(lattice, grid, f, [&](int i, int j, bool fluid) {
        return fluid ? (grad(i, j, 0, 1) - grad(i, j, 1, 0)) / h : nan;
      });
    }
  }
  const bool diverging = field == Field::pressure || field == Field::vorticity;
  f.map.map = diverging ? ColorMap::coolwarm : ColorMap::viridis;
  if (range) {
    f.map.lo = (*range)[0];
    f.map.hi = (*range)[1];
  } else if (field == Field::solid) {
    f.map.lo = 0;
    f.map.hi = 1;
  } else {
    const auto [lo, hi] = finiteRange(f.value);
    if (diverging) {
      // As for the speed: a still fluid's noise on the scale of a flow at
      // Mach 0.01 (its vorticity across a cell, its dynamic pressure), white.
      const auto& p = lattice.params();
      const double c = p.h / p.dt;
      const double still =
          field == Field::vorticity ? 1e-9 * c / p.h : 1e-9 * p.def.density * c * c;
      const double flow =
          field == Field::vorticity ? 0.01 * c / p.h : p.def.density * (0.01 * c) * (0.01 * c);
      const double m = std::max(std::abs(lo), std::abs(hi));
      const double d = m < still ? flow : m;
      f.map.lo = -d;
      f.map.hi = d;
    } else if (field == Field::velocity) {
      // Still fluid, scaled to its rounding noise, would show the map's top
      // colour: its scale is Mach 0.01, and it reads as still.
      f.map.lo = 0;
      f.map.hi = hi < stillSpeed(lattice) ? 0.01 * lattice.params().h / lattice.params().dt : hi;
    } else {
      f.map.lo = lo;
      f.map.hi = hi;
    }
  }
  switch (field) {
    case Field::solid:
      f.title = "solid ratio";
      break;
    case Field::density:
      f.title = "density";
      break;
    case Field::pressure:
      f.title = "pressure \u2212 p\u2080";
      break;
    case Field::velocity:
      f.title = "speed |u|";
      break;
    default:
      f.title = "vorticity";
  }
  return f;
}

Rgb nodeKindColour(lb::NodeKind kind) {
  switch (kind) {
    case NodeKind::fluid:
      return {198, 219, 239};
    case NodeKind::noslip:
      return {64, 64, 64};
    case NodeKind::slip:
      return {107, 127, 160};
    case NodeKind::solid:
      return {20, 20, 20};
    case NodeKind::velocity:
      return {0, 158, 115};
    case NodeKind::pressure:
      return {230, 159, 0};
    default:  // open: outside an inlet or outlet, never read
      return {255, 255, 255};
  }
}

std::vector<float> solidRatios(const lb::Lattice& lattice) {
  const int nx = lattice.nx();
  std::vector<float> eps(std::size_t(nx) * lattice.ny(), 0.0f);
  const std::int64_t origin = lattice.nodeIndex(0, 0);
  const std::int64_t row = lattice.nodeIndex(0, 1) - origin;
  for (const lb::CoveredCell& c : lattice.coveredCells()) {
    const std::int64_t r = c.node - origin;
    const std::int64_t j = r / row, i = r % row;
    if (i >= 0 && i < nx && j >= 0 && j < lattice.ny())
      eps[std::size_t(j) * nx + std::size_t(i)] = float(c.eps);
  }
  return eps;
}

bool usesSolidRatios(Field field, const ViewOptions& v) {
  return field == Field::solid || field == Field::nodes || v.vectors || v.streamlines;
}

Window latticeWindow(const lb::Lattice& lattice) {
  const auto& p = lattice.params();
  return {p.def.origin.x(), p.def.origin.y(), p.def.origin.x() + p.nx * p.h,
          p.def.origin.y() + p.ny * p.h};
}

Key nodeKindKey(const lb::Lattice& lattice, const std::vector<float>& eps) {
  static const char* names[] = {"fluid",         "no-slip wall",  "slip wall", "solid",
                                "velocity edge", "pressure edge", "open"};
  bool present[8] = {};
  bool covered = false;
  for (int j = 0; j < lattice.ny(); ++j)
    for (int i = 0; i < lattice.nx(); ++i) {
      present[int(lattice.kind(i, j))] = true;
      if (lattice.kind(i, j) == NodeKind::fluid && eps[std::size_t(j) * lattice.nx() + i] > 0)
        covered = true;
    }
  Key key;
  key.title = "node kind";
  key.continuous = false;
  for (int k = 0; k <= int(NodeKind::open); ++k)
    if (present[k]) key.entries.push_back({names[k], nodeKindColour(NodeKind(k))});
  if (covered) key.entries.push_back({"covered by a solid", kCoveredColour});
  return key;
}

Sprite fieldSprite(const lb::Lattice& lattice, const std::vector<float>& eps, Field field,
                   const FieldValues* values, const FieldGrid& grid, const WorldMap& world) {
  // A table of the map at 4096 points: within a quarter of a level of the
  // interpolated colour, at a fraction of the cost per node.
  constexpr int kTable = 4096;
  std::vector<Rgb> table(kTable);
  if (values)
    for (int k = 0; k < kTable; ++k)
      table[std::size_t(k)] = mapColor(values->map.map, (k + 0.5) / kTable);
  const Rgb nanColour = mapColor(ColorMap::viridis, std::numeric_limits<double>::quiet_NaN());
  auto colourOf = [&](double v) {
    const double t = values->map.position(v);
    if (std::isnan(t)) return nanColour;
    return table[std::size_t(std::clamp(t * kTable, 0.0, kTable - 1.0))];
  };
  Sprite s;
  s.width = grid.width();
  s.height = grid.height();
  s.rgba.resize(std::size_t(s.width) * s.height * 4);
  const int nx = lattice.nx();
#pragma omp parallel for schedule(dynamic, 8)
  for (int b = 0; b < s.height; ++b) {
    const int j = grid.row[std::size_t(b)];
    for (int a = 0; a < s.width; ++a) {
      const int i = grid.col[std::size_t(a)];
      const std::size_t k = std::size_t(b) * s.width + a;
      Rgb c;
      if (field == Field::nodes) {
        const NodeKind kind = lattice.kind(i, j);
        c = kind == NodeKind::fluid && eps[std::size_t(j) * nx + i] > 0 ? kCoveredColour
                                                                        : nodeKindColour(kind);
      } else if (values->fluid[k] || field == Field::solid) {
        c = colourOf(values->value[k]);
      } else {
        c = kWallColour;
      }
      s.rgba[4 * k] = c.r;
      s.rgba[4 * k + 1] = c.g;
      s.rgba[4 * k + 2] = c.b;
      s.rgba[4 * k + 3] = 255;
    }
  }
  // Over the grid's world rectangle: node texels over their cells
  // [origin + i h, origin + (i+1) h) (Lattice::position), pixel texels over their pixels.
  const Point lo = world(Vec2(grid.x0, grid.y0));
  const Point hi = world(Vec2(grid.x1, grid.y1));
  s.x0 = lo.x;
  s.y0 = lo.y;
  s.x1 = hi.x;
  s.y1 = hi.y;
  return s;
}

namespace {

// Velocity (physical units) at a point, bilinear between fluid nodes; nullopt
// outside the fluid.
std::optional<Vec2> velocityAt(const lb::Lattice& lattice, const std::vector<float>& eps,
                               const Vec2& x) {
  const auto& p = lattice.params();
  const Vec2 r = (x - p.def.origin) / p.h - Vec2(0.5, 0.5);
  const int i = int(std::floor(r.x())), j = int(std::floor(r.y()));
  if (i < 0 || j < 0 || i + 1 >= p.nx || j + 1 >= p.ny) return std::nullopt;
  const double fx = r.x() - i, fy = r.y() - j;
  Vec2 u = Vec2::Zero();
  for (int dj = 0; dj < 2; ++dj)
    for (int di = 0; di < 2; ++di) {
      if (!holdsFluid(lattice.kind(i + di, j + dj)) ||
          eps[std::size_t(j + dj) * p.nx + std::size_t(i + di)] > 0.5f)
        return std::nullopt;
      u += (di ? fx : 1 - fx) * (dj ? fy : 1 - fy) * lattice.velocity(i + di, j + dj);
    }
  return u;
}

// The largest speed over a grid of at most about 250,000 nodes: the scale of
// the streamlines' stagnation test, not worth a pass over a large lattice.
double maxSpeed(const lb::Lattice& lattice) {
  const double n = double(lattice.nx()) * lattice.ny();
  const int stride = std::max(1, int(std::ceil(std::sqrt(n / 250000.0))));
  double m = 0;
  for (int j = 0; j < lattice.ny(); j += stride)
    for (int i = 0; i < lattice.nx(); i += stride)
      if (holdsFluid(lattice.kind(i, j))) m = std::max(m, lattice.velocity(i, j).norm());
  return m;
}

}  // namespace

void addArrows(const lb::Lattice& lattice, const std::vector<float>& eps, const WorldMap& world,
               const Window& shown, float spacing, float scale, Rgba colour, double fullSpeed,
               std::vector<Stroke>& out) {
  const auto& p = lattice.params();
  const float cell = world.length(p.h);
  const int stride = int(std::clamp(std::ceil(double(spacing) / cell), 1.0, 1e6));
  // The nodes in view, on the grid of the whole lattice (arrows stay put as
  // the window moves).
  const Window w = shown.intersect(latticeWindow(lattice));
  if (w.empty()) return;
  auto first = [&](double from, double origin, int n) {
    const double k = std::clamp(std::floor((from - origin) / p.h), 0.0, double(n));
    const int start = stride / 2;
    return start + int(std::ceil((k - start) / stride)) * stride;
  };
  auto last = [&](double to, double origin, int n) {
    return int(std::clamp(std::ceil((to - origin) / p.h), 0.0, double(n)));
  };
  const int i0 = first(w.x0, p.def.origin.x(), p.nx), i1 = last(w.x1, p.def.origin.x(), p.nx);
  const int j0 = first(w.y0, p.def.origin.y(), p.ny), j1 = last(w.y1, p.def.origin.y(), p.ny);
  // The arrows' nodes and velocities first: without a given scale, the
  // fastest arrow is the longest, 90% of the grid spacing.
  struct Site {
    Point centre;
    Vec2 u;
  };
  std::vector<Site> sites;
  double umax = 0;
  for (int j = std::max(j0, 0); j < std::min(j1, p.ny); j += stride)
    for (int i = std::max(i0, 0); i < std::min(i1, p.nx); i += stride) {
      if (!holdsFluid(lattice.kind(i, j)) || eps[std::size_t(j) * lattice.nx() + i] > 0.5f)
        continue;
      sites.push_back({world(lattice.position(i, j)), lattice.velocity(i, j)});
      umax = std::max(umax, sites.back().u.norm());
    }
  const double full = fullSpeed > 0 ? fullSpeed : umax;
  if (!(umax >= stillSpeed(lattice)) || !std::isfinite(full)) return;
  const float longest = 0.9f * float(stride) * cell;
  for (const Site& site : sites) {
    const double speed = site.u.norm();
    const float len = float(std::min(1.0, speed / full)) * longest;
    if (!(len >= scale)) continue;  // shorter than a pixel (or still): no arrow
    const Vec2 d = site.u / speed;
    const Point c = site.centre;
    const Point tip{c.x + 0.5f * len * float(d.x()), c.y + 0.5f * len * float(d.y())};
    const Point tail{c.x - 0.5f * len * float(d.x()), c.y - 0.5f * len * float(d.y())};
    out.push_back({tail, tip, scale, colour});
    const float head = std::max(3.0f * scale, 0.3f * len);
    for (double turn : {2.6, -2.6}) {  // barbs about 150 degrees off the shaft
      const Vec2 b = rotated(d, turn);
      out.push_back(
          {tip, {tip.x + head * float(b.x()), tip.y + head * float(b.y())}, scale, colour});
    }
  }
}

void addStreamlines(const lb::Lattice& lattice, const std::vector<float>& eps,
                    const WorldMap& world, const Window& shown, float spacing, float scale,
                    Rgba colour, std::vector<Stroke>& out) {
  const double umax = maxSpeed(lattice);
  if (!(umax >= stillSpeed(lattice))) return;  // still fluid: its noise has no lines
  const double h = lattice.params().h;
  // Evenly spaced lines (after Jobard & Lefer): a line stops where it comes
  // closer than about `separation` to another one, and a seed starts only in
  // empty space. The occupancy grid has cells of half the separation.
  const double separation = 2.0 * spacing / world.pixelsPerUnit;  // world units
  const double cellSize = 0.5 * separation;
  // The grid covers the part of the lattice in view (a line ends where it
  // leaves it): about (viewport / separation)^2 cells whatever the zoom.
  const Window w = shown.intersect(latticeWindow(lattice));
  if (w.empty()) return;
  const int gx = int(std::clamp(std::ceil((w.x1 - w.x0) / cellSize), 1.0, 4096.0));
  const int gy = int(std::clamp(std::ceil((w.y1 - w.y0) / cellSize), 1.0, 4096.0));
  std::vector<int> owner(std::size_t(gx) * gy, -1);
  auto cellOf = [&](const Vec2& x) -> long {
    const double fi = std::floor((x.x() - w.x0) / cellSize);
    const double fj = std::floor((x.y() - w.y0) / cellSize);
    if (!(fi >= 0 && fj >= 0 && fi < gx && fj < gy)) return -1;
    return long(fj) * gx + long(fi);
  };
  // Free if no other line holds this cell or its neighbours.
  auto free = [&](const Vec2& x, int line) {
    const long c = cellOf(x);
    if (c < 0) return false;
    const int ci = int(c % gx), cj = int(c / gx);
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int i = ci + di, j = cj + dj;
        if (i < 0 || j < 0 || i >= gx || j >= gy) continue;
        const int o = owner[std::size_t(j) * gx + i];
        if (o >= 0 && o != line) return false;
      }
    return true;
  };
  // Steps of half a node, or of 2 pixels where nodes are smaller than that.
  const double ds = std::max(0.5 * h, 2.0 * scale / world.pixelsPerUnit);
  const int maxSteps =
      int(std::min(2.0 * ((w.x1 - w.x0) + (w.y1 - w.y0)) / ds + 1, double(1 << 20)));
  int line = 0;
  for (int j = 0; j < gy; ++j)
    for (int i = 0; i < gx; ++i, ++line) {
      const Vec2 seed = Vec2(w.x0, w.y0) + cellSize * Vec2(i + 0.5, j + 0.5);
      if (!free(seed, line) || !velocityAt(lattice, eps, seed)) continue;
      for (double direction : {1.0, -1.0}) {
        Vec2 x = seed;
        for (int step = 0; step < maxSteps; ++step) {
          // Midpoint rule along the unit direction.
          const auto u1 = velocityAt(lattice, eps, x);
          if (!u1 || u1->norm() < 1e-3 * umax) break;
          const Vec2 mid = x + direction * 0.5 * ds * u1->normalized();
          const auto u2 = velocityAt(lattice, eps, mid);
          if (!u2 || u2->norm() < 1e-3 * umax) break;
          const Vec2 next = x + direction * ds * u2->normalized();
          if (!free(next, line)) break;
          out.push_back({world(x), world(next), scale, colour});
          const long c = cellOf(next);
          if (owner[std::size_t(c)] < 0) owner[std::size_t(c)] = line;
          x = next;
        }
      }
    }
}

}  // namespace detail
}  // namespace sf::render
