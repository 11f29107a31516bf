#include "sandflow/lb/lattice.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <new>
#include <numeric>

#include "sandflow/core/assert.hpp"
#include "sandflow/core/error.hpp"
#include "sandflow/core/memory.hpp"

namespace sf::lb {
namespace {

double* allocatePopulations(std::size_t count) {
  const std::size_t bytes = (count * sizeof(double) + 63) / 64 * 64;
  void* p = std::aligned_alloc(64, bytes);
  if (!p)
    throw Error("RESOURCE MEMORY",
                "cannot allocate " + formatNumber(bytes / 1e9) + " GB for the lattice populations");
  return static_cast<double*>(p);
}

}  // namespace

Lattice::Lattice(const ResolvedLattice& params) : p_(params) {
  rowStride_ = p_.nx + 2;
  // The nine direction arrays are stride_ apart. A grid of a power-of-two
  // width puts them 32 bytes apart modulo 4 KiB, so the eighteen streams of a
  // step share a handful of L1 sets; padding spreads them over all of them.
  const std::ptrdiff_t nodes = rowStride_ * (p_.ny + 2);
  stride_ = (nodes + 511) / 512 * 512 + 56;
  f_ = allocatePopulations(populationSlots());
  kind_.reserve(stride_);
  // First touch in parallel, the way the step will use the memory.
  const double rho0 = p_.def.density;
  const std::ptrdiff_t n = stride_;
  for (int d = 0; d < 9; ++d) {
    double* a = f_ + d * stride_;
    const double value = d2q9::w[d] * rho0;
#pragma omp parallel for schedule(static) num_threads(threads_.get())
    for (std::ptrdiff_t k = 0; k < n; ++k) a[k] = value;
  }
  rebuildTopology();
  initialize([](const Vec2&, double&, Vec2&) {});
}

Lattice::~Lattice() {
  std::free(f_);
  std::free(spare_);
}

void Lattice::keepPrevious(bool keep) {
  if (keep == (spare_ != nullptr)) return;
  canUndo_ = false;
  if (!keep) {
    std::free(spare_);
    spare_ = nullptr;
    return;
  }
  checkMemory(2.0 * populationSlots() * sizeof(double),
              "a " + std::to_string(p_.nx) + " x " + std::to_string(p_.ny) +
                  " lattice keeping its state before each step (with elements)");
  spare_ = allocatePopulations(populationSlots());
  // The slots no step writes (fixed solids' insides) as they are in f_.
  std::copy(f_, f_ + populationSlots(), spare_);
}

void Lattice::fill() {
  for (const auto& k : kinds_) k->fill(f_, layout_, threads_.get());
}

void Lattice::reconfigure(const ResolvedLattice& params, double machLimit) {
  if (params.nx != p_.nx || params.ny != p_.ny || params.h != p_.h ||
      params.def.origin != p_.def.origin)
    throw Error("VALUE GEOMETRY",
                "the lattice's origin, size and spacing are fixed: delete it and create a new one");
  if (params.def.density != p_.def.density)
    throw Error("VALUE DENSITY",
                "the density is the initial state: it cannot change on a live lattice");
  ResolvedLattice next = params;
  // A pressure side the change leaves alone keeps its excess over the
  // reference pressure c_s^2 rho0, as the fluid's pressure does (c_s follows dt).
  const double cs2 = p_.soundSpeed() * p_.soundSpeed();
  const double cs2Next = next.soundSpeed() * next.soundSpeed();
  for (int s = 0; s < 4; ++s) {
    SideDef& side = next.def.sides[s];
    const SideDef& was = p_.def.sides[s];
    if (side.kind == SideKind::pressure && was.kind == SideKind::pressure &&
        side.pressure == was.pressure)
      side.pressure += (cs2Next - cs2) * p_.def.density;
  }
  const bool wallsChanged = [&] {
    for (int s = 0; s < 4; ++s)
      if (!sameSide(next.def.sides[s], p_.def.sides[s])) return true;
    return next.dt != p_.dt;  // wall terms are in lattice units
  }();
  const bool stepChanged = next.dt != p_.dt || next.tau != p_.tau ||
                           next.tauMinus() != p_.tauMinus() || next.def.forcing != p_.def.forcing ||
                           next.def.collision != p_.def.collision ||
                           next.def.forceScheme != p_.def.forceScheme;
  if (stepChanged) convertPopulations(next, machLimit);
  p_ = next;
  if (wallsChanged)
    rebuildTopology();  // fills the walls' slots
  else if (stepChanged)
    fill();
}

void Lattice::setThreads(int threads) {
  threads_.set(threads);
}

StepContext Lattice::contextFor(const ResolvedLattice& p) const {
  StepContext c;
  c.src = f_;
  c.dst = spare_ ? spare_ : f_;
  c.from = layout_;
  c.stride = stride_;
  c.rowStride = rowStride_;
  c.collision = p.def.collision;
  c.forceScheme = p.def.forceScheme;
  c.params.omegaPlus = 1.0 / p.tau;
  c.params.omegaMinus = 1.0 / p.tauMinus();
  c.params.fx = p.forceToLattice(p.def.forcing.x());
  c.params.fy = p.forceToLattice(p.def.forcing.y());
  c.threads = threads_.get();
  return c;
}

void Lattice::setTime(double t) {
  if (t == time_) return;
  time_ = t;
  if (sidesVary()) imposeSides(time_ + p_.dt);
}

void Lattice::setSideValues(int side, std::vector<Vec2> values) {
  SF_ASSERT(side >= 0 && side < 4);
  SideDef& d = p_.def.sides[side];
  if (d.kind != SideKind::velocity || !d.byExpression())
    throw Error("VALUE WALLS",
                std::string(sideNames[side]) + " is not a velocity side given by expressions");
  checkSideValues(p_, side, values);
  d.values = std::move(values);
  imposeSides(time_ + p_.dt);
}

bool Lattice::sidesVary() const {
  for (const SideDef& d : p_.def.sides)
    if (d.kind == SideKind::velocity && (d.ramp > 0 || d.timed)) return true;
  return false;
}

void Lattice::imposeSides(double t) {
  const double toLattice = p_.dt / p_.h;
  for (const auto& k : kinds_) {
    auto* z = dynamic_cast<ZouHeNode*>(k.get());
    if (!z || z->pressure) continue;
    const SideDef& d = p_.def.sides[z->side];
    z->velocity = d.velocity * toLattice;  // as it always was: uniform sides keep their bits
    z->velocities.clear();
    if (d.profile == SideProfile::uniform && !d.byExpression() && d.ramp == 0) continue;
    const double ramp = rampFactor(t, d.ramp);
    const bool alongX = z->side == bottom || z->side == top;
    for (const std::int64_t x : z->nodes) {
      const int n = int(alongX ? x % rowStride_ - 1 : x / rowStride_ - 1);
      z->velocities.push_back(sideVelocityAt(p_, z->side, n) * toLattice * ramp);
    }
  }
}

StepStats Lattice::step(double machLimit) {
  Profile& profile = profile_.get();
  if (profile_.owned()) profile.beginStep();
  const auto t0 = Profile::Clock::now();
  if (sidesVary()) imposeSides(time_ + p_.dt);
  const StepContext ctx = context();
  StepStats stats;
  // The covered cells in the bulk's sweep when they can be, else in a pass
  // of their own (then the sweep times them, and the bulk's time is the
  // rest): after the bulk into another array, or in place before it, into a
  // buffer written over the bulk's outputs after it. None: the plain sweep
  // (solids all beyond the lattice's walls).
  const FluidNode& fluid = static_cast<const FluidNode&>(*kinds_.front());
  const bool covered = !covered_.cells.empty();
  const bool together = covered && fluid.sweepsWith(covered_);
  const bool before = covered && !together && ctx.inPlace();
  double coveredSeconds = 0, coveredU2 = 0;
  const auto coveredPass = [&](double* buffer) {
    const auto c0 = Profile::Clock::now();
    coveredU2 = covered_.streamCollide(ctx, buffer).maxU2;
    coveredSeconds += std::chrono::duration<double>(Profile::Clock::now() - c0).count();
  };
  if (before) {
    coveredBuffer_.resize(covered_.passBufferSize());
    coveredPass(coveredBuffer_.data());
  }
  for (const auto& k : kinds_)
    stats.merge(k.get() == &fluid && together
                    ? fluid.streamCollideWith(ctx, covered_, coveredSeconds)
                    : k->streamCollide(ctx));
  if (covered && !together) {
    if (before) {
      const auto c0 = Profile::Clock::now();
      covered_.scatterAll(ctx, coveredBuffer_.data());
      coveredSeconds += std::chrono::duration<double>(Profile::Clock::now() - c0).count();
    } else {
      coveredPass(nullptr);
    }
    // Over the bulk's values: the bulk's mass already holds these nodes.
    stats.maxU2 = std::max(stats.maxU2, coveredU2);
  }
  const auto t2 = Profile::Clock::now();
  const double all = std::chrono::duration<double>(t2 - t0).count();
  profile.add(Stage::latticeBulk, std::max(0.0, all - coveredSeconds));
  if (covered) profile.add(Stage::latticeCovered, std::min(all, coveredSeconds));
  const bool unstable = !std::isfinite(stats.mass) || !(stats.maxU2 <= machLimit * machLimit);
  // Another array: a refused step leaves the state before it as it was.
  if (unstable && spare_) reportInstability(stats, machLimit, spare_, flipped(layout_));
  if (spare_) std::swap(f_, spare_);
  layout_ = flipped(layout_);
  fill();
  timeBefore_ = time_;
  time_ += p_.dt;
  lastMach_ = std::sqrt(stats.maxU2);
  canUndo_ = spare_ != nullptr;
  profile.lap(Stage::latticeFill, t2);
  // In place the step is done either way: the state is the one it made.
  if (unstable) reportInstability(stats, machLimit, f_, layout_);
  return stats;
}

void Lattice::undoStep() {
  if (!canUndo_) throw Error("STATE UNDO", "there is no lattice step to undo");
  // The step wrote the other array and swapped: the state before it is intact there.
  std::swap(f_, spare_);
  layout_ = flipped(layout_);
  time_ = timeBefore_;
  canUndo_ = false;
}

void Lattice::moments(const double* f, Layout layout, std::int64_t x, double& rho, double& jx,
                      double& jy) const {
  const Slots s = slots();
  rho = jx = jy = 0;
  for (int d = 0; d < 9; ++d) {
    const double v = f[s.post(layout, d, x)];
    rho += v;
    jx += d2q9::ex[d] * v;
    jy += d2q9::ey[d] * v;
  }
}

void Lattice::reportInstability(const StepStats& stats, double machLimit, const double* f,
                                Layout layout) const {
  // Find the culprit in the new state the step wrote (f, in `layout`).
  std::int64_t worst = -1;
  double worstU2 = -1.0;
  bool nan = !std::isfinite(stats.mass);
  for (int j = 0; j < p_.ny && !(nan && worst >= 0); ++j)
    for (int i = 0; i < p_.nx; ++i) {
      const std::int64_t x = index(i, j);
      if (!holdsFluid(x)) continue;
      double rho, jx, jy;
      moments(f, layout, x, rho, jx, jy);
      const double u2 = (jx * jx + jy * jy) / (rho * rho);
      if (nan && !std::isfinite(rho + jx + jy)) {
        worst = x;
        break;
      }
      if (!nan && u2 > worstU2) worstU2 = u2, worst = x;
    }
  const int i = int(worst % rowStride_) - 1, j = int(worst / rowStride_) - 1;
  const Vec2 at = worst >= 0 ? position(i, j) : Vec2::Zero();
  const std::string where = "node (" + std::to_string(i) + ", " + std::to_string(j) + ") at {" +
                            formatNumber(at.x()) + " " + formatNumber(at.y()) + "}";
  if (nan) throw Error("UNSTABLE NAN", "the fluid became NaN at " + where);
  throw Error("UNSTABLE MACH", "Mach number " + formatNumber(std::sqrt(stats.maxU2)) + " exceeds " +
                                   formatNumber(machLimit) + " at " + where +
                                   ": reduce the timestep or the forcing");
}

// Pre-collision velocity (lattice units) from the stored post-collision state:
// collision adds F to the first moment, and Guo's velocity carries F/2 back.
Vec2 Lattice::velocityFromMoments(double rho, double jx, double jy) const {
  const double back = p_.def.forceScheme == ForceScheme::guo ? 0.5 : 1.0;
  const Vec2 F(p_.forceToLattice(p_.def.forcing.x()), p_.forceToLattice(p_.def.forcing.y()));
  return (Vec2(jx, jy) - back * F) / rho;
}

Vec2 Lattice::latticeVelocity(std::int64_t x) const {
  double rho, jx, jy;
  moments(f_, layout_, x, rho, jx, jy);
  return velocityFromMoments(rho, jx, jy);
}

bool Lattice::holdsFluid(std::int64_t x) const {
  const NodeKind k = kind_[x];
  return k == NodeKind::fluid || k == NodeKind::velocity || k == NodeKind::pressure;
}

double Lattice::density(int i, int j) const {
  const std::int64_t x = index(i, j);
  if (!holdsFluid(x)) return p_.def.density;
  double rho, jx, jy;
  moments(f_, layout_, x, rho, jx, jy);
  return rho;
}

Vec2 Lattice::velocity(int i, int j) const {
  const std::int64_t x = index(i, j);
  if (!holdsFluid(x)) return Vec2::Zero();
  return latticeVelocity(x) * p_.latticeSpeed();
}

void Lattice::rowFields(int j, double* rho, Vec2* u) const {
  std::vector<int> all(std::size_t(p_.nx));
  std::iota(all.begin(), all.end(), 0);
  rowFields(j, all.data(), p_.nx, rho, u);
}

void Lattice::rowFields(int j, const int* columns, int n, double* rho, Vec2* u) const {
  // Each direction's slot is the node plus a fixed offset in this layout:
  // found once for the row, not per node and direction.
  const Slots s = slots();
  std::array<std::ptrdiff_t, 9> offset;
  for (int d = 0; d < 9; ++d) offset[std::size_t(d)] = s.post(layout_, d, 0);
  const std::int64_t first = index(0, j);
  for (int k = 0; k < n; ++k) {
    const std::int64_t x = first + columns[k];
    if (!holdsFluid(x)) {
      rho[k] = p_.def.density;
      u[k] = Vec2::Zero();
      continue;
    }
    double r = 0, jx = 0, jy = 0;  // in moments()'s order: the same sums to the bit
    for (int d = 0; d < 9; ++d) {
      const double v = f_[offset[std::size_t(d)] + x];
      r += v;
      jx += d2q9::ex[d] * v;
      jy += d2q9::ey[d] * v;
    }
    rho[k] = r;
    u[k] = velocityFromMoments(r, jx, jy) * p_.latticeSpeed();
  }
}

double Lattice::pressure(int i, int j) const {
  const double cs = p_.soundSpeed();
  return cs * cs * density(i, j);
}

Vec2 Lattice::position(int i, int j) const {
  return p_.def.origin + Vec2((i + 0.5) * p_.h, (j + 0.5) * p_.h);
}

std::optional<std::pair<int, int>> Lattice::nodeAt(const Vec2& x) const {
  const Vec2 r = (x - p_.def.origin) / p_.h;
  if (!(r.x() >= 0 && r.y() >= 0 && r.x() <= p_.nx && r.y() <= p_.ny)) return std::nullopt;
  return std::pair{std::min(int(r.x()), p_.nx - 1), std::min(int(r.y()), p_.ny - 1)};
}

double Lattice::mass() const {
  double m = 0;
  for (int j = 0; j < p_.ny; ++j)
    for (int i = 0; i < p_.nx; ++i)
      if (holdsFluid(index(i, j)))
        for (int d = 0; d < 9; ++d) m += f_[slots().post(layout_, d, index(i, j))];
  return m * p_.h * p_.h;
}

Vec2 Lattice::momentum() const {
  Vec2 m = Vec2::Zero();
  for (int j = 0; j < p_.ny; ++j)
    for (int i = 0; i < p_.nx; ++i) {
      const std::int64_t x = index(i, j);
      if (!holdsFluid(x)) continue;
      double rho, jx, jy;
      moments(f_, layout_, x, rho, jx, jy);
      m += rho * velocityFromMoments(rho, jx, jy);
    }
  return m * p_.h * p_.h * p_.latticeSpeed();
}

double Lattice::maxMach() const {
  // Rows on the step's threads: the status line asks for this every frame. A
  // maximum is the same in any order, so the result does not depend on them.
  double u2 = 0;
#pragma omp parallel for schedule(static) num_threads(threads_.get()) reduction(max : u2)
  for (int j = 0; j < p_.ny; ++j)
    for (int i = 0; i < p_.nx; ++i)
      if (holdsFluid(index(i, j))) u2 = std::max(u2, latticeVelocity(index(i, j)).squaredNorm());
  return std::sqrt(u2);
}

void Lattice::initialize(const std::function<void(const Vec2&, double&, Vec2&)>& field) {
  for (int j = 0; j < p_.ny; ++j)
    for (int i = 0; i < p_.nx; ++i) {
      const std::int64_t x = index(i, j);
      if (!holdsFluid(x)) continue;
      double rho = p_.def.density;
      Vec2 u = Vec2::Zero();
      field(position(i, j), rho, u);
      if (!(rho > 0) || !std::isfinite(rho) || !u.allFinite())
        throw Error("VALUE FIELD",
                    "initial field is not a positive finite density and "
                    "finite velocity at {" +
                        formatNumber(position(i, j).x()) + " " + formatNumber(position(i, j).y()) +
                        "}");
      setNodeState(x, rho, u * (p_.dt / p_.h));
    }
  fill();
}

void Lattice::setNodeState(std::int64_t x, double rho, const Vec2& u) {
  canUndo_ = false;
  double f[9];
  collidedEquilibrium(context(), rho, u, f);
  const Slots s = slots();
  for (int d = 0; d < 9; ++d) f_[s.post(layout_, d, x)] = f[d];
}

void Lattice::collidedEquilibrium(const StepContext& ctx, double rho, const Vec2& u,
                                  double (&f)[9]) {
  // Stored populations are post-collision: collide an equilibrium whose
  // collision velocity is u, so that the node reports u (and the force acts
  // from t = 0 on).
  const double back = ctx.forceScheme == ForceScheme::guo ? 0.5 : 0.0;
  const Vec2 ueq = u - back * Vec2(ctx.params.fx, ctx.params.fy) / rho;
  equilibria(rho, ueq.x(), ueq.y(), f);
  double u2;
  collide(ctx.collision, ctx.forceScheme, f, ctx.params, u2);
}

double Lattice::population(int direction, int i, int j) const {
  return f_[slots().post(layout_, direction, index(i, j))];
}

std::vector<double> Lattice::populations() const {
  std::vector<double> f(9 * nodes(), 0.0);
  const Slots s = slots();
  for (int j = 0; j < p_.ny; ++j)
    for (int i = 0; i < p_.nx; ++i) {
      const std::int64_t x = index(i, j);
      if (!holdsFluid(x)) continue;
      for (int d = 0; d < 9; ++d)
        f[(std::size_t(d) * p_.ny + j) * p_.nx + i] = f_[s.post(layout_, d, x)];
    }
  return f;
}

std::size_t Lattice::memoryBytes() const {
  return (spare_ ? 2 : 1) * populationSlots() * sizeof(double) +
         kind_.capacity() * sizeof(NodeKind);
}

// ---- obstacles -------------------------------------------------------------

namespace {

// The id to give a new obstacle: `wanted`, or the next free one when < 0.
int obstacleId(int wanted, const std::vector<int>& used) {
  if (wanted < 0) {
    int id = 0;
    for (int u : used) id = std::max(id, u + 1);
    return id;
  }
  if (std::find(used.begin(), used.end(), wanted) != used.end())
    throw Error("VALUE ID", "obstacle id " + std::to_string(wanted) + " is in use");
  return wanted;
}

}  // namespace

int Lattice::addObstacle(const RectObstacle& rect) {
  RectObstacle r = rect;
  if (!r.lo.allFinite() || !r.hi.allFinite() || !(r.lo.x() < r.hi.x()) || !(r.lo.y() < r.hi.y()))
    throw Error("VALUE RECT", "rect must be {x0 y0 x1 y1} with x0 < x1 and y0 < y1");
  r.id = obstacleId(r.id, obstacleIds());
  bool covers = false;
  for (int j = 0; j < p_.ny && !covers; ++j)
    for (int i = 0; i < p_.nx && !covers; ++i) {
      const Vec2 x = position(i, j);
      covers = x.x() >= r.lo.x() && x.x() <= r.hi.x() && x.y() >= r.lo.y() && x.y() <= r.hi.y();
    }
  if (!covers)
    throw Error("VALUE RECT", "rect {" + formatNumber(r.lo.x()) + " " + formatNumber(r.lo.y()) +
                                  " " + formatNumber(r.hi.x()) + " " + formatNumber(r.hi.y()) +
                                  "} covers no lattice node (spacing " + formatNumber(p_.h) + ")");
  obstacles_.push_back(r);
  rebuildTopology();
  return r.id;
}

int Lattice::addCircle(const CircleObstacle& circle) {
  CircleObstacle c = circle;
  if (!c.centre.allFinite() || !std::isfinite(c.radius) || !c.velocity.allFinite() ||
      !std::isfinite(c.spin))
    throw Error("VALUE CIRCLE", "circle centre, radius and velocity must be finite");
  if (!(c.radius > 0))
    throw Error("VALUE RADIUS", "circle radius must be > 0, got " + formatNumber(c.radius));
  // Inside: some of the disc must lie on the lattice; outside: some of the
  // lattice must lie outside the disc.
  const Vec2 lo = p_.def.origin, hi = lo + Vec2(p_.nx * p_.h, p_.ny * p_.h);
  const Vec2 nearest = c.centre.cwiseMax(lo).cwiseMin(hi);
  double farthest = 0;
  for (const Vec2& corner : {lo, hi, Vec2(lo.x(), hi.y()), Vec2(hi.x(), lo.y())})
    farthest = std::max(farthest, (corner - c.centre).norm());
  if (!c.outside && (nearest - c.centre).norm() >= c.radius)
    throw Error("VALUE CIRCLE", "circle {" + formatNumber(c.centre.x()) + " " +
                                    formatNumber(c.centre.y()) + " " + formatNumber(c.radius) +
                                    "} lies outside the lattice");
  if (c.outside && farthest <= c.radius)
    throw Error("VALUE CIRCLE",
                "circle {" + formatNumber(c.centre.x()) + " " + formatNumber(c.centre.y()) + " " +
                    formatNumber(c.radius) +
                    "} holds the whole lattice: as an outside circle it would cover nothing");
  c.id = obstacleId(c.id, obstacleIds());
  c.force = Vec2::Zero(), c.torque = 0, c.cells = 0;
  circles_.push_back(c);
  return c.id;
}

void Lattice::setCircleLoad(std::size_t index, const Vec2& force, double torque,
                            std::size_t cells) {
  CircleObstacle& c = circles_.at(index);
  c.force = force, c.torque = torque, c.cells = cells;
}

void Lattice::advanceCircles(double dt) {
  const Vec2 period(p_.nx * p_.h, p_.ny * p_.h);
  const bool periodic[2] = {p_.def.sides[left].kind == SideKind::periodic,
                            p_.def.sides[bottom].kind == SideKind::periodic};
  for (CircleObstacle& c : circles_) {
    c.centre += dt * c.velocity;
    for (int a = 0; a < 2; ++a)
      if (periodic[a] && c.velocity[a] != 0) {
        const double lo = p_.def.origin[a];
        c.centre[a] = lo + std::fmod(std::fmod(c.centre[a] - lo, period[a]) + period[a], period[a]);
      }
  }
}

void Lattice::setCoveredCells(std::vector<CoveredCell> cells, bool equilibriumInterior) {
  swapCoveredCells(cells, equilibriumInterior);
}

void Lattice::swapCoveredCells(std::vector<CoveredCell>& cells, bool equilibriumInterior,
                               bool inNodeOrder) {
  covered_.cells.swap(cells);
  covered_.equilibriumInterior = equilibriumInterior;
  // Not zeroed: the next step writes every cell's (the force sums read them
  // after it), and zeroing cost a pass over the array a step.
  covered_.exchange.resize(covered_.cells.size());
  const auto descent = [&] {
    return std::adjacent_find(
        covered_.cells.begin(), covered_.cells.end(),
        [](const CoveredCell& a, const CoveredCell& b) { return a.node >= b.node; });
  };
  SF_ASSERT(!inNodeOrder || descent() == covered_.cells.end());
  covered_.ascending = inNodeOrder || descent() == covered_.cells.end();
  static_cast<FluidNode&>(*kinds_.front()).planSweep(covered_.cells, covered_.ascending);
}

void Lattice::pulledMoments(const std::vector<CoveredCell>& cells, std::vector<double>& rho,
                            std::vector<Vec2>& j) const {
  rho.resize(cells.size());
  j.resize(cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const Slots s = slots();
    double r = 0, jx = 0, jy = 0;
    for (int d = 0; d < 9; ++d) {
      const double f = f_[s.input(layout_, d, cells[k].node)];
      r += f, jx += d2q9::ex[d] * f, jy += d2q9::ey[d] * f;
    }
    rho[k] = r;
    j[k] = Vec2(jx, jy);
  }
}

double Lattice::solidRatio(int i, int j) const {
  const std::int64_t x = index(i, j);
  for (const CoveredCell& c : covered_.cells)
    if (c.node == x) return c.eps;
  return 0.0;
}

Vec2 Lattice::solidVelocity(int i, int j) const {
  const std::int64_t x = index(i, j);
  for (const CoveredCell& c : covered_.cells)
    if (c.node == x) return Vec2(c.ux, c.uy) * p_.latticeSpeed();
  return Vec2::Zero();
}

void Lattice::deleteObstacle(int id) {
  auto circle = std::find_if(circles_.begin(), circles_.end(),
                             [&](const CircleObstacle& o) { return o.id == id; });
  if (circle != circles_.end()) {
    circles_.erase(circle);
    return;
  }
  auto it = std::find_if(obstacles_.begin(), obstacles_.end(),
                         [&](const RectObstacle& o) { return o.id == id; });
  if (it == obstacles_.end())
    throw Error("LOOKUP OBSTACLE", "no obstacle with id " + std::to_string(id));
  obstacles_.erase(it);
  rebuildTopology();
}

std::vector<int> Lattice::obstacleIds() const {
  std::vector<int> ids;
  for (const auto& o : obstacles_) ids.push_back(o.id);
  for (const auto& o : circles_) ids.push_back(o.id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

bool Lattice::hasNoSlipSurfaces() const {
  for (const SideDef& side : p_.def.sides)
    if (side.kind == SideKind::noslip) return true;
  return !circles_.empty() || std::any_of(obstacles_.begin(), obstacles_.end(),
                                          [](const RectObstacle& o) { return !o.slip; });
}

ObstacleInfo Lattice::obstacleInfo(int id) const {
  ObstacleInfo info;
  auto circle = std::find_if(circles_.begin(), circles_.end(),
                             [&](const CircleObstacle& o) { return o.id == id; });
  if (circle != circles_.end()) {
    info.circle = true;
    info.disc = *circle;
    info.nodes = circle->cells;
    info.force = circle->force;
    info.torque = circle->torque;
    return info;
  }
  auto it = std::find_if(obstacles_.begin(), obstacles_.end(),
                         [&](const RectObstacle& o) { return o.id == id; });
  if (it == obstacles_.end())
    throw Error("LOOKUP OBSTACLE", "no obstacle with id " + std::to_string(id));
  info.rect = *it;
  const Vec2 centre = 0.5 * (it->lo + it->hi);
  for (int j = 0; j < p_.ny; ++j)
    for (int i = 0; i < p_.nx; ++i) {
      const Vec2 x = position(i, j);
      info.nodes +=
          x.x() >= it->lo.x() && x.x() <= it->hi.x() && x.y() >= it->lo.y() && x.y() <= it->hi.y();
    }
  // Momentum exchange over the wall links: what leaves the fluid node towards
  // the wall minus what comes back, per step.
  const double scale = p_.h * p_.h * p_.h / (p_.dt * p_.dt);
  const Slots s = slots();
  for (const auto& k : kinds_) {
    const auto* links = dynamic_cast<const LinkNode*>(k.get());
    if (!links || dynamic_cast<const PeriodicNode*>(k.get())) continue;
    for (const Link& l : links->links) {
      if (l.owner != id) continue;
      const int in = l.in, out = l.out;
      const Vec2 dp = f_[s.post(layout_, out, l.from)] * Vec2(d2q9::ex[out], d2q9::ey[out]) -
                      f_[s.input(layout_, in, l.node)] * Vec2(d2q9::ex[in], d2q9::ey[in]);
      const Vec2 F = dp * scale;
      const int i = l.node % rowStride_ - 1, j = l.node / rowStride_ - 1;
      const Vec2 arm = position(i, j) - 0.5 * p_.h * Vec2(d2q9::ex[in], d2q9::ey[in]) - centre;
      info.force += F;
      info.torque += arm.x() * F.y() - arm.y() * F.x();
    }
  }
  return info;
}

}  // namespace sf::lb
