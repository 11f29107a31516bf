// The assembly's contacts: pair builds, the contact pass and its sums.
#include "sandflow/dem/contact_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include <omp.h>

#include "contact_force.hpp"
#include "disc_contacts.hpp"
#include "sandflow/core/parallel.hpp"
#include "sandflow/dem/narrow_phase.hpp"

namespace sf::dem {
namespace {

// The same key for (a, b) and (b, a).
std::uint64_t pairKey(int a, int b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

}  // namespace

void ContactSet::forget(int id) {
  slotsMoved_ = true;
  // An element given its id later starts afresh (the next pair search
  // carries history over by ids).
  ContactList& l = list_;
  std::int32_t* touching = l.history[l.current].touching.data();
  for (std::size_t k = 0; k < l.size(); ++k)
    if (l.idA[k] == id || l.idB[k] == id) touching[k] = 0;
  viewValid_ = false;
}

std::size_t ContactSet::touchingCount() const {
  const auto& t = list_.now().touching;
  return std::size_t(std::count(t.begin(), t.end(), std::int32_t(1)));
}

Vec2 ContactSet::forceOn(int s) const {
  const ContactList& l = list_;
  Vec2 f = Vec2::Zero();
  for (std::size_t k = 0; k < l.size(); ++k)
    if (l.touching(k))
      f += l.a[k] == s   ? Vec2(-l.fx[k], -l.fy[k])
           : l.b[k] == s ? Vec2(l.fx[k], l.fy[k])
                         : Vec2::Zero();
  return f;
}

const std::vector<Contact>& ContactSet::view() const {
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

// Candidate pairs from boxes grown by a skin; rebuilt only once some element
// has moved (or turned) by half the skin since the last build.
void ContactSet::update(const Bodies& bodies, const MaterialTable& materials,
                        std::uint64_t generation, bool vectorPass) {
  const int n = bodies.size();
  bool rebuild = !pairsValid_ || int(builtAt_.size()) != n || lawsStale(materials, generation);
  if (!rebuild) {
    const Vec2 *x = bodies.x.data(), *x0 = builtAt_.data();
    const double *angle = bodies.angle.data(), *angle0 = builtAngle_.data(),
                 *reach = bodies.reach.data();
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
  for (int s = 0; s < n; ++s) smallest = std::min(smallest, bodies.extent[s]);
  skin_ = std::isfinite(smallest) ? 0.2 * smallest : 0.0;
  // The build's buffers are kept: a fresh list would fault in its pages.
  std::vector<Box>& boxes = build_.boxes;
  boxes.resize(n);
  for (int s = 0; s < n; ++s) {
    Box b = bodies.shape[s]->bounds(bodies.x[s], bodies.angle[s]);
    boxes[s] = {b.lo - Vec2(skin_, skin_), b.hi + Vec2(skin_, skin_)};
  }
  std::vector<std::pair<int, int>>& pairs = build_.pairs;
  dess_.findPairs(boxes, pairs);

  if (lawsStale(materials, generation)) buildLaws(materials);
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
  const int nm = materials.size();
  for (const auto& [a, b] : pairs) {
    if (!canCollide(bodies.shape[a]->type(), bodies.shape[b]->type())) continue;
    if (bodies.ghost[a] || bodies.ghost[b]) continue;
    const bool immovable = bodies.invMass[a] == 0 && bodies.invInertia[a] == 0 &&
                           bodies.invMass[b] == 0 && bodies.invInertia[b] == 0;
    if (immovable) continue;
    std::ptrdiff_t from = -1;
    bool swapped = false;
    if (slotsMoved_) {
      if (auto it = byIds.find(pairKey(bodies.id[a], bodies.id[b])); it != byIds.end())
        from = std::ptrdiff_t(it->second), swapped = old.idA[it->second] != bodies.id[a];
    } else {
      for (int run = 0; run < 2; ++run) {
        std::size_t& k = cursor[run];
        while (k < runEnd[run] && std::pair(old.a[k], old.b[k]) < std::pair(a, b)) ++k;
        if (k < runEnd[run] && old.a[k] == a && old.b[k] == b && oldHistory.touching[k])
          from = std::ptrdiff_t(k);
      }
    }
    const bool discs =
        bodies.shape[a]->type() == ShapeType::disc && bodies.shape[b]->type() == ShapeType::disc;
    // Boxes grown by the skin also pair discs that sit diagonally apart. Each
    // disc moves at most half the skin before the next build, so two that are
    // farther than their radii plus the skin cannot touch until then (the
    // margin covers the rounding of the distances).
    if (discs) {
      const double gap = bodies.reach[a] + bodies.reach[b] + skin_;
      if ((bodies.x[a] - bodies.x[b]).squaredNorm() > gap * gap * (1 + 1e-12)) continue;
    }
    const bool linear = !laws_[bodies.material[a] * nm + bodies.material[b]].hertz;
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
      next.idA[k] = bodies.id[e.a], next.idB[k] = bodies.id[e.b];
      next.discs[k] = e.discs;
      prepareContact(bodies, next, k);
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
  ++listVersion_;
  viewValid_ = false;
  lawsAt_ = generation;
  slotsMoved_ = false;
  builtAt_ = bodies.x;
  builtAngle_ = bodies.angle;
  pairsValid_ = true;
  ++builds_;
}

std::size_t ContactSet::evaluate(const Bodies& b, const std::vector<Vec2>& vel,
                                 const std::vector<double>& omega, double dt, double maxOverlap,
                                 int threads) {
  const detail::ContactInputs in{b.x.data(),   b.angle.data(), b.reach.data(), vel.data(),
                                 omega.data(), b.shape.data(), laws_.data(),   dt,
                                 1.0 / dt,     maxOverlap};
  const detail::LawColumns lawColumns{lawKn_.data(), lawKs_.data(), lawFriction_.data()};
  ContactList& l = list_;
  const std::size_t nc = l.size(), nv = l.vectorCount;
  // The next history and the results of every contact: the linear disc pairs
  // many at a time, the others one by one. Few contacts stay on one thread: a
  // parallel region would cost more.
  const int team = parallel::team(std::ptrdiff_t(nc), parallel::kContactPairs, threads);
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
  return bad;
}

const ContactsByElement& ContactSet::byElement(int n) {
  if (byElementVersion_ != listVersion_ || byElement_.start.size() != std::size_t(n) + 1)
    byElement_.build(list_, n), byElementVersion_ = listVersion_;
  return byElement_;
}

// The sums, in list order (the same bits for any thread count). Without a
// branch on touching (not predictable): a contact that does not touch has a
// zero force and torques, and adds nothing.
void ContactSet::sumOnto(Bodies& b, char* __restrict touching) const {
  const ContactList& l = list_;
  const std::size_t nc = l.size();
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
}

}  // namespace sf::dem
