#include "sandflow/sim/manager.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sandflow/core/error.hpp"

namespace sf::sim {
namespace {

// A measured number for a message, to `digits` significant digits (a box's
// width is 1.2000000000000002).
std::string rounded(double value, int digits) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

// What marks each warning given once a run in the log (Manager::warned).
constexpr std::string_view kBgkMarker = "with the BGK collision: its bounce-back walls slip";
constexpr std::string_view kLightMarker = "too light for the explicit coupling";
constexpr std::string_view kOverlapMarker = "its own periodic image";
constexpr std::string_view kCellReynoldsMarker = "cell Reynolds number";
constexpr std::string_view kDemStepMarker = "over its accurate step";
constexpr std::string_view kOutrunMarker = "faster than anything that drives it";

}  // namespace

// The default thread count honours OMP_NUM_THREADS (else the machine's cores).
Manager::Manager() : threads_(std::make_unique<int>(std::max(1, omp_get_max_threads()))) {
  attachParts();
}

void Manager::attachParts() {
  assembly_.attachThreads(threads_.get());
  coupler_.attachThreads(threads_.get());
  if (lattice_) lattice_->attachThreads(threads_.get());
}

lb::Lattice& Manager::lattice() {
  if (!lattice_) throw Error("LOOKUP LATTICE", "there is no lattice", Remedy::createLattice);
  return *lattice_;
}

const lb::Lattice& Manager::lattice() const {
  if (!lattice_) throw Error("LOOKUP LATTICE", "there is no lattice", Remedy::createLattice);
  return *lattice_;
}

void Manager::createLattice(lb::LatticeDef def) {
  if (lattice_) throw Error("EXISTS LATTICE", "a lattice exists", Remedy::deleteLattice);
  // A fixed timestep gives tau (with a viscosity) or the viscosity (with tau).
  if (fixedTimestep_ && (!def.tau || !def.viscosity)) def.timestep = fixedTimestep_;
  auto lattice = std::make_unique<lb::Lattice>(lb::resolve(def));
  // Extreme but finite settings (a viscosity of 1e-300 makes the timestep
  // 1e296) can leave the first state itself not finite: refuse them here.
  if (const std::vector<std::string> problems = lattice->validate(); !problems.empty())
    throw Error("VALUE LATTICE", "these settings give the fluid a state that is not finite (" +
                                     problems.front() + "): check the viscosity, tau and forcing");
  lattice_ = std::move(lattice);
  attachParts();
  latticeBorn_ = steps_;
  machWarned_ = false;
  checkCollision();
}

void Manager::reconfigureLattice(const lb::LatticeDef& def) {
  lattice();  // there must be one
  configureStep(def, std::nullopt, std::nullopt);
}

// Given when the lattice is made or changed, and (for obstacles added since,
// or a timestep that moved tau) at the step.
void Manager::checkCollision() {
  const lb::ResolvedLattice& p = lattice_->params();
  if (p.def.collision != lb::Collision::bgk || !(p.tau > kBgkTauLimit) ||
      !lattice_->hasNoSlipSurfaces() || warned(kBgkMarker))
    return;
  warn("tau " + rounded(p.tau, 6) + " " + std::string(kBgkMarker) +
           ", an error that grows as tau squared (channel flow 16 cells across is 5% off at tau "
           "2, 15% at 3, 54% at 5, 250% at 10): keep tau at " +
           formatNumber(kBgkTauLimit) + " or less",
       Remedy::trtCollision);
}

// Both want the coverage of this step (the coupler's prepare).
void Manager::checkCoverage() {
  const dem::Bodies& b = assembly_.bodies();
  const coupling::SelfOverlap& o = coupler_.selfOverlapping();
  if (o.count > 0 && !warned(kOverlapMarker)) {
    const lb::ResolvedLattice& p = lattice_->params();
    double wide = 0;  // the first one's extent along (the first of) its axes
    const int axis = o.axes & 1 ? 0 : 1;
    if (o.element >= 0) {
      for (int s = 0; s < b.size(); ++s)
        if (b.id[s] == o.element) {
          const dem::Box box = b.shape[s]->bounds(b.x[s], b.angle[s]);
          wide = box.hi[axis] - box.lo[axis];
        }
    } else {
      for (const lb::CircleObstacle& c : lattice_->circles())
        if (c.id == o.obstacle) wide = 2 * c.radius;
    }
    const double length = (axis == 0 ? p.nx : p.ny) * p.h;
    const std::string more = o.count > 1 ? " (and " + std::to_string(o.count - 1) + " more)" : "";
    warn((o.element >= 0 ? "element " + std::to_string(o.element)
                         : "obstacle " + std::to_string(o.obstacle)) +
         more + " is " + rounded(wide, 6) + " wide along " + (axis == 0 ? "x" : "y") +
         (wide >= length ? ", as wide as the periodic lattice (" + rounded(length, 6) + ") or wider"
                         : ", within a cell of the periodic lattice's " + rounded(length, 6)) +
         ": it meets " + std::string(kOverlapMarker) +
         ", and the cells there get wrong solid ratios (fluid flows through it); make the "
         "lattice wider than the element by a cell or more");
  }
  if (coupling_.implicit || warned(kLightMarker)) return;
  // |lambda| reaches 1 at r = 1 with the first-order integrator, at 1/2 with
  // the others (docs/coupling.md, Stability).
  const double limit = assembly_.integrator == dem::Integrator::euler ? 1.0 : 0.5;
  const double rho = lattice_->params().def.density;
  int first = -1, count = 0;
  double feedback = 0;
  for (int s = 0; s < b.size(); ++s) {
    if (b.ghost[s] || b.shape[s]->type() == dem::ShapeType::wall) continue;
    // r is at most rho A / m (B <= eps), a quarter more for the stair-step
    // and subcell ratios: most elements are heavier and need no sum.
    if (1.25 * rho * b.shape[s]->area() < limit * b.mass[s]) continue;
    const double r = coupler_.explicitFeedback(*lattice_, b, s);
    if (!(r >= limit) || count++ > 0) continue;
    first = s, feedback = r;
  }
  if (count == 0) return;
  warn("element " + std::to_string(b.id[first]) +
           (count > 1 ? " (and " + std::to_string(count - 1) + " more)" : "") + ", of density " +
           rounded(b.mass[first] / (b.shape[first]->area() * rho), 3) + " times the fluid's, is " +
           std::string(kLightMarker) + ": the fluid inside it feeds back " + rounded(feedback, 3) +
           " of its motion each step, at or over the limit " + formatNumber(limit) +
           ", so its velocity will flip sign from step to step and grow",
       Remedy::implicitCoupling);
}

void Manager::deleteLattice() {
  lattice();  // throws if none
  lattice_.reset();
  coupler_.clear(assembly_);
  coupled_ = false;
}

void Manager::setCoupling(const coupling::Settings& settings) {
  if (settings.subcells != coupling::kExact && settings.subcells != 1 && settings.subcells != 2 &&
      settings.subcells != 4 && settings.subcells != 8)
    throw Error("VALUE SOLIDRATIO", "the solid ratio's subcells must be exact, 1, 2, 4 or 8, got " +
                                        std::to_string(settings.subcells));
  coupling_ = settings;
}

double Manager::timestep() const {
  if (lattice_) return lattice_->params().dt;
  if (fixedTimestep_) return *fixedTimestep_;
  const double critical = assembly_.criticalTimestep();
  return std::isfinite(critical) ? critical / 10 : 0.0;
}

void Manager::setGravity(const Vec2& g) {
  if (!g.allFinite()) throw Error("VALUE GRAVITY", "gravity must be finite");
  gravity_ = g;
}

// The remedy counts the substeps that bring the element step under the
// critical one (none past the most a step may take).
void Manager::checkDemTimestep(double step, int substeps) const {
  const double critical = assembly_.criticalTimestep();
  const double dt = step / substeps;
  if (!(dt > critical)) return;
  long long needed = 0;
  if (step / critical <= double(kMaxSubsteps)) {
    needed = std::llround(std::ceil(step / critical));
    while (step / double(needed) > critical) ++needed;  // rounding at the boundary
  }
  throw Error("VALUE TIMESTEP",
              "timestep " + formatNumber(dt) + " exceeds the elements' critical timestep " +
                  formatNumber(critical) + " (2 sqrt(m/k), lightest element, stiffest material)",
              {Remedy::elementSubsteps, needed <= kMaxSubsteps ? needed : 0});
}

// Over the accurate step, impacts rebound off their set restitution (by
// 20% or more at twice it, docs/stability.md) and can gain energy; over the
// stable step a lasting contact grows. The critical step (refused above) is
// the undamped single element's, so both can lie under it.
void Manager::checkDemAccuracy(double dt) {
  const dem::Assembly::TimestepLimits limits = assembly_.timestepLimits();
  if (!(dt > limits.accurate) || warned(kDemStepMarker)) return;
  const int more = int(std::ceil(substeps_ * dt / limits.accurate));
  const bool unstable = dt > limits.stable;
  warn("the element step " + formatNumber(dt) + " is " + rounded(dt / limits.accurate, 3) +
       " times " + std::string(kDemStepMarker) + " " + formatNumber(limits.accurate) +
       " (0.5 sqrt(m*/k), effective mass m* " + formatNumber(limits.effectiveMass) +
       ", stiffness k " + formatNumber(limits.stiffness) + ")" +
       (unstable ? " and over its stable step " + formatNumber(limits.stable) +
                       " (2 sqrt(m*/k) (sqrt(1 + zeta^2) - zeta), damping ratio zeta " +
                       rounded(limits.zeta, 3) + "): a lasting contact will grow without bound"
                 : ": a contact spans under 6 steps, so impacts rebound off their set "
                   "restitution and can gain energy") +
       "; take " + std::to_string(more) + " element substeps per step, or a timestep " +
       std::to_string(more) + " times smaller");
}

// A flow driven only by its walls and held solids (no forcing, no inlet, no
// pressure side, no free element) stays about as slow as they are; twice the
// fastest of them is going unstable (TRT at tau 10, lid 0.04 c:
// docs/stability.md, problem 6). A free element's wake can outlive its
// motion, so scenes with one are not judged; nor is a lattice's start, whose
// sound waves can outrun an impulsively started wall (Couette at 320 cells:
// 2.3 times at step 2) until they have crossed it twice. A lattice loaded
// from a checkpoint counts as started.
void Manager::checkOutrun() {
  const lb::ResolvedLattice& p = lattice_->params();
  if (!p.def.forcing.isZero() || steps_ - latticeBorn_ < 4LL * std::max(p.nx, p.ny)) return;
  const dem::Bodies& b = assembly_.bodies();
  if (coupled_)
    for (int s = 0; s < b.size(); ++s)
      if (b.invMass[s] > 0 || b.invInertia[s] > 0) return;
  double driver = coupled_ ? coupler_.fastest().mach : 0.0;
  for (const lb::SideDef& side : p.def.sides) {
    if (side.kind == lb::SideKind::velocity || side.kind == lb::SideKind::pressure) return;
    if (side.kind == lb::SideKind::noslip)
      driver = std::max(driver, p.velocityToLattice(side.velocity.norm()));
  }
  // A circular wall's solid turns rigidly: out to its rim, or, for one that
  // holds the fluid inside it, out to the lattice's farthest corner (the
  // covered nodes there move with it, and the fastest fluid counts them).
  const Vec2 lo = p.def.origin, hi = lo + Vec2(p.nx * p.h, p.ny * p.h);
  for (const lb::CircleObstacle& c : lattice_->circles()) {
    double reach = c.radius;
    if (c.outside)
      for (const Vec2& corner : {lo, hi, Vec2(lo.x(), hi.y()), Vec2(hi.x(), lo.y())})
        reach = std::max(reach, (corner - c.centre).norm());
    driver = std::max(driver, p.velocityToLattice(c.velocity.norm() + std::abs(c.spin) * reach));
  }
  const double fluid = lattice_->lastStepMach();
  // Under a billionth of the lattice speed both are rounding noise.
  // (The log is searched last: this runs every step.)
  if (!(driver > 1e-9) || !(fluid > 2 * driver) || warned(kOutrunMarker)) return;
  warn("the fluid moves at " + rounded(fluid / driver, 3) + " times the fastest wall or " +
       "solid at step " + std::to_string(steps_ + 1) + " (" + formatNumber(fluid) + " against " +
       formatNumber(driver) + " of the lattice speed), " + std::string(kOutrunMarker) +
       ": the flow is going unstable (tau " + rounded(p.tau, 6) +
       "; a smaller tau, a finer lattice or a smaller timestep)");
}

// Near tau 0.5 the viscosity is too small for the grid: grid-scale
// oscillations grow, unseen by the Mach check until the flow is several
// times faster than anything drives it (docs/stability.md, tau).
void Manager::checkCellReynolds() {
  const lb::ResolvedLattice& p = lattice_->params();
  const double nu = (p.tau - 0.5) / 3;  // lattice units, as the speed
  const double re = lattice_->lastStepMach() / nu;
  if (!(re > kCellReynoldsLimit) || warned(kCellReynoldsMarker)) return;
  warn("the " + std::string(kCellReynoldsMarker) + " u h / nu is " + rounded(re, 3) + " at step " +
       std::to_string(steps_ + 1) + " (fastest fluid " + formatNumber(lattice_->lastStepMach()) +
       " of the lattice speed, tau " + rounded(p.tau, 6) + "), over " +
       formatNumber(kCellReynoldsLimit) +
       ": with tau this near 0.5 grid-scale oscillations can grow unseen; refine the lattice "
       "or raise tau (more viscosity or a smaller timestep)");
}

void Manager::setStepping(std::optional<double> dt, std::optional<int> substeps) {
  configureStep(std::nullopt, dt, substeps);
}

void Manager::configureStep(const std::optional<lb::LatticeDef>& def, std::optional<double> dt,
                            std::optional<int> substeps) {
  const int n = substeps.value_or(substeps_);
  if (n < 1 || n > kMaxSubsteps)
    throw Error("VALUE SUBSTEPS", "substeps must be 1 to " + std::to_string(kMaxSubsteps) +
                                      ", got " + std::to_string(n));
  if (dt && (!(*dt > 0) || !std::isfinite(*dt)))
    throw Error("VALUE TIMESTEP", "a timestep must be > 0, got " + formatNumber(*dt));
  // Everything is checked before anything changes; the lattice converts its
  // populations once (may refuse: tau).
  std::optional<lb::ResolvedLattice> next;
  if (lattice_ && (def || dt)) {
    lb::LatticeDef d = def.value_or(lattice_->params().def);
    if (dt) {  // the viscosity stays and tau follows
      d.viscosity = lb::resolve(d).viscosity;
      d.tau.reset();
      d.timestep = *dt;
    }
    next = lb::resolve(d);
  }
  if (dt) {
    checkDemTimestep(*dt, n);
  } else if (substeps && !assembly_.empty()) {
    const double step = next ? next->dt : timestep();
    if (step > 0) checkDemTimestep(step, n);
  }
  if (next) lattice_->reconfigure(*next);
  if (dt)
    fixedTimestep_ = *dt;
  else if (fixedTimestep_ && next)
    fixedTimestep_ = next->dt;
  substeps_ = n;
  if (next) checkCollision();
}

void Manager::setThreads(int threads) {
  if (threads < 1 || threads > kMaxThreads)
    throw Error("VALUE THREADS", "the thread count must be 1 to " + std::to_string(kMaxThreads) +
                                     ", got " + std::to_string(threads));
  *threads_ = threads;
  attachParts();
}

// Covers the lattice for this step and checks what the fluid will see: a solid
// surface faster than the Mach limit stops the step before anything changes;
// one above the warning limit, an element spanning under two cells, and what
// checkCoverage finds, warn.
void Manager::coupleBeforeFluid() {
  coupler_.prepare(*lattice_, assembly_, coupling_, gravity_);
  const coupling::SolidSpeed& fast = coupler_.fastest();
  const std::string who = fast.element >= 0 ? "element " + std::to_string(fast.element)
                                            : "obstacle " + std::to_string(fast.obstacle);
  if (fast.mach > machStopLimit())
    throw Error("UNSTABLE SOLIDSPEED", "the surface of " + who + " moves at Mach " +
                                           formatNumber(fast.mach) + " over the lattice, beyond " +
                                           formatNumber(machStopLimit()) +
                                           ": reduce the timestep or the speed");
  if (!solidMachWarned_ && fast.mach > machWarnLimit()) {
    solidMachWarned_ = true;
    warn("the surface of " + who + " moves at Mach " + formatNumber(fast.mach) +
         " over the lattice, beyond " + formatNumber(machWarnLimit()) +
         ": the fluid near it is no longer nearly incompressible");
  }
  const dem::Bodies& b = assembly_.bodies();
  const double h = lattice_->params().h;
  for (int s = 0; s < b.size(); ++s) {
    if (b.ghost[s] || b.shape[s]->type() == dem::ShapeType::wall) continue;
    const double size = 2 * b.extent[s];
    if (size >= 2 * h || !underResolvedWarned_.insert(b.id[s]).second) continue;
    warn("element " + std::to_string(b.id[s]) + " is " + formatNumber(size) +
         " across, under two lattice cells (h = " + formatNumber(h) +
         "): the fluid does not resolve it");
  }
  checkCoverage();
}

void Manager::stepElements(double dt) {
  for (int k = 0; k < substeps_; ++k) {
    try {
      assembly_.step(dt, gravity_);
    } catch (const Error& e) {
      const std::string where = substeps_ > 1
                                    ? " (substep " + std::to_string(k + 1) + " of " +
                                          std::to_string(substeps_) +
                                          "; elements stay at substep " + std::to_string(k) + ")"
                                    : "";
      throw Error(e.code(), e.what() + where, e.remedy());
    }
  }
}

void Manager::step() {
  const double dt = timestep();
  const double demDt = dt / substeps_;
  if (!assembly_.empty()) {
    if (!(dt > 0))
      throw Error("VALUE TIMESTEP", "no timestep: the elements are all held", Remedy::setTimestep);
    checkDemTimestep(dt, substeps_);
    checkDemAccuracy(demDt);
  }
  auto stamp = [&](const Error& e) {
    return Error(e.code(),
                 "step " + std::to_string(steps_ + 1) + " (t = " + formatNumber(time_ + dt) +
                     "): " + e.what(),
                 e.remedy());
  };
  // Attached afresh each step: the lattice and the elements may have been
  // replaced (a new lattice, a reset, a checkpoint) since the last.
  profile_.beginStep();
  attachParts();
  assembly_.attachProfile(&profile_);
  coupler_.attachProfile(&profile_);
  if (lattice_) {
    lattice_->attachProfile(&profile_);
    // Elements can refuse the step after the fluid has made it: the fluid
    // keeps its state before it to go back to. Alone it streams in place.
    lattice_->keepPrevious(!assembly_.empty());
    checkCollision();
    const bool couple = coupling::Coupler::needed(*lattice_, assembly_);
    bool fluidStepped = false;
    try {
      if (couple) {
        coupleBeforeFluid();
      } else if (coupled_) {
        lattice_->setCoveredCells({}, coupling_.equilibriumInterior);
        coupler_.clear(assembly_);
      }
      coupled_ = couple;
      fluidStepped = true;
      lattice_->step(machStopLimit());
    } catch (const Error& e) {
      const Error stamped = stamp(e);
      // In place, a step that finds the flow unstable has still been taken.
      if (fluidStepped && !lattice_->keepsPrevious()) {
        lattice_->advanceCircles(dt);
        time_ += dt;
        ++steps_;
      }
      throw stamped;
    }
    if (couple) coupler_.collect(*lattice_, assembly_, coupling_, gravity_);
    if (!machWarned_ && lattice_->lastStepMach() > machWarnLimit()) {
      machWarned_ = true;
      warn("Mach number " + formatNumber(lattice_->lastStepMach()) + " at step " +
           std::to_string(steps_ + 1) + " exceeds " + formatNumber(machWarnLimit()) +
           ": the flow is no longer nearly incompressible (reduce the timestep or the forcing)");
    }
    checkCellReynolds();
    checkOutrun();
  }
  try {
    stepElements(demDt);
  } catch (const Error& e) {
    if (lattice_) lattice_->undoStep();  // the fluid goes back with the elements
    throw stamp(e);
  }
  if (lattice_) lattice_->advanceCircles(dt);
  time_ += dt;
  ++steps_;
}

void Manager::reset() {
  lattice_.reset();
  coupler_ = coupling::Coupler();
  coupling_ = coupling::Settings();
  coupled_ = false;
  substeps_ = 1;
  solidMachWarned_ = false;
  underResolvedWarned_.clear();
  profile_.reset();
  assembly_ = dem::Assembly();
  attachParts();
  gravity_ = Vec2::Zero();
  fixedTimestep_.reset();
  time_ = 0.0;
  steps_ = 0;
  mlups_ = 0.0;
  machWarned_ = false;
  latticeBorn_ = -1000000000;
  pendingWarnings_.clear();
  warningLog_.clear();
}

void Manager::warn(const std::string& message, Remedy remedy) {
  pendingWarnings_.push_back({message, remedy});
  warningLog_.push_back({message, remedy});
}

bool Manager::warned(std::string_view marker) const {
  return std::any_of(warningLog_.begin(), warningLog_.end(),
                     [&](const Warning& w) { return w.text.find(marker) != std::string::npos; });
}

std::vector<Warning> Manager::takeWarnings() {
  std::vector<Warning> out;
  out.swap(pendingWarnings_);
  return out;
}

}  // namespace sf::sim
