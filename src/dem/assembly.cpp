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

// The same key for (a, b) and (b, a).
std::uint64_t pairKey(int a, int b) {
  if (a > b) std::swap(a, b);
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
  slotsMoved_ = true;
  // Its contacts end here: an element given its id later starts afresh (the
  // next pair search carries history over by ids).
  ContactList& l = list_;
  std::int32_t* touching = l.history[l.current].touching.data();
  for (std::size_t k = 0; k < l.size(); ++k)
    if (l.idA[k] == id || l.idB[k] == id) touching[k] = 0;
  viewValid_ = false;
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
    throw Error("VALUE STRESS", "a servo stress applies to walls only");
  if (std::isinf(stress)) throw Error("VALUE STRESS", "a servo stress must be finite");
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
    const ContactList& l = list_;
    for (std::size_t k = 0; k < l.size(); ++k) {
      if (!l.touching(k) || (l.a[k] != s && l.b[k] != s)) continue;
      const Vec2 force(l.fx[k], l.fy[k]);
      const Vec2 onWall = l.a[k] == s ? Vec2(-force) : force;
      load -= onWall.dot(inward);  // the grains push the plate back
      const int other = l.a[k] == s ? l.b[k] : l.a[k];
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

std::size_t Assembly::touchingCount() const {
  const auto& t = list_.now().touching;
  return std::size_t(std::count(t.begin(), t.end(), std::int32_t(1)));
}

Vec2 Assembly::contactForce(int s) const {
  const ContactList& l = list_;
  Vec2 f = Vec2::Zero();
  for (std::size_t k = 0; k < l.size(); ++k)
    if (l.touching(k))
      f += l.a[k] == s   ? Vec2(-l.fx[k], -l.fy[k])
           : l.b[k] == s ? Vec2(l.fx[k], l.fy[k])
                         : Vec2::Zero();
  return f;
}

const std::vector<Contact>& Assembly::contacts() const {
  if (viewValid_) return view_;
  const ContactList& l = list_;
  const ContactHistory& h = l.now();
  view_.resize(l.size());
  for (std::size_t k = 0; k < l.size(); ++k) {
    Contact& c = view_[k];
    c.a = l.a[k], c.b = l.b[k], c.idA = l.idA[k], c.idB = l.idB[k];
    c.touching = h.touching[k] != 0;
    c.discs = l.discs[k] != 0;
    c.dampingPart = l.dampingPart[k];
    c.normal = Vec2(h.nx[k], h.ny[k]);
    c.shear = c.touching ? Vec2(h.sx[k], h.sy[k]) : Vec2::Zero();
    c.point = Vec2(l.px[k], l.py[k]);
    c.overlap = l.overlap[k];
    c.force = c.touching ? Vec2(l.fx[k], l.fy[k]) : Vec2::Zero();
  }
  viewValid_ = true;
  return view_;
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
  bool rebuild = !pairsValid_ || int(builtAt_.size()) != n || lawsStale();
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
  // The build's buffers are kept: a fresh list would fault in its pages.
  std::vector<Box>& boxes = build_.boxes;
  boxes.resize(n);
  for (int s = 0; s < n; ++s) {
    Box b = bodies_.shape[s]->bounds(bodies_.x[s], bodies_.angle[s]);
    boxes[s] = {b.lo - Vec2(skin_, skin_), b.hi + Vec2(skin_, skin_)};
  }
  std::vector<std::pair<int, int>>& pairs = build_.pairs;
  dess_.findPairs(boxes, pairs);

  if (lawsStale()) buildLaws();
  // The new list: linear disc pairs first, then the others, each run in slot
  // pair order (as the broad phase returns them).
  std::vector<PairBuild::Kept>* kept = build_.kept;
  kept[0].clear(), kept[1].clear();
  // Contact history carries over by element ids. Each run of the old list is
  // in slot-pair order, so while no slot has moved a merge does it (one
  // cursor per run); after a deletion, a map. There the last slot moved into
  // the deleted one, so a pair may come back with its ends swapped: its
  // history is then turned round.
  const ContactList& old = list_;
  const ContactHistory& oldHistory = old.now();
  std::unordered_map<std::uint64_t, std::size_t> byIds;
  if (slotsMoved_)
    for (std::size_t k = 0; k < old.size(); ++k)
      if (oldHistory.touching[k]) byIds[pairKey(old.idA[k], old.idB[k])] = k;
  std::size_t cursor[2] = {0, old.vectorCount};
  const std::size_t runEnd[2] = {old.vectorCount, old.size()};
  const int nm = materials_.size();
  for (const auto& [a, b] : pairs) {
    if (!canCollide(bodies_.shape[a]->type(), bodies_.shape[b]->type())) continue;
    if (bodies_.ghost[a] || bodies_.ghost[b]) continue;
    const bool immovable = bodies_.invMass[a] == 0 && bodies_.invInertia[a] == 0 &&
                           bodies_.invMass[b] == 0 && bodies_.invInertia[b] == 0;
    if (immovable) continue;
    std::ptrdiff_t from = -1;
    bool swapped = false;
    if (slotsMoved_) {
      if (auto it = byIds.find(pairKey(bodies_.id[a], bodies_.id[b])); it != byIds.end())
        from = std::ptrdiff_t(it->second), swapped = old.idA[it->second] != bodies_.id[a];
    } else {
      for (int run = 0; run < 2; ++run) {
        std::size_t& k = cursor[run];
        while (k < runEnd[run] && std::pair(old.a[k], old.b[k]) < std::pair(a, b)) ++k;
        if (k < runEnd[run] && old.a[k] == a && old.b[k] == b && oldHistory.touching[k])
          from = std::ptrdiff_t(k);
      }
    }
    const bool discs =
        bodies_.shape[a]->type() == ShapeType::disc && bodies_.shape[b]->type() == ShapeType::disc;
    // Boxes grown by the skin also pair discs that sit diagonally apart. Each
    // disc moves at most half the skin before the next build, so two that are
    // farther than their radii plus the skin cannot touch until then (the
    // margin covers the rounding of the distances).
    if (discs) {
      const double gap = bodies_.reach[a] + bodies_.reach[b] + skin_;
      if ((bodies_.x[a] - bodies_.x[b]).squaredNorm() > gap * gap * (1 + 1e-12)) continue;
    }
    const bool linear = !laws_[bodies_.material[a] * nm + bodies_.material[b]].hertz;
    kept[discs && linear && vectorPass ? 0 : 1].push_back({a, b, discs, swapped, from});
  }
  // The new list goes into the spare one; every column of every contact is
  // written (a reused list holds the contacts of an older build).
  ContactList& next = build_.spare;
  next.resize(kept[0].size() + kept[1].size());
  next.vectorCount = kept[0].size();
  next.current = 0;
  ContactHistory& h = next.history[0];
  std::size_t k = 0;
  for (int run = 0; run < 2; ++run)
    for (const PairBuild::Kept& e : kept[run]) {
      next.a[k] = e.a, next.b[k] = e.b;
      next.idA[k] = bodies_.id[e.a], next.idB[k] = bodies_.id[e.b];
      next.discs[k] = e.discs;
      prepareContact(next, k);
      h.touching[k] = e.old >= 0;
      if (e.old >= 0) {
        // Normal (a to b), shear spring and force (on b): the other way
        // round for a pair whose ends swapped.
        const std::size_t o = std::size_t(e.old);
        const double sign = e.swapped ? -1.0 : 1.0;
        h.nx[k] = sign * oldHistory.nx[o], h.ny[k] = sign * oldHistory.ny[o];
        h.sx[k] = sign * oldHistory.sx[o], h.sy[k] = sign * oldHistory.sy[o];
        next.fx[k] = sign * old.fx[o], next.fy[k] = sign * old.fy[o];
        next.px[k] = old.px[o], next.py[k] = old.py[o], next.overlap[k] = old.overlap[o];
      } else {
        h.nx[k] = h.ny[k] = h.sx[k] = h.sy[k] = 0.0;
        next.fx[k] = next.fy[k] = next.px[k] = next.py[k] = next.overlap[k] = 0.0;
      }
      next.ta[k] = next.tb[k] = 0.0;
      ++k;
    }
  std::swap(list_, next);
  viewValid_ = false;
  lawsAt_ = generation_;
  slotsMoved_ = false;
  builtAt_ = bodies_.x;
  builtAngle_ = bodies_.angle;
  pairsValid_ = true;
  ++builds_;
}

void Assembly::prepareContact(ContactList& l, std::size_t k) const {
  const Bodies& b = bodies_;
  const int i = l.a[k], j = l.b[k], nm = materials_.size();
  l.law[k] = b.material[i] * nm + b.material[j];
  const PairLaw& law = laws_[l.law[k]];
  // The damping coefficient depends on the masses and materials only: 2 zeta
  // sqrt(m_eff kn) for the linear law, 2 zeta sqrt(m_eff) for Hertz, whose kn
  // changes with the overlap.
  const double meff = 1.0 / (b.invMass[i] + b.invMass[j]);
  l.dampingPart[k] = law.damping >= 0
                         ? law.damping
                         : 2.0 * law.zeta * std::sqrt(meff * (law.hertz ? 1.0 : law.kn));
  l.minSize[k] = std::min(b.extent[i], b.extent[j]);
  l.radius[k] = effectiveRadius(i, j);
}

bool Assembly::lawsStale() const {
  const int nm = materials_.size();
  return lawsMaterials_ != materials_.version() || int(laws_.size()) != nm * nm ||
         lawsAt_ != generation_;
}

void Assembly::buildLaws() {
  const int nm = materials_.size();
  laws_.resize(nm * nm);
  lawKn_.resize(nm * nm), lawKs_.resize(nm * nm), lawFriction_.resize(nm * nm);
  for (int i = 0; i < nm; ++i)
    for (int j = 0; j < nm; ++j) {
      const PairLaw law = combine(materials_[i], materials_[j]);
      laws_[i * nm + j] = law;
      lawKn_[i * nm + j] = law.kn, lawKs_[i * nm + j] = law.ks;
      lawFriction_[i * nm + j] = law.friction;
    }
  lawsMaterials_ = materials_.version();
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
  const detail::ContactInputs in{b.x.data(),   b.angle.data(), b.reach.data(), vel.data(),
                                 omega.data(), b.shape.data(), laws_.data(),   dt,
                                 maxOverlap};
  prepareDamping(dt);  // each contact's damping and normal-force mode (law_columns.cpp)
  const detail::LawColumns lawColumns{lawKn_.data(), lawKs_.data(), lawFriction_.data()};
  ContactList& l = list_;
  const std::size_t nc = l.size(), nv = l.vectorCount;
  auto t0 = Clock::now();
  // The next history and the results of every contact: the linear disc pairs
  // many at a time, the others one by one. Few contacts stay on one thread: a
  // parallel region would cost more.
  const int team = nc >= 512 ? std::max(threads, 1) : 1;
  std::size_t bad = nc;  // the first contact that stops the step
  if (team == 1) {
    const std::size_t first = detail::linearDiscContacts(l, 0, nv, in, lawColumns);
    const std::size_t other = detail::evaluateOthers(l, nv, nc, in);
    bad = first < nv ? first : other;  // the vector pairs come first in the list
  } else {
#pragma omp parallel num_threads(team) reduction(min : bad)
    {
      const std::size_t size = std::size_t(omp_get_num_threads()),
                        me = std::size_t(omp_get_thread_num());
      const std::size_t begin = nv * me / size, end = nv * (me + 1) / size;
      const std::size_t first = detail::linearDiscContacts(l, begin, end, in, lawColumns);
      if (first < end) bad = std::min(bad, first);
      const std::ptrdiff_t chunks = std::ptrdiff_t((nc - nv + 63) / 64);
#pragma omp for schedule(dynamic)
      for (std::ptrdiff_t q = 0; q < chunks; ++q) {
        const std::size_t from = nv + 64 * std::size_t(q), to = std::min(nc, from + 64);
        const std::size_t stop = detail::evaluateOthers(l, from, to, in);
        if (stop < to) bad = std::min(bad, stop);
      }
    }
  }
  times_.contactPass += since(t0);
  if (bad < nc)  // the history stays as it was (the step does not commit)
    throw Error("UNSTABLE OVERLAP",
                "elements " + std::to_string(l.idA[bad]) + " and " + std::to_string(l.idB[bad]) +
                    " overlap by " + formatNumber(l.overlap[bad]) + ", more than " +
                    formatNumber(maxOverlap) +
                    " of the smaller one's size: reduce the timestep or stiffen the material");

  t0 = Clock::now();
  // The sums, in list order (the same bits for any thread count). Without a
  // branch on touching (not predictable): a contact that does not touch has
  // a zero force and torques, and adds nothing.
  std::vector<char>& touchingFlags = scratchTouch_;  // for checkSpeeds
  touchingFlags.assign(n, 0);
  char* __restrict touching = touchingFlags.data();
  Vec2* __restrict force = b.force.data();
  double* __restrict torque = b.torque.data();
  const std::int32_t* __restrict touches = l.history[1 - l.current].touching.data();
  const int* __restrict pa = l.a.data();
  const int* __restrict pb = l.b.data();
  const double* __restrict fx = l.fx.data();
  const double* __restrict fy = l.fy.data();
  const double* __restrict ta = l.ta.data();
  const double* __restrict tb = l.tb.data();
  for (std::size_t k = 0; k < nc; ++k) {
    const int i = pa[k], j = pb[k];
    const Vec2 f(fx[k], fy[k]);
    const char t = char(touches[k]);
    touching[i] |= t;
    touching[j] |= t;
    force[i] -= f;
    force[j] += f;
    torque[i] -= ta[k];
    torque[j] += tb[k];
  }
  times_.sums += since(t0);
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
  // Verlet moves before it checks: the pose and half-step velocities to go
  // back to.
  std::vector<Vec2> x0, v0;
  std::vector<double> a0, w0;
  if (integrator == Integrator::verlet) {
    // Kick-drift with the forces of the previous step, then forces, then kick.
    x0 = b.x, v0 = b.vHalf;
    a0 = b.angle, w0 = b.wHalf;
    if (anyUnstarted()) {
      // An element without a previous step (new, or set by hand) kicks with the
      // force at its present state: evaluate it, keeping the contact history
      // (the step's own evaluation follows) and the others' forces.
      const std::vector<Vec2> f0 = b.force;
      const std::vector<double> torque0 = b.torque;
      updatePairs();
      try {
        computeForces(dt, gravity, false);  // the history stays: nothing commits
      } catch (...) {
        b.force = f0, b.torque = torque0;
        throw;
      }
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
  } else {
    updatePairs();
    // Velocity-dependent forces (damping) use the last half-step velocity: the
    // extrapolated v(t) = v(t - dt/2) + a(t - dt) dt/2 feeds back the previous
    // acceleration and sustains limit cycles of the contact-rotation modes at
    // dt_crit/10 (a settling bed never came to rest).
    if (anyUnstarted())
      for (int s = 0; s < n; ++s)
        if (!b.started[s]) b.vHalf[s] = b.v[s], b.wHalf[s] = b.w[s];
  }
  times_.sort += since(t0);
  t0 = Clock::now();
  spareForce_.resize(std::size_t(n)), spareTorque_.resize(std::size_t(n));
  b.force.swap(spareForce_), b.torque.swap(spareTorque_);
  try {
    computeForces(dt, gravity, integrator != Integrator::euler);
    times_.narrow += since(t0);
    t0 = Clock::now();
    checkSpeeds(dt);
  } catch (...) {
    b.force.swap(spareForce_), b.torque.swap(spareTorque_);
    if (integrator == Integrator::verlet) b.x = x0, b.angle = a0, b.vHalf = v0, b.wHalf = w0;
    throw;
  }
  // Nothing can fail now: the contacts' new history and the bonds' breaks of
  // this step stand.
  list_.current = 1 - list_.current;
  viewValid_ = false;
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
