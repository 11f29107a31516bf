#include "sandflow/dem/assembly.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <omp.h>

#include "contact_force.hpp"
#include "element_sums.hpp"
#include "integrate.hpp"
#include "sandflow/core/error.hpp"

namespace sf::dem {
namespace {

using Clock = Profile::Clock;

}  // namespace

int Assembly::nextId() const {
  long long next = 0;  // the largest id + 1, which int cannot hold after 2147483647
  for (int id : bodies_.id) next = std::max(next, id + 1LL);
  if (next > std::numeric_limits<int>::max())
    throw Error("VALUE ID", "element id " + std::to_string(next - 1) +
                                " is in use and is the largest there is: give new elements an id");
  return int(next);
}

int Assembly::slot(int id) const {
  const int s = bodies_.slot(id);
  if (s < 0) throw Error("LOOKUP ELEMENT", "no element with id " + std::to_string(id));
  return s;
}

int Assembly::add(ElementDef def) {
  if (!def.shape) throw Error("VALUE SHAPE", "an element needs a shape");
  if (def.material < 0 || def.material >= materials_.size())
    throw Error("LOOKUP MATERIAL", "no such material");
  if (!def.x.allFinite() || !std::isfinite(def.angle) || !def.v.allFinite() ||
      !std::isfinite(def.w) || !def.force.allFinite() || !std::isfinite(def.torque) ||
      !def.acceleration.allFinite())
    throw Error("VALUE NUMBER", "element position, velocity and forces must be finite");
  if (def.shape->type() == ShapeType::disc) {  // a negative radius has an area too
    const double r = static_cast<const Disc&>(*def.shape).radius();
    if (!(r > 0))
      throw Error("VALUE RADIUS", "a disc's radius must be > 0, got " + formatNumber(r));
  }
  checkMass(*def.shape, materials_[def.material]);
  if (def.id < 0) def.id = nextId();
  if (bodies_.slot(def.id) >= 0)
    throw Error("EXISTS ELEMENT", "element id " + std::to_string(def.id) + " is in use");
  bodies_.push(def.id);
  const int s = bodies_.size() - 1;
  bodies_.shape[s] = std::move(def.shape);
  bodies_.material[s] = def.material;
  bodies_.x[s] = def.x;
  bodies_.angle[s] = def.angle;
  bodies_.v[s] = def.v;
  bodies_.w[s] = def.w;
  bodies_.hold[s] = def.hold;
  bodies_.appliedForce[s] = def.force;
  bodies_.appliedTorque[s] = def.torque;
  bodies_.acceleration[s] = def.acceleration;
  updateMass(s);
  touched();
  return def.id;
}

void Assembly::remove(int id) {
  bodies_.swapRemove(slot(id));
  contacts_.forget(id);
  sources_.forget(id);
  bonds_.forget(id);
  touched();
}

void Assembly::checkMass(const Shape& shape, const Material& material) {
  const double m = material.density * shape.area(), inertia = m * shape.inertiaPerMass();
  if (!(std::isfinite(m) && m > 0))
    throw Error("VALUE MASS", "an element's mass, density " + formatNumber(material.density) +
                                  " x area " + formatNumber(shape.area()) +
                                  ", must be finite and > 0, got " + formatNumber(m));
  if (!(std::isfinite(inertia) && inertia > 0))
    throw Error("VALUE MASS", "an element's moment of inertia must be finite and > 0, got " +
                                  formatNumber(inertia) + " (mass " + formatNumber(m) + ")");
}

void Assembly::updateMass(int s) {
  ++generation_;
  const Shape& shape = *bodies_.shape[s];
  const double m = materials_[bodies_.material[s]].density * shape.area();
  bodies_.mass[s] = m;
  bodies_.inertia[s] = m * shape.inertiaPerMass();
  const std::uint8_t h = bodies_.hold[s];
  // A held degree of freedom moves as prescribed: to its contacts it is infinitely heavy.
  bodies_.invMass[s] = (h & holdX) && (h & holdY) ? 0.0 : 1.0 / m;
  bodies_.invInertia[s] = (h & holdRotation) ? 0.0 : 1.0 / bodies_.inertia[s];
  bodies_.reach[s] = shape.boundingRadius();
  bodies_.extent[s] = shape.contactSize();
}

void Assembly::setPlateStress(int id, double stress) {
  const int s = slot(id);
  PlateServo::set(bodies_, s, stress);
  if (!std::isnan(stress)) updateMass(s);
}

double Assembly::criticalTimestep() const {
  if (criticalAt_ != generation_ || criticalMaterials_ != materials_.version())
    criticalAt_ = generation_, criticalMaterials_ = materials_.version(),
    critical_ = measureCriticalTimestep(), limits_ = measureTimestepLimits(critical_);
  return critical_;
}

double Assembly::measureCriticalTimestep() const {
  double mMin = std::numeric_limits<double>::infinity(), kMax = 0.0;
  for (int s = 0; s < bodies_.size(); ++s) {
    kMax = std::max(kMax, stiffestContact(s));
    // Sources count: their clones will be free.
    if (bodies_.invMass[s] > 0 || bodies_.ghost[s]) mMin = std::min(mMin, bodies_.mass[s]);
  }
  if (!std::isfinite(mMin) || kMax <= 0) return std::numeric_limits<double>::infinity();
  return 2.0 * std::sqrt(mMin / kMax);
}

void Assembly::clearFluidLoads() {
  for (int s = 0; s < bodies_.size(); ++s)
    bodies_.fluidForce[s] = Vec2::Zero(), bodies_.fluidTorque[s] = 0,
    bodies_.buoyancy[s] = Vec2::Zero();
}

double Assembly::kineticEnergy() const {
  double e = 0;
  for (int s = 0; s < bodies_.size(); ++s)
    e += 0.5 * bodies_.mass[s] * bodies_.v[s].squaredNorm() +
         0.5 * bodies_.inertia[s] * bodies_.w[s] * bodies_.w[s];
  return e;
}

Vec2 Assembly::momentum() const {
  Vec2 p = Vec2::Zero();
  for (int s = 0; s < bodies_.size(); ++s) p += bodies_.mass[s] * bodies_.v[s];
  return p;
}

// The elements' own loads: the reference step's first pass (the gather
// starts each element's sum with the same expression).
void Assembly::ownLoads(const Vec2& gravity) {
  Bodies& b = bodies_;
  Vec2* __restrict f = b.force.data();
  double* __restrict t = b.torque.data();
  const Vec2 *applied = b.appliedForce.data(), *own = b.acceleration.data(),
             *fluid = b.fluidForce.data(), *buoyancy = b.buoyancy.data();
  const double *mass = b.mass.data(), *appliedTorque = b.appliedTorque.data(),
               *fluidTorque = b.fluidTorque.data();
  for (int s = 0; s < b.size(); ++s) {
    f[s] = applied[s] + mass[s] * (gravity + own[s]) + fluid[s] + buoyancy[s];
    t[s] = appliedTorque[s] + fluidTorque[s];
  }
}

// Each element's own loads and then its contacts, one element at a time
// (element_sums.hpp), in blocks of slots over the threads; returns the probe
// (0 when every sum is finite).
double Assembly::gatherSums(const Vec2& gravity) {
  Bodies& b = bodies_;
  const int n = b.size();
  const ContactsByElement& by = contacts_.byElement(n);
  const ContactList& l = contacts_.list();
  const detail::SumInputs in{b.appliedForce.data(),
                             b.acceleration.data(),
                             b.fluidForce.data(),
                             b.buoyancy.data(),
                             b.mass.data(),
                             b.appliedTorque.data(),
                             b.fluidTorque.data(),
                             gravity,
                             by.start.data(),
                             by.entry.data(),
                             l.fx.data(),
                             l.fy.data(),
                             l.ta.data(),
                             l.tb.data(),
                             l.history[1 - l.current].touching.data(),
                             b.force.data(),
                             b.torque.data(),
                             scratchTouch_.data()};
  const int team = parallel::team(n, parallel::kIntegrateSlots, threads());
  if (team == 1) return detail::sumElements(in, 0, n);
  double probe = 0;
#pragma omp parallel num_threads(team) reduction(+ : probe)
  {
    const int count = omp_get_num_threads(), me = omp_get_thread_num();
    probe += detail::sumElements(in, int(std::int64_t(n) * me / count),
                                 int(std::int64_t(n) * (me + 1) / count));
  }
  return probe;
}

void Assembly::computeForces(double dt, const Vec2& gravity, bool useHalfVelocity) {
  Bodies& b = bodies_;
  const int n = b.size();
  const std::vector<Vec2>& vel = useHalfVelocity ? b.vHalf : b.v;
  const std::vector<double>& omega = useHalfVelocity ? b.wHalf : b.w;
  Profile& profile = profile_.get();
  auto t0 = Clock::now();
  if (referenceStep) ownLoads(gravity);
  t0 = profile.lap(Stage::demSums, t0);
  // Each contact's damping and normal-force mode for the step (law_columns.cpp).
  contacts_.prepareDamping(b, materials_, generation_, dt);
  const std::size_t bad = contacts_.evaluate(b, vel, omega, dt, maxOverlap_, threads());
  t0 = profile.lap(Stage::demContacts, t0);
  const ContactList& l = contacts_.list();
  if (bad < l.size())  // the history stays as it was (the step does not commit)
    throw Error("UNSTABLE OVERLAP",
                "elements " + std::to_string(l.idA[bad]) + " and " + std::to_string(l.idB[bad]) +
                    " overlap by " + formatNumber(l.overlap[bad]) + ", more than " +
                    formatNumber(maxOverlap_) +
                    " of the smaller one's size: reduce the timestep or stiffen the material");

  scratchTouch_.resize(std::size_t(n));  // for checkSpeeds
  double probe = 0;
  if (referenceStep) {
    std::fill(scratchTouch_.begin(), scratchTouch_.end(), 0);
    contacts_.sumOnto(b, scratchTouch_.data());
  } else {
    probe = gatherSums(gravity);
  }
  if (!bonds_.empty()) bonds_.addForces(b, time_, dt, vel, omega);
  if (referenceStep || !bonds_.empty()) {
    const Vec2* force = b.force.data();
    const double* torque = b.torque.data();
    // x - x is 0 for finite x and NaN otherwise: one branch-free pass, then
    // the slot is looked for only when some force is not finite.
    probe = 0;
    for (int s = 0; s < n; ++s)
      probe +=
          (force[s].x() - force[s].x()) + (force[s].y() - force[s].y()) + (torque[s] - torque[s]);
  }
  profile.lap(Stage::demSums, t0);
  if (probe != 0 || std::isnan(probe))
    for (int s = 0; s < n; ++s)
      if (!b.force[s].allFinite() || !std::isfinite(b.torque[s]))
        throw Error("UNSTABLE NAN",
                    "the force on element " + std::to_string(b.id[s]) + " is not finite");
}

// Energy blow-up shows as an element in contact about to jump by more than
// half its own size in one step (free flight may be that fast): stop before
// moving anything.
void Assembly::checkSpeeds(double dt, const char* only) const {
  const Bodies& b = bodies_;
  const char* touching = scratchTouch_.data();  // marked by computeForces
  const Vec2 *v = b.v.data(), *force = b.force.data();
  const double *w = b.w.data(), *torque = b.torque.data(), *mass = b.mass.data(),
               *inertia = b.inertia.data(), *reach = b.reach.data(), *extent = b.extent.data();
  for (int s = 0; s < b.size(); ++s) {
    if (only && !only[s]) continue;
    if (b.invMass[s] == 0 && b.invInertia[s] == 0) continue;
    if (!touching[s]) {
      // Free flight may be fast, but not beyond what a double holds (a
      // force of -1e308 on a light disc): refused before anything moves.
      // (as the integrators do: the acceleration first, which may overflow)
      const Vec2 a = force[s] / mass[s];
      const double alpha = torque[s] / inertia[s];
      Vec2 vFree = v[s] + dt * a;
      double wFree = w[s] + dt * alpha;
      if (b.hold[s] & holdX) vFree.x() = 0;
      if (b.hold[s] & holdY) vFree.y() = 0;
      if (b.hold[s] & holdRotation) wFree = 0;
      if (!vFree.allFinite() || !std::isfinite(wFree) || !(b.x[s] + dt * vFree).allFinite() ||
          !std::isfinite(b.angle[s] + dt * wFree))
        throw Error("UNSTABLE NAN", "element " + std::to_string(b.id[s]) +
                                        " would reach a position or velocity that is not finite "
                                        "(its force {" +
                                        formatNumber(force[s].x()) + " " +
                                        formatNumber(force[s].y()) + "} on mass " +
                                        formatNumber(mass[s]) + ")");
      continue;
    }
    const Vec2 vNext = v[s] + dt * force[s] / mass[s];
    const double wNext = std::abs(w[s] + dt * torque[s] / inertia[s]);
    const double size = extent[s];
    // |v| <= |vx| + |vy|: nearly every element passes without a square root.
    if ((std::abs(vNext.x()) + std::abs(vNext.y()) + wNext * reach[s]) * dt <= 0.5 * size) continue;
    const double jump = (vNext.norm() + wNext * reach[s]) * dt;
    if (jump > 0.5 * size || !std::isfinite(jump))
      throw Error("UNSTABLE SPEED",
                  "element " + std::to_string(b.id[s]) + " would move " + formatNumber(jump) +
                      " in one step, more than half its size " + formatNumber(size) +
                      ": the motion is blowing up (reduce the timestep)");
  }
}

detail::Motion Assembly::motion() {
  Bodies& b = bodies_;
  return {b.x.data(),     b.v.data(),       b.vHalf.data(),  b.angle.data(), b.w.data(),
          b.wHalf.data(), b.force.data(),   b.torque.data(), b.mass.data(),  b.inertia.data(),
          b.hold.data(),  b.started.data(), acc_.data(),     alpha_.data()};
}

// Verlet kicks before the forces with the last step's: an element without a
// previous step (new, or set by hand) kicks with the force at its present
// state. It is evaluated here, keeping the contact history (the step's own
// evaluation follows) and the others' forces.
void Assembly::startForces(double dt, const Vec2& gravity) {
  Bodies& b = bodies_;
  const std::vector<Vec2> f0 = b.force;
  const std::vector<double> torque0 = b.torque;
  contacts_.update(b, materials_, generation_, vectorPass);
  try {
    computeForces(dt, gravity, false);  // the history stays: nothing commits
  } catch (...) {
    b.force = f0, b.torque = torque0;
    throw;
  }
  for (int s = 0; s < b.size(); ++s)
    if (b.started[s])
      b.force[s] = f0[s], b.torque[s] = torque0[s];
    else
      b.started[s] = 1;
}

// Nothing can fail now: the contacts' new history and the bonds' breaks of
// this step stand.
void Assembly::commitStep() {
  contacts_.commit();
  bonds_.commit();
}

// The stages: pre-force integration, pair upkeep, forces (whose failure puts
// everything back), the checks, the commit, the plates' servo, post-force
// integration, the clock and the sources' clones.
void Assembly::setMaxOverlap(double share) {
  if (!(share > 0 && share <= kMaxOverlapLimit))
    throw Error("VALUE MAXOVERLAP",
                "the overlap limit must be > 0 and <= " + formatNumber(kMaxOverlapLimit) +
                    ", got " + formatNumber(share));
  maxOverlap_ = share;
}

void Assembly::step(double dt, const Vec2& gravity) {
  if (empty()) return;
  Profile& profile = profile_.get();
  if (profile_.owned()) profile.beginStep();
  auto t0 = Clock::now();
  Bodies& b = bodies_;
  const int n = b.size();
  bonds_.beginStep();
  // A scheme that moves before it checks (Verlet): the pose and half-step
  // velocities to go back to.
  const bool movesFirst = detail::kicksBeforeForces(integrator);
  std::vector<Vec2> x0, v0;
  std::vector<double> a0, w0;
  if (movesFirst) x0 = b.x, v0 = b.vHalf, a0 = b.angle, w0 = b.wHalf;
  if (movesFirst && anyUnstarted()) {
    t0 = profile.lap(Stage::demIntegrate, t0);
    startForces(dt, gravity);  // its forces record their stages
    t0 = Clock::now();
  }
  if (lastStep_ > 0 && dt != lastStep_) detail::changeStep(integrator, motion(), n, lastStep_, dt);
  lastStep_ = dt;
  detail::preForce(integrator, motion(), n, dt, threads());
  t0 = profile.lap(Stage::demIntegrate, t0);
  contacts_.update(b, materials_, generation_, vectorPass);
  profile.lap(Stage::demPairs, t0);
  spareForce_.resize(std::size_t(n)), spareTorque_.resize(std::size_t(n));
  b.force.swap(spareForce_), b.torque.swap(spareTorque_);
  acc_.resize(std::size_t(n)), alpha_.resize(std::size_t(n)), suspect_.resize(std::size_t(n));
  try {
    computeForces(dt, gravity, integrator != Integrator::euler);  // records its stages
    t0 = Clock::now();
    if (referenceStep) {
      checkSpeeds(dt, nullptr);
    } else {
      const detail::SpeedInputs in{b.reach.data(), b.extent.data(), scratchTouch_.data(),
                                   suspect_.data()};
      if (detail::accelerate(motion(), in, n, dt, threads())) checkSpeeds(dt, suspect_.data());
    }
  } catch (...) {
    b.force.swap(spareForce_), b.torque.swap(spareTorque_);
    if (movesFirst) b.x = x0, b.angle = a0, b.vHalf = v0, b.wHalf = w0;
    throw;
  }
  commitStep();
  plates_.servo(b, materials_, contacts_.list(), generation_, dt);
  if (referenceStep)
    detail::postForce(integrator, motion(), n, dt, threads());
  else
    detail::postForceFused(integrator, motion(), n, dt, threads());
  time_ += dt;
  if (!sources_.empty())
    sources_.spawn(b, time_, [this](ElementDef d) { return add(std::move(d)); });
  profile.lap(Stage::demIntegrate, t0);
}

}  // namespace sf::dem
