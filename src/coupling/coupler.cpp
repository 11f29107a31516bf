#include "sandflow/coupling/coupler.hpp"

#include <Eigen/Cholesky>
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
                      const Vec2& gravity, int threads) {
  const auto t0 = Clock::now();
  threads_ = threads;
  Grid grid = gridOf(lattice);
  const dem::Bodies& b = assembly.bodies();
  const int n = b.size();
  const std::vector<lb::CircleObstacle>& circles = lattice.circles();
  const bool remeasure =
      lattice.topologyVersion() != topology_ || settings.subcells != measuredWith_.subcells;
  topology_ = lattice.topologyVersion();
  measuredWith_ = settings;
  if (remeasure) elements_.clear(), circles_.clear();
  if (remeasure || open_.size() != std::size_t(grid.nx) * grid.ny) {
    open_.assign(std::size_t(grid.nx) * grid.ny, 0);
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i)
        open_[std::size_t(j) * grid.nx + i] = lattice.kind(i, j) == lb::NodeKind::fluid;
  }
  grid.open = open_.data();
  elements_.resize(n);
  circles_.resize(circles.size());

  // 1. Coverage of whatever moved (or changed shape) since it was measured,
  //    kept to the cells that hold bulk fluid.
  auto measure = [&](Cached& c, const Footprint& f, const Vec2& reference) {
    cover(f, reference, grid, settings.subcells, c.cells);
  };
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads) if (n >= 16)
  for (int s = 0; s < n; ++s) {
    Cached& c = elements_[s];
    if (!covers(b, s)) {
      c = Cached{};
      continue;
    }
    const dem::Shape& shape = *b.shape[s];
    if (!stale(c, b.id[s], b.x[s], b.angle[s], shape.area(), b.reach[s], 0, false)) continue;
    std::vector<CellCover> kept = std::move(c.cells);  // keep its capacity
    kept.clear();
    c = Cached{b.id[s], b.x[s], b.angle[s], shape.area(), b.reach[s], 0, false, std::move(kept)};
    if (const auto f = footprintOf(shape, b.x[s], b.angle[s])) measure(c, *f, b.x[s]);
  }
  for (std::size_t k = 0; k < circles.size(); ++k) {
    const lb::CircleObstacle& o = circles[k];
    Cached& c = circles_[k];
    if (!stale(c, o.id, o.centre, 0, 0, 0, o.radius, o.outside)) continue;
    c = Cached{o.id, o.centre, 0, 0, 0, o.radius, o.outside, {}};
    measure(c, *circleFootprint(o.centre, o.radius, o.outside), o.centre);
  }

  // 2. One piece per solid per cell, solid by solid (the order the force sums
  //    keep), then the pieces in node order and each node's pieces made a cell.
  const int owners = n + int(circles.size());
  auto coverOf = [&](int owner) -> const std::vector<CellCover>& {
    return owner < n ? elements_[owner].cells : circles_[owner - n].cells;
  };
  pieceStart_.assign(owners + 1, 0);
  for (int o = 0; o < owners; ++o) pieceStart_[o + 1] = pieceStart_[o] + coverOf(o).size();
  pieces_.resize(pieceStart_[owners]);
  keys_.resize(pieces_.size());
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads) if (owners >= 64)
  for (int o = 0; o < owners; ++o) {
    const std::vector<CellCover>& from = coverOf(o);
    const int owner = o < n ? o : -1 - (o - n);
    for (std::size_t k = pieceStart_[o], m = 0; m < from.size(); ++k, ++m) {
      const CellCover& cc = from[m];
      pieces_[k] = {0, owner, cc.eps, cc.arm, cc.interior};
      keys_[k] = std::uint32_t(lattice.nodeIndex(cc.i, cc.j));  // fits: see sortByNode
    }
  }
  sortByNode();
  // Rigid velocities (vx, vy, w) of the owners: elements as they are, or
  // solved with the exchange they will cause; circles as prescribed.
  velocity_.resize(n);
  for (int s = 0; s < n; ++s) velocity_[s] = Vec3(b.v[s].x(), b.v[s].y(), b.w[s]);
  const double toLattice = lattice.params().dt / lattice.params().h;
  // The cells: where the sorted nodes change (sortByNode counted them chunk by
  // chunk), each filled by the chunk its first piece lies in (any thread
  // count, the same list). Explicitly coupled, each cell gets its solid velocity at once
  // and each chunk notes its first fastest cell.
  std::vector<lb::CoveredCell>& cells = cellsBuffer_;  // reused: no fresh pages per step
  const std::ptrdiff_t count = std::ptrdiff_t(order_.size());
  const std::ptrdiff_t chunks = (count + kChunk - 1) / kChunk;
  auto starts = [&](std::ptrdiff_t k) { return k == 0 || keys_[k] != keys_[k - 1]; };
  for (std::ptrdiff_t c = 0; c < chunks; ++c) chunkCells_[c + 1] += chunkCells_[c];
  const std::size_t total = chunkCells_[chunks];
  cells.resize(total), epsSum_.resize(total), cellStart_.resize(total + 1);
  cellStart_[total] = std::int32_t(count);
  const bool blendNow = !settings.implicit;
  chunkFastest_.assign(chunks, {0.0, -1});
#pragma omp parallel for schedule(static) num_threads(threads) if (chunks > 1)
  for (std::ptrdiff_t c = 0; c < chunks; ++c) {
    std::int32_t cell = chunkCells_[c];
    std::pair<double, std::int32_t> best{0.0, -1};
    for (std::ptrdiff_t k = c * kChunk; k < std::min(count, (c + 1) * kChunk); ++k) {
      if (!starts(k)) continue;
      const std::uint32_t node = keys_[k];
      double sum = 0;
      std::ptrdiff_t end = k;
      for (; end < count && keys_[end] == node; ++end) {
        Piece& p = pieces_[order_[end]];
        p.cell = cell;
        sum += p.eps;
      }
      const bool interior = end - k == 1 && pieces_[order_[k]].interior;
      cellStart_[cell] = std::int32_t(k);
      epsSum_[cell] = sum;
      cells[cell] = {node, std::min(1.0, sum), 0.0, 0.0, interior};
      if (blendNow) {
        const Vec2 u = cellVelocity(k, end, sum, circles, toLattice);
        cells[cell].ux = u.x(), cells[cell].uy = u.y();
        if (!interior && u.squaredNorm() > best.first) best = {u.squaredNorm(), cell};
      }
      ++cell;
    }
    chunkFastest_[c] = best;
  }
  if (!blendNow) {
    solveVelocities(lattice, assembly, settings, cells, gravity);
    blendVelocities(lattice, circles, cells);
    // The first fastest cell of each chunk of cells.
    const std::ptrdiff_t cellChunks = (std::ptrdiff_t(total) + kChunk - 1) / kChunk;
    chunkFastest_.assign(cellChunks, {0.0, -1});
#pragma omp parallel for schedule(static) num_threads(threads) if (cellChunks > 1)
    for (std::ptrdiff_t c = 0; c < cellChunks; ++c) {
      std::pair<double, std::int32_t> best{0.0, -1};
      for (std::ptrdiff_t k = c * kChunk; k < std::min(std::ptrdiff_t(total), (c + 1) * kChunk);
           ++k) {
        const double u2 = cells[k].ux * cells[k].ux + cells[k].uy * cells[k].uy;
        if (!cells[k].interior && u2 > best.first) best = {u2, std::int32_t(k)};
      }
      chunkFastest_[c] = best;
    }
  }
  // The fastest surface that the fluid sees (interior cells move no fluid):
  // of the chunks' fastest, the first.
  fastest_ = SolidSpeed{};
  double fastest2 = 0;
  for (const auto& [u2, c] : chunkFastest_) {
    if (!(u2 > fastest2)) continue;
    fastest2 = u2;
    const int owner = pieces_[order_[cellStart_[c]]].owner;
    fastest_.element = owner >= 0 ? b.id[owner] : -1;
    fastest_.obstacle = owner < 0 ? circles[-1 - owner].id : -1;
  }
  fastest_.mach = std::sqrt(fastest2);
  cells_ = cells.size();
  // Ours now holds the old list; the new one ascends by node (sortByNode).
  lattice.swapCoveredCells(cells, settings.equilibriumInterior, true);
  times_.coverage += since(t0);
}

// Each cell's solid velocity: the coverage-weighted mean of its owners' rigid
// velocities at the cell centre, in lattice units.
[[gnu::always_inline]] inline Vec2 Coupler::cellVelocity(
    std::ptrdiff_t first, std::ptrdiff_t last, double epsSum,
    const std::vector<lb::CircleObstacle>& circles, double toLattice) const {
  double ux = 0, uy = 0;
  for (std::ptrdiff_t k = first; k < last; ++k) {
    const Piece& p = pieces_[order_[k]];
    const Vec2 v = p.owner >= 0
                       ? Vec2(velocity_[p.owner].x(), velocity_[p.owner].y()) +
                             spin(velocity_[p.owner].z(), p.arm)
                       : circles[-1 - p.owner].velocity + spin(circles[-1 - p.owner].spin, p.arm);
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
#pragma omp parallel for schedule(static) num_threads(threads_) if (count >= 16384)
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

// The pieces in node order (order_, with keys_ sorted alongside), equal nodes
// in piece order: what a stable sort of all pieces gives. A solid's pieces
// come row by row, so they form runs of consecutive nodes, a few per solid:
// the runs are sorted, laid end to end, and only where runs overlap (cells
// that several solids share) are their pieces sorted one by one.
void Coupler::sortByNode() {
  const std::size_t count = keys_.size();
  runFirst_.clear(), runKeys_.clear();
  for (std::size_t k = 0; k < count; ++k)
    if (k == 0 || keys_[k] != keys_[k - 1] + 1) {
      runFirst_.push_back(std::int32_t(k));
      runKeys_.push_back(keys_[k]);
    }
  runFirst_.push_back(std::int32_t(count));
  const std::vector<std::int32_t>& first = runFirst_;
  radixSort(runKeys_, runOrder_);
  sortedKeys_.resize(count), order_.resize(count);
  // Alongside, per chunk of kChunk sorted pieces, how many start a cell.
  chunkCells_.assign((count + kChunk - 1) / kChunk + 1, 0);
  auto allStart = [&](std::size_t a, std::size_t b) {
    for (std::size_t e; a < b; a = e) {
      e = std::min<std::size_t>(b, (a / kChunk + 1) * kChunk);
      chunkCells_[a / kChunk + 1] += std::int32_t(e - a);
    }
  };
  std::size_t out = 0;
  const std::size_t runs = runOrder_.size();
  for (std::size_t r = 0; r < runs;) {
    // A group: runs whose node ranges overlap, one after another.
    std::size_t end = r + 1;
    auto last = [&](std::size_t q) {
      const std::int32_t run = runOrder_[q];
      return keys_[first[run + 1] - 1];
    };
    std::uint32_t reach = last(r);
    while (end < runs && runKeys_[end] <= reach) reach = std::max(reach, last(end++));
    if (end == r + 1) {
      const std::size_t from = out;
      for (std::int32_t k = first[runOrder_[r]]; k < first[runOrder_[r] + 1]; ++k)
        sortedKeys_[out] = keys_[k], order_[out++] = k;
      allStart(from, out);
    } else {
      const std::size_t from = out;
      for (std::size_t q = r; q < end; ++q)
        for (std::int32_t k = first[runOrder_[q]]; k < first[runOrder_[q] + 1]; ++k)
          sortedKeys_[out] = keys_[k], order_[out++] = k;
      std::sort(order_.begin() + from, order_.begin() + out, [&](std::int32_t x, std::int32_t y) {
        return keys_[x] != keys_[y] ? keys_[x] < keys_[y] : x < y;
      });
      for (std::size_t q = from; q < out; ++q) {
        sortedKeys_[q] = keys_[order_[q]];
        chunkCells_[q / kChunk + 1] += q == from || sortedKeys_[q] != sortedKeys_[q - 1];
      }
    }
    r = end;
  }
  keys_.swap(sortedKeys_);
}

// The implicit coupling. The momentum a cell gives the fluid is linear in the
// solid velocity, E = beta (rho u_s - j) with beta = B (1 for an equilibrium
// interior), so an element's fluid force is F(V) = -K V + F0 for its rigid
// velocity V = (vx, vy, w). Solving the element's update together with it,
//   M (V - V0) = c dt (F_other + F(V)),   c = 1/2 (central, verlet) or 1 (euler),
// gives the velocity the fluid sees. Its interior fluid then cannot feed the
// one-step oscillation that makes the explicit coupling of light elements
// unstable (|lambda| = r / (2 + r) < 1 for any fluid-to-solid mass ratio r).
// Cells shared with other solids count the others' velocities as given.
void Coupler::solveVelocities(const lb::Lattice& lattice, const dem::Assembly& assembly,
                              const Settings& settings, const std::vector<lb::CoveredCell>& cells,
                              const Vec2& gravity) {
  const lb::ResolvedLattice& p = lattice.params();
  const dem::Bodies& b = assembly.bodies();
  const double dt = p.dt, toLattice = dt / p.h, scale = p.h * p.h * p.h / (dt * dt);
  const double tau = p.tau;
  std::vector<double> rho;
  std::vector<Vec2> j;
  lattice.pulledMoments(cells, rho, j);
  // The explicit cell velocities, to take the other owners' part from.
  std::vector<lb::CoveredCell> given = cells;
  blendVelocities(lattice, lattice.circles(), given);

  const int n = b.size();
  std::vector<Eigen::Matrix3d> K(n, Eigen::Matrix3d::Zero());
  std::vector<Vec3> F0(n, Vec3::Zero());
  for (const Piece& piece : pieces_) {
    if (piece.owner < 0) continue;
    const lb::CoveredCell& cell = cells[piece.cell];
    const double beta = cell.interior && settings.equilibriumInterior
                            ? 1.0
                            : cell.eps * (tau - 0.5) / ((1.0 - cell.eps) + (tau - 0.5));
    const double share = settings.share == Share::equal ? 1.0 / sharing(piece.cell)
                                                        : piece.eps / epsSum_[piece.cell];
    const double alpha = piece.eps / epsSum_[piece.cell];
    const double r = rho[piece.cell];
    const Vec2& arm = piece.arm;
    const Vec3& V = velocity_[piece.owner];
    // This owner's own part of the explicit cell velocity, and the others'.
    const Vec2 own = alpha * toLattice * (Vec2(V.x(), V.y()) + spin(V.z(), arm));
    const Vec2 others = Vec2(given[piece.cell].ux, given[piece.cell].uy) - own;
    const double g = scale * toLattice * share * beta * r * alpha;
    Eigen::Matrix3d k;
    k << 1, 0, -arm.y(), 0, 1, arm.x(), -arm.y(), arm.x(), arm.squaredNorm();
    K[piece.owner] += g * k;
    const Vec2 f = scale * share * beta * (j[piece.cell] - r * others);
    F0[piece.owner] += Vec3(f.x(), f.y(), cross(arm, f));
  }
  const double c = assembly.integrator == dem::Integrator::euler ? 1.0 : 0.5;
  for (int s = 0; s < n; ++s) {
    if (K[s].isZero()) continue;
    const bool central = assembly.integrator == dem::Integrator::central && b.started[s];
    const Vec3 base = central ? Vec3(b.vHalf[s].x(), b.vHalf[s].y(), b.wHalf[s]) : velocity_[s];
    // Every force but the fluid's, as the last step left it.
    Vec3 other;
    if (b.started[s]) {
      other << b.force[s].x() - b.fluidForce[s].x(), b.force[s].y() - b.fluidForce[s].y(),
          b.torque[s] - b.fluidTorque[s];
    } else {
      const Vec2 f = b.appliedForce[s] + b.mass[s] * (gravity + b.acceleration[s]) + b.buoyancy[s];
      other << f.x(), f.y(), b.appliedTorque[s];
    }
    const Vec3 M(b.mass[s], b.mass[s], b.inertia[s]);
    Eigen::Matrix3d A = c * dt * K[s];
    A.diagonal() += M;
    Vec3 rhs = M.cwiseProduct(base) + c * dt * (other + F0[s]);
    // Held degrees of freedom keep their prescribed velocity.
    const std::uint8_t hold[3] = {dem::holdX, dem::holdY, dem::holdRotation};
    for (int d = 0; d < 3; ++d)
      if (b.hold[s] & hold[d]) {
        rhs -= A.col(d) * velocity_[s][d];
        A.row(d).setZero();
        A.col(d).setZero();
        A(d, d) = 1;
        rhs[d] = velocity_[s][d];
      }
    velocity_[s] = A.ldlt().solve(rhs);
  }
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
  // Owner by owner over its pieces, in their order: the sums do not depend on
  // the thread count.
  const int n = b.size(), owners = n + int(circles.size());
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads_) if (owners >= 64)
  for (int o = 0; o < owners; ++o) {
    Vec2 force = Vec2::Zero();
    double torque = 0, area = 0;
    for (std::size_t k = pieceStart_[o]; k < pieceStart_[o + 1]; ++k) {
      const Piece& piece = pieces_[k];
      const double share = settings.share == Share::equal ? 1.0 / sharing(piece.cell)
                                                          : piece.eps / epsSum_[piece.cell];
      const Vec2 F = -share * scale * exchange[piece.cell];  // the solid gets the opposite
      force += F;
      torque += cross(piece.arm, F);
      area += piece.eps;
    }
    if (o < n) {
      b.fluidForce[o] = force, b.fluidTorque[o] = torque, submerged[o] = area;
    } else {
      circleForce[o - n] = force, circleTorque[o - n] = torque;
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
  open_.clear();
  topology_ = 0;  // a lattice's versions start above 0: the next one is measured afresh
  pieces_.clear();
  order_.clear();
  cellStart_.clear();
  epsSum_.clear();
  cells_ = 0;
  fastest_ = SolidSpeed{};
  dem::Bodies& b = assembly.bodies();
  for (int s = 0; s < b.size(); ++s)
    b.fluidForce[s] = Vec2::Zero(), b.fluidTorque[s] = 0, b.buoyancy[s] = Vec2::Zero();
}

}  // namespace sf::coupling
