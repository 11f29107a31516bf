#include "sandflow/dem/assembly.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_map>

#include <omp.h>

#include "contact_force.hpp"
#include "disc_contacts.hpp"
#include "integrate.hpp"
#include "sandflow/core/error.hpp"

namespace sf::dem {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::uint64_t pairKey(int a, int b) {
  return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

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
  slotsMoved_ = true;
  std::erase_if(sources_, [&](const Source& x) { return x.id == id; });
  std::erase_if(bonds_, [&](const Bond& x) { return x.idA == id || x.idB == id; });
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
  if (bodies_.shape[s]->type() != ShapeType::wall)
    throw Error("VALUE STRESS", "-stress applies to walls only");
  if (std::isinf(stress)) throw Error("VALUE STRESS", "-stress must be finite");
  bodies_.stress[s] = stress;
  if (!std::isnan(stress)) bodies_.hold[s] = holdX | holdY | holdRotation, updateMass(s);
}

// Servo: move each plate along its normal at a speed proportional to the
// missing load, with a gain that would close 2% of the gap per step against
// the stiffness of the contacts it has, and never faster than 1e-3 of the
// smallest element per step (an unloaded plate would otherwise slam into the
// specimen). A faster servo fights the contact dashpots: the plate's own speed
// comes back as damping force and the loop rings.
void Assembly::servoPlates(double dt) {
  if (platesAt_ != generation_) {
    plates_.clear();
    for (int s = 0; s < bodies_.size(); ++s)
      if (!std::isnan(bodies_.stress[s])) plates_.push_back(s);
    platesAt_ = generation_;
  }
  for (int s : plates_) {
    if (std::isnan(bodies_.stress[s])) continue;  // servo removed since
    const auto& wall = static_cast<const Wall&>(*bodies_.shape[s]);
    const Vec2 inward(-std::sin(bodies_.angle[s]), std::cos(bodies_.angle[s]));
    double load = 0, stiffness = 0;
    for (const Contact& c : contacts_) {
      if (!c.touching || (c.a != s && c.b != s)) continue;
      const Vec2 onWall = c.a == s ? Vec2(-c.force) : c.force;
      load -= onWall.dot(inward);  // the grains push the plate back
      const int other = c.a == s ? c.b : c.a;
      stiffness += combine(materials_[bodies_.material[s]], materials_[bodies_.material[other]]).kn;
    }
    const double target = bodies_.stress[s] * wall.length();
    const double k = std::max(stiffness, materials_[bodies_.material[s]].kn);
    double smallest = std::numeric_limits<double>::infinity();
    for (int o = 0; o < bodies_.size(); ++o)
      if (o != s) smallest = std::min(smallest, bodies_.extent[o]);
    const double limit = std::isfinite(smallest) ? 1e-3 * smallest / dt : 0.0;
    const double speed = std::clamp(0.02 * (target - load) / (k * dt), -limit, limit);
    bodies_.v[s] = speed * inward;
    bodies_.vHalf[s] = bodies_.v[s];
    bodies_.w[s] = bodies_.wHalf[s] = 0;
  }
}

double Assembly::curvatureRadius(int s) const {
  const Shape& shape = *bodies_.shape[s];
  return shape.type() == ShapeType::wall ? std::numeric_limits<double>::infinity()
                                         : shape.contactSize();
}

double Assembly::effectiveRadius(int a, int b) const {
  const double ra = curvatureRadius(a), rb = curvatureRadius(b);
  if (!std::isfinite(ra)) return rb;
  if (!std::isfinite(rb)) return ra;
  return ra * rb / (ra + rb);
}

double Assembly::criticalTimestep() const {
  if (criticalAt_ != generation_ || criticalMaterials_ != materials_.version())
    criticalAt_ = generation_, criticalMaterials_ = materials_.version(),
    critical_ = measureCriticalTimestep();
  return critical_;
}

double Assembly::measureCriticalTimestep() const {
  double mMin = std::numeric_limits<double>::infinity(), kMax = 0.0;
  for (int s = 0; s < bodies_.size(); ++s) {
    const Material& m = materials_[bodies_.material[s]];
    // Hertz: the stiffness at an overlap of 1% of the element's size.
    const double r = curvatureRadius(s);
    kMax = std::max(kMax, m.law == ContactLaw::hertz && std::isfinite(r)
                              ? 8.0 * m.youngs / (2 * (1 + m.poisson)) * std::sqrt(r * 0.01 * r)
                              : std::max(m.kn, m.ks));
    // Sources count: their clones will be free.
    if (bodies_.invMass[s] > 0 || bodies_.ghost[s]) mMin = std::min(mMin, bodies_.mass[s]);
  }
  if (!std::isfinite(mMin) || kMax <= 0) return std::numeric_limits<double>::infinity();
  return 2.0 * std::sqrt(mMin / kMax);
}

std::size_t Assembly::touchingCount() const {
  return std::count_if(contacts_.begin(), contacts_.end(),
                       [](const Contact& c) { return c.touching; });
}

Vec2 Assembly::contactForce(int s) const {
  Vec2 f = Vec2::Zero();
  for (const Contact& c : contacts_)
    if (c.touching) f += c.a == s ? Vec2(-c.force) : c.b == s ? c.force : Vec2::Zero();
  return f;
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

// Candidate pairs from boxes grown by a skin; rebuilt only once some element
// has moved (or turned) by half the skin since the last build.
void Assembly::updatePairs() {
  const int n = bodies_.size();
  bool rebuild = !pairsValid_ || int(builtAt_.size()) != n;
  if (!rebuild) {
    const Vec2 *x = bodies_.x.data(), *x0 = builtAt_.data();
    const double *angle = bodies_.angle.data(), *angle0 = builtAngle_.data(),
                 *reach = bodies_.reach.data();
    const double half = 0.5 * skin_;
    for (int s = 0; s < n && !rebuild; ++s) {
      const Vec2 d = x[s] - x0[s];
      const double turn = reach[s] * std::abs(angle[s] - angle0[s]);
      // |d| <= |dx| + |dy|: the square root only near the threshold.
      if (std::abs(d.x()) + std::abs(d.y()) + turn <= half) continue;
      rebuild = d.norm() + turn > half;
    }
  }
  if (!rebuild) return;

  double smallest = std::numeric_limits<double>::infinity();
  for (int s = 0; s < n; ++s) smallest = std::min(smallest, bodies_.extent[s]);
  skin_ = std::isfinite(smallest) ? 0.2 * smallest : 0.0;
  std::vector<Box> boxes(n);
  for (int s = 0; s < n; ++s) {
    Box b = bodies_.shape[s]->bounds(bodies_.x[s], bodies_.angle[s]);
    boxes[s] = {b.lo - Vec2(skin_, skin_), b.hi + Vec2(skin_, skin_)};
  }
  std::vector<std::pair<int, int>> pairs;
  dess_.findPairs(boxes, pairs);

  // Contact history carries over by element ids. Both lists are sorted by slot
  // pair, so while no slot has moved a merge does it; after a deletion, a map.
  std::unordered_map<std::uint64_t, std::pair<Vec2, Vec2>> history;  // shear, normal
  if (slotsMoved_)
    for (const Contact& c : contacts_)
      if (c.touching) history[pairKey(c.idA, c.idB)] = {c.shear, c.normal};
  std::size_t old = 0;
  std::vector<Contact> next;
  next.reserve(pairs.size());
  for (const auto& [a, b] : pairs) {
    if (!canCollide(bodies_.shape[a]->type(), bodies_.shape[b]->type())) continue;
    if (bodies_.ghost[a] || bodies_.ghost[b]) continue;
    const bool immovable = bodies_.invMass[a] == 0 && bodies_.invInertia[a] == 0 &&
                           bodies_.invMass[b] == 0 && bodies_.invInertia[b] == 0;
    if (immovable) continue;
    Contact c{a, b};
    c.idA = bodies_.id[a], c.idB = bodies_.id[b];
    c.discs =
        bodies_.shape[a]->type() == ShapeType::disc && bodies_.shape[b]->type() == ShapeType::disc;
    if (slotsMoved_) {
      if (auto it = history.find(pairKey(c.idA, c.idB)); it != history.end())
        c.shear = it->second.first, c.normal = it->second.second, c.touching = true;
    } else {
      while (old < contacts_.size() &&
             std::pair(contacts_[old].a, contacts_[old].b) < std::pair(a, b))
        ++old;
      if (old < contacts_.size() && contacts_[old].a == a && contacts_[old].b == b &&
          contacts_[old].touching)
        c.shear = contacts_[old].shear, c.normal = contacts_[old].normal, c.touching = true;
    }
    next.push_back(c);
  }
  contacts_.swap(next);
  refreshLaws(true);
  slotsMoved_ = false;
  builtAt_ = bodies_.x;
  builtAngle_ = bodies_.angle;
  pairsValid_ = true;
  ++builds_;
}

void Assembly::prepareContact(Contact& c) const {
  const Bodies& b = bodies_;
  const int i = c.a, j = c.b, nm = materials_.size();
  c.law = b.material[i] * nm + b.material[j];
  const PairLaw& law = laws_[c.law];
  // The damping coefficient depends on the masses and materials only: 2 zeta
  // sqrt(m_eff kn) for the linear law, 2 zeta sqrt(m_eff) for Hertz, whose kn
  // changes with the overlap.
  const double meff = 1.0 / (b.invMass[i] + b.invMass[j]);
  c.damping = law.damping >= 0 ? law.damping
                               : 2.0 * law.zeta * std::sqrt(meff * (law.hertz ? 1.0 : law.kn));
  c.size = std::min(b.extent[i], b.extent[j]);
  c.radius = effectiveRadius(i, j);
  c.vectorDiscs = c.discs && !law.hertz;
}

void Assembly::refreshLaws(bool newContacts) {
  const int nm = materials_.size();
  const bool materialsChanged =
      dampingMaterials_ != materials_.version() || int(laws_.size()) != nm * nm;
  if (!newContacts && !materialsChanged && dampingAt_ == generation_) return;
  if (materialsChanged) {
    laws_.resize(nm * nm);
    for (int i = 0; i < nm; ++i)
      for (int j = 0; j < nm; ++j) laws_[i * nm + j] = combine(materials_[i], materials_[j]);
  }
  for (Contact& c : contacts_) prepareContact(c);
  dampingAt_ = generation_, dampingMaterials_ = materials_.version();
}

void Assembly::computeForces(double dt, const Vec2& gravity, bool useHalfVelocity) {
  Bodies& b = bodies_;
  const int n = b.size();
  const std::vector<Vec2>& vel = useHalfVelocity ? b.vHalf : b.v;
  const std::vector<double>& omega = useHalfVelocity ? b.wHalf : b.w;
  {
    Vec2* __restrict f = b.force.data();
    double* __restrict t = b.torque.data();
    const Vec2 *applied = b.appliedForce.data(), *own = b.acceleration.data(),
               *fluid = b.fluidForce.data(), *buoyancy = b.buoyancy.data();
    const double *mass = b.mass.data(), *appliedTorque = b.appliedTorque.data(),
                 *fluidTorque = b.fluidTorque.data();
    for (int s = 0; s < n; ++s) {
      f[s] = applied[s] + mass[s] * (gravity + own[s]) + fluid[s] + buoyancy[s];
      t[s] = appliedTorque[s] + fluidTorque[s];
    }
  }
  refreshLaws();
  const detail::ContactInputs in{b.x.data(),   b.angle.data(), b.reach.data(), vel.data(),
                                 omega.data(), b.shape.data(), laws_.data(),   dt};
  const std::ptrdiff_t nc = std::ptrdiff_t(contacts_.size());
  Contact* contacts = contacts_.data();
  Vec2* __restrict before = (scratchShear_.resize(nc), scratchShear_.data());
  std::vector<char>& touchingFlags = scratchTouch_;  // for checkSpeeds
  touchingFlags.assign(n, 0);
  char* touching = touchingFlags.data();
  // The first contact (in list order, whatever the threads) that stops the step.
  std::ptrdiff_t bad = nc;
  const double limit = maxOverlap;
  // Each element sums its contacts in list order on one thread or several, so
  // the forces are the same bits for any thread count.
  Vec2* __restrict force = b.force.data();
  double* __restrict torque = b.torque.data();
  const Vec2* x = b.x.data();
  // Takes the force and point as values: read back from the contact just
  // written, they would wait for the stores (two 8-byte stores do not forward
  // to a 16-byte load).
  auto add = [=](int a, int b, const Vec2& f, const Vec2& point) {
    touching[a] = touching[b] = 1;
    force[a] -= f;
    force[b] += f;
    torque[a] -= cross(point - x[a], f);
    torque[b] += cross(point - x[b], f);
  };
  // Three passes. First, which candidates may touch: disc pairs are tested,
  // other shapes listed; the disc pairs with a linear law are staged in
  // columns for the vector pass.
  scratchLive_.resize(2 * nc);
  std::ptrdiff_t* __restrict live = scratchLive_.data();
  std::ptrdiff_t* __restrict others = live + nc;
  scratchPairIndex_.resize(2 * nc);
  scratchPairData_.resize(9 * nc);
  double* pd = scratchPairData_.data();
  const detail::DiscPairs pairs{scratchPairIndex_.data(),
                                scratchPairIndex_.data() + nc,
                                pd,
                                pd + nc,
                                pd + 2 * nc,
                                pd + 3 * nc,
                                pd + 4 * nc,
                                pd + 5 * nc,
                                pd + 6 * nc,
                                pd + 7 * nc,
                                pd + 8 * nc};
  std::ptrdiff_t count = 0, vectorCount = 0, otherCount = 0;
  for (std::ptrdiff_t k = 0; k < nc; ++k) {
    Contact& c = contacts[k];
    before[k] = c.shear;
    const bool hit = detail::mayTouch(c, in);
    // Written every time, kept by counting: whether a pair touches is not
    // predictable, and a branch would be mispredicted often.
    live[count] = others[otherCount] = k;
    detail::stage(c, laws_.data(), pairs, vectorCount);
    count += hit;
    otherCount += hit & !c.vectorDiscs;
    vectorCount += hit & c.vectorDiscs;
  }
  // Second, the forces: the linear disc pairs many at a time, the others one by one.
  scratchResults_.resize(9 * std::size_t(vectorCount));
  double* r = scratchResults_.data();
  const std::ptrdiff_t vc = vectorCount;
  const detail::DiscResults out{r,          r + vc,     r + 2 * vc, r + 3 * vc, r + 4 * vc,
                                r + 5 * vc, r + 6 * vc, r + 7 * vc, r + 8 * vc};
  // Few contacts stay on one thread: a parallel region would cost more.
  const int team = count >= 512 ? std::max(threads, 1) : 1;
  if (team == 1) {
    detail::linearDiscContacts(pairs, 0, vc, in, out);
    for (std::ptrdiff_t q = 0; q < otherCount; ++q)
      detail::evaluateContact(contacts[others[q]], in);
  } else {
#pragma omp parallel num_threads(team)
    {
      const int size = omp_get_num_threads(), me = omp_get_thread_num();
      detail::linearDiscContacts(pairs, vc * me / size, vc * (me + 1) / size, in, out);
#pragma omp for schedule(dynamic, 64)
      for (std::ptrdiff_t q = 0; q < otherCount; ++q)
        detail::evaluateContact(contacts[others[q]], in);
    }
  }
  // Third, in list order: the results stored, the checks, the sums.
  for (std::ptrdiff_t i = 0, q = 0; i < count; ++i) {
    const std::ptrdiff_t k = live[i];
    Contact& c = contacts[k];
    if (c.vectorDiscs) {
      const Vec2 f(out.fx[q], out.fy[q]), point(out.px[q], out.py[q]);
      c.touching = true;
      c.normal = Vec2(out.nx[q], out.ny[q]);
      c.point = point;
      c.overlap = out.overlap[q];
      c.force = f;
      c.shear = Vec2(out.sx[q], out.sy[q]);
      if (bad == nc && (c.overlap > limit * c.size || !f.allFinite())) bad = k;
      add(c.a, c.b, f, point);
      ++q;
    } else if (c.touching) {
      if (bad == nc && detail::excessive(c, limit)) bad = k;
      add(c.a, c.b, c.force, c.point);
    }
  }
  if (bad < nc) {
    // The step stops: the shear springs stay as they were.
    for (std::ptrdiff_t k = 0; k < nc; ++k) contacts[k].shear = before[k];
    const Contact& c = contacts[bad];
    throw Error("UNSTABLE OVERLAP",
                "elements " + std::to_string(c.idA) + " and " + std::to_string(c.idB) +
                    " overlap by " + formatNumber(c.overlap) + ", more than " +
                    formatNumber(maxOverlap) +
                    " of the smaller one's size: reduce the timestep or stiffen the material");
  }
  if (!bonds_.empty()) bondForces(dt, vel, omega);
  // x - x is 0 for finite x and NaN otherwise: one branch-free pass, then the
  // slot is looked for only when some force is not finite.
  double probe = 0;
  for (int s = 0; s < n; ++s)
    probe +=
        (force[s].x() - force[s].x()) + (force[s].y() - force[s].y()) + (torque[s] - torque[s]);
  if (probe != 0 || std::isnan(probe))
    for (int s = 0; s < n; ++s)
      if (!b.force[s].allFinite() || !std::isfinite(b.torque[s]))
        throw Error("UNSTABLE NAN",
                    "the force on element " + std::to_string(b.id[s]) + " is not finite");
}

// Energy blow-up shows as an element in contact about to jump by more than
// half its own size in one step (free flight may be that fast): stop before
// moving anything.
void Assembly::checkSpeeds(double dt) const {
  const Bodies& b = bodies_;
  const char* touching = scratchTouch_.data();  // marked by computeForces
  const Vec2 *v = b.v.data(), *force = b.force.data();
  const double *w = b.w.data(), *torque = b.torque.data(), *mass = b.mass.data(),
               *inertia = b.inertia.data(), *reach = b.reach.data(), *extent = b.extent.data();
  for (int s = 0; s < b.size(); ++s) {
    if (!touching[s] || (b.invMass[s] == 0 && b.invInertia[s] == 0)) continue;
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

void Assembly::integrate(double dt) {
  Bodies& b = bodies_;
  const detail::Motion m{b.x.data(),    b.v.data(),       b.vHalf.data(), b.angle.data(),
                         b.w.data(),    b.wHalf.data(),   b.force.data(), b.torque.data(),
                         b.mass.data(), b.inertia.data(), b.hold.data()};
  if (integrator == Integrator::central && anyUnstarted())
    detail::startCentral(m, b.started.data(), b.size(), dt);
  detail::advance(integrator, m, b.size(), dt, threads);
}

void Assembly::step(double dt, const Vec2& gravity) {
  if (empty()) return;
  auto t0 = Clock::now();
  Bodies& b = bodies_;
  const int n = b.size();
  bondsPending_ = false;
  std::vector<Vec2> x0;  // verlet moves before it checks: the pose to go back to
  std::vector<double> a0;
  if (integrator == Integrator::verlet) {
    // Kick-drift with the forces of the previous step, then forces, then kick.
    x0 = b.x;
    a0 = b.angle;
    if (anyUnstarted()) {
      // An element without a previous step (new, or set by hand) kicks with the
      // force at its present state: evaluate it, keeping the contact history
      // (the step's own evaluation follows) and the others' forces.
      const std::vector<Vec2> f0 = b.force;
      const std::vector<double> torque0 = b.torque;
      updatePairs();
      const std::vector<Contact> history = contacts_;
      try {
        computeForces(dt, gravity, false);
      } catch (...) {
        b.force = f0, b.torque = torque0, contacts_ = history;
        throw;
      }
      contacts_ = history;
      for (int s = 0; s < n; ++s)
        if (b.started[s])
          b.force[s] = f0[s], b.torque[s] = torque0[s];
        else
          b.started[s] = 1;
    }
    for (int s = 0; s < n; ++s) {
      Vec2 a = b.force[s] / b.mass[s];
      double alpha = b.torque[s] / b.inertia[s];
      if (b.hold[s] & holdX) a.x() = 0;
      if (b.hold[s] & holdY) a.y() = 0;
      if (b.hold[s] & holdRotation) alpha = 0;
      b.vHalf[s] = b.v[s] + 0.5 * dt * a;
      b.wHalf[s] = b.w[s] + 0.5 * dt * alpha;
      b.x[s] += dt * b.vHalf[s];
      b.angle[s] += dt * b.wHalf[s];
    }
    updatePairs();
    times_.sort += since(t0);
    t0 = Clock::now();
    try {
      computeForces(dt, gravity, true);
    } catch (...) {
      b.x = x0;
      b.angle = a0;
      throw;
    }
  } else {
    updatePairs();
    times_.sort += since(t0);
    t0 = Clock::now();
    // Velocity-dependent forces (damping) use the last half-step velocity: the
    // extrapolated v(t) = v(t - dt/2) + a(t - dt) dt/2 feeds back the previous
    // acceleration and sustains limit cycles of the contact-rotation modes at
    // dt_crit/10 (a settling bed never came to rest).
    if (anyUnstarted())
      for (int s = 0; s < n; ++s)
        if (!b.started[s]) b.vHalf[s] = b.v[s], b.wHalf[s] = b.w[s];
    computeForces(dt, gravity, integrator == Integrator::central);
  }
  times_.narrow += since(t0);
  t0 = Clock::now();
  try {
    checkSpeeds(dt);
  } catch (...) {
    if (integrator == Integrator::verlet) b.x = x0, b.angle = a0;
    throw;
  }
  // Nothing can fail now: the bonds' breaks of this step stand.
  if (bondsPending_) {
    bonds_.swap(pendingBonds_);
    breaks_.insert(breaks_.end(), pendingBreaks_.begin(), pendingBreaks_.end());
    bondsPending_ = false;
  }
  servoPlates(dt);
  integrate(dt);
  time_ += dt;
  if (!sources_.empty()) spawnClones();
  times_.integrate += since(t0);
}

}  // namespace sf::dem
