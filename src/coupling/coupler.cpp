#include "sandflow/coupling/coupler.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "sandflow/dem/shape.hpp"

namespace sf::coupling {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

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

}  // namespace

bool Coupler::needed(const lb::Lattice& lattice, const dem::Assembly& assembly) {
  if (!lattice.circles().empty()) return true;
  const dem::Bodies& b = assembly.bodies();
  for (int s = 0; s < b.size(); ++s)
    if (covers(b, s)) return true;
  return false;
}

bool Coupler::stale(const Cached& c, int id, const Vec2& x, double angle, double area, double reach,
                    double radius, bool outside) const {
  return c.id != id || c.x != x || c.angle != angle || c.area != area || c.reach != reach ||
         c.radius != radius || c.outside != outside;
}

void Coupler::prepare(lb::Lattice& lattice, const dem::Assembly& assembly, const Settings& settings,
                      int threads) {
  const auto t0 = Clock::now();
  const Grid grid = gridOf(lattice);
  const dem::Bodies& b = assembly.bodies();
  const int n = b.size();
  const std::vector<lb::CircleObstacle>& circles = lattice.circles();
  const bool remeasure =
      lattice.topologyVersion() != topology_ || settings.subcells != measuredWith_.subcells;
  topology_ = lattice.topologyVersion();
  measuredWith_ = settings;
  if (remeasure) elements_.clear(), circles_.clear();
  elements_.resize(n);
  circles_.resize(circles.size());

  // 1. Coverage of whatever moved (or changed shape) since it was measured.
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads) if (n >= 16)
  for (int s = 0; s < n; ++s) {
    Cached& c = elements_[s];
    if (!covers(b, s)) {
      c = Cached{};
      continue;
    }
    const dem::Shape& shape = *b.shape[s];
    if (!stale(c, b.id[s], b.x[s], b.angle[s], shape.area(), b.reach[s], 0, false)) continue;
    c = Cached{b.id[s], b.x[s], b.angle[s], shape.area(), b.reach[s], 0, false, {}};
    if (const auto f = footprintOf(shape, b.x[s], b.angle[s]))
      cover(*f, b.x[s], grid, settings.subcells, c.cells);
  }
  for (std::size_t k = 0; k < circles.size(); ++k) {
    const lb::CircleObstacle& o = circles[k];
    Cached& c = circles_[k];
    if (!stale(c, o.id, o.centre, 0, 0, 0, o.radius, o.outside)) continue;
    c = Cached{o.id, o.centre, 0, 0, 0, o.radius, o.outside, {}};
    cover(*circleFootprint(o.centre, o.radius, o.outside), o.centre, grid, settings.subcells,
          c.cells);
  }

  // 2. Cells: coverage summed over the solids on each (capped at 1), solid
  //    velocity weighted by coverage, interior only when one solid holds it.
  std::vector<lb::CoveredCell> cells;
  pieces_.clear();
  epsSum_.clear();
  owners_.clear();
  cellOf_.resize(std::size_t(lattice.nx() + 2) * (lattice.ny() + 2), -1);
  const double toLattice = lattice.params().dt / lattice.params().h;
  auto add = [&](int owner, const CellCover& cc, const Vec2& velocity) {
    if (lattice.kind(cc.i, cc.j) != lb::NodeKind::fluid) return;
    const std::int64_t node = lattice.nodeIndex(cc.i, cc.j);
    std::int32_t& k = cellOf_[node];
    const Vec2 u = velocity * toLattice;
    if (k < 0) {
      k = std::int32_t(cells.size());
      cells.push_back({node, 0.0, 0.0, 0.0, cc.interior});
      epsSum_.push_back(0.0);
      owners_.push_back(0);
    } else {
      cells[k].interior = false;
    }
    lb::CoveredCell& cell = cells[k];
    cell.ux += cc.eps * u.x();
    cell.uy += cc.eps * u.y();
    epsSum_[k] += cc.eps;
    ++owners_[k];
    pieces_.push_back({k, owner, cc.eps, cc.arm});
  };
  for (int s = 0; s < n; ++s)
    for (const CellCover& cc : elements_[s].cells) add(s, cc, b.v[s] + spin(b.w[s], cc.arm));
  for (std::size_t k = 0; k < circles.size(); ++k)
    for (const CellCover& cc : circles_[k].cells)
      add(-1 - int(k), cc, circles[k].velocity + spin(circles[k].spin, cc.arm));
  fastest_ = SolidSpeed{};
  for (std::size_t k = 0; k < cells.size(); ++k) {
    lb::CoveredCell& cell = cells[k];
    cellOf_[cell.node] = -1;
    cell.eps = std::min(1.0, epsSum_[k]);
    cell.ux /= epsSum_[k];
    cell.uy /= epsSum_[k];
  }
  // The fastest surface that the fluid sees (interior cells move no fluid).
  for (const Piece& p : pieces_) {
    const lb::CoveredCell& cell = cells[p.cell];
    if (cell.interior) continue;
    const double mach = std::hypot(cell.ux, cell.uy);
    if (mach > fastest_.mach) {
      fastest_.mach = mach;
      fastest_.element = p.owner >= 0 ? b.id[p.owner] : -1;
      fastest_.obstacle = p.owner < 0 ? circles[-1 - p.owner].id : -1;
    }
  }
  cells_ = cells.size();
  lattice.setCoveredCells(std::move(cells), settings.equilibriumInterior);
  times_.coverage += since(t0);
}

void Coupler::collect(lb::Lattice& lattice, dem::Assembly& assembly, const Settings& settings,
                      const Vec2& gravity) {
  const auto t0 = Clock::now();
  dem::Bodies& b = assembly.bodies();
  const lb::ResolvedLattice& p = lattice.params();
  // Lattice momentum per step to force per unit thickness: h^2 rho h/dt per dt.
  const double scale = p.h * p.h * p.h / (p.dt * p.dt);
  const std::vector<Vec2>& exchange = lattice.coveredExchange();
  const std::vector<lb::CircleObstacle>& circles = lattice.circles();
  std::vector<Vec2> circleForce(circles.size(), Vec2::Zero());
  std::vector<double> circleTorque(circles.size(), 0.0);
  std::vector<double> submerged(b.size(), 0.0);
  for (int s = 0; s < b.size(); ++s) b.fluidForce[s] = Vec2::Zero(), b.fluidTorque[s] = 0;
  // Pieces come grouped by owner in a fixed order: the sums do not depend on
  // the thread count.
  for (const Piece& piece : pieces_) {
    const double share = settings.share == Share::equal ? 1.0 / owners_[piece.cell]
                                                        : piece.eps / epsSum_[piece.cell];
    const Vec2 F = -share * scale * exchange[piece.cell];  // the solid gets the opposite
    const double T = cross(piece.arm, F);
    if (piece.owner >= 0) {
      b.fluidForce[piece.owner] += F;
      b.fluidTorque[piece.owner] += T;
      submerged[piece.owner] += piece.eps;
    } else {
      circleForce[-1 - piece.owner] += F;
      circleTorque[-1 - piece.owner] += T;
    }
  }
  for (std::size_t k = 0; k < circles.size(); ++k)
    lattice.setCircleLoad(k, circleForce[k], circleTorque[k], circles_[k].cells.size());
  // Static buoyancy on the immersed area: the element's own area when the
  // lattice holds all of it, the covered cells' area when it sticks out.
  const double rho = p.def.density, cellArea = p.h * p.h;
  const Vec2 lo = p.def.origin, hi = lo + Vec2(p.nx * p.h, p.ny * p.h);
  const Grid grid = gridOf(lattice);
  for (int s = 0; s < b.size(); ++s) {
    b.buoyancy[s] = Vec2::Zero();
    if (!settings.buoyancy || submerged[s] == 0) continue;
    const dem::Box box = b.shape[s]->bounds(b.x[s], b.angle[s]);
    const bool within = (grid.periodicX || (box.lo.x() >= lo.x() && box.hi.x() <= hi.x())) &&
                        (grid.periodicY || (box.lo.y() >= lo.y() && box.hi.y() <= hi.y()));
    const double area = within ? b.shape[s]->area() : submerged[s] * cellArea;
    b.buoyancy[s] = Vec2::Zero() - rho * area * gravity;  // no -0 without gravity
  }
  times_.forces += since(t0);
}

void Coupler::clear(dem::Assembly& assembly) {
  elements_.clear();
  circles_.clear();
  pieces_.clear();
  cellOf_.clear();
  epsSum_.clear();
  owners_.clear();
  cells_ = 0;
  fastest_ = SolidSpeed{};
  dem::Bodies& b = assembly.bodies();
  for (int s = 0; s < b.size(); ++s)
    b.fluidForce[s] = Vec2::Zero(), b.fluidTorque[s] = 0, b.buoyancy[s] = Vec2::Zero();
}

}  // namespace sf::coupling
