#include "sandflow/sim/manager.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sandflow/core/error.hpp"

namespace sf::sim {

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
  watch_.forget(WarningCode::mach);
  watch_.checkCollision(*this);
}

void Manager::reconfigureLattice(const lb::LatticeDef& def) {
  lattice();  // there must be one
  configureStep(def, std::nullopt, std::nullopt);
}

void Manager::deleteLattice() {
  lattice();  // throws if none
  lattice_.reset();
  coupler_.clear(assembly_);
  coversCells_ = false;
}

void Manager::setCouplingSettings(const coupling::Settings& settings) {
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
  if (next) lattice_->reconfigure(*next, machStopLimit());
  if (dt)
    fixedTimestep_ = *dt;
  else if (fixedTimestep_ && next)
    fixedTimestep_ = next->dt;
  substeps_ = n;
  if (next) watch_.checkCollision(*this);
}

void Manager::setThreads(int threads) {
  if (threads < 1 || threads > kMaxThreads)
    throw Error("VALUE THREADS", "the thread count must be 1 to " + std::to_string(kMaxThreads) +
                                     ", got " + std::to_string(threads));
  *threads_ = threads;
  attachParts();
}

// Covers the lattice for this step: a solid surface faster than the Mach
// limit stops the step before anything changes; the watch sees the rest.
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
  watch_.checkCoverage(*this);
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
    watch_.checkDemAccuracy(*this, demDt);
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
    lattice_->setTime(time_);  // its sides ramp by the scene's clock
    // Elements can refuse the step after the fluid has made it: the fluid
    // keeps its state before it to go back to. Alone it streams in place.
    lattice_->keepPrevious(!assembly_.empty());
    watch_.checkCollision(*this);
    const bool couple = coupling::Coupler::needed(*lattice_, assembly_);
    bool fluidStepped = false;
    try {
      if (couple) {
        coupleBeforeFluid();
      } else if (coversCells_) {
        lattice_->setCoveredCells({}, coupling_.equilibriumInterior);
        coupler_.clear(assembly_);
      }
      coversCells_ = couple;
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
    watch_.checkFluid(*this, steps_ - latticeBorn_);
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
  coversCells_ = false;
  substeps_ = 1;
  profile_.reset();
  assembly_ = dem::Assembly();
  attachParts();
  gravity_ = Vec2::Zero();
  fixedTimestep_.reset();
  time_ = 0.0;
  steps_ = 0;
  latticeBorn_ = -1000000000;
  watch_.clear();
}

std::vector<Warning> Manager::takeWarnings() {
  return watch_.take();
}

}  // namespace sf::sim
