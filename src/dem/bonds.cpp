// The bond set: making bonds, their forces, and breaking.
#include <algorithm>
#include <cmath>

#include "sandflow/core/error.hpp"
#include "sandflow/core/memory.hpp"
#include "sandflow/dem/bond_set.hpp"
#include "sandflow/dem/dess.hpp"
#include "sandflow/dem/narrow_phase.hpp"

namespace sf::dem {
namespace {

// Closest surface points of two elements (a's, b's), for bonding; false when
// farther apart than `gap`.
bool closestPoints(const Bodies& B, int a, int b, double gap, Vec2& pa, Vec2& pb) {
  const Shape &sa = *B.shape[a], &sb = *B.shape[b];
  if (sa.type() == ShapeType::disc && sb.type() == ShapeType::disc) {
    const double ra = static_cast<const Disc&>(sa).radius(),
                 rb = static_cast<const Disc&>(sb).radius();
    const Vec2 d = B.x[b] - B.x[a];
    const double dist = d.norm();
    if (dist - ra - rb > gap || dist == 0) return false;
    const Vec2 n = d / dist;
    pa = B.x[a] + ra * n;
    pb = B.x[b] - rb * n;
    return true;
  }
  const bool wallDisc = sa.type() == ShapeType::wall && sb.type() == ShapeType::disc;
  const bool discWall = sa.type() == ShapeType::disc && sb.type() == ShapeType::wall;
  if (wallDisc || discWall) {
    const int w = wallDisc ? a : b, d = wallDisc ? b : a;
    const auto [p, q] = static_cast<const Wall&>(*B.shape[w]).ends(B.x[w], B.angle[w]);
    const double r = static_cast<const Disc&>(*B.shape[d]).radius();
    const Vec2 seg = q - p, c = B.x[d];
    const double t = std::clamp((c - p).dot(seg) / seg.squaredNorm(), 0.0, 1.0);
    const Vec2 onWall = p + t * seg;
    const double dist = (c - onWall).norm();
    if (dist - r > gap || dist == 0) return false;
    const Vec2 onDisc = c - r * (c - onWall) / dist;
    pa = wallDisc ? onWall : onDisc;
    pb = wallDisc ? onDisc : onWall;
    return true;
  }
  // Other shapes bond where they overlap or touch.
  Manifold m;
  if (!collide(sa, {B.x[a], B.angle[a]}, sb, {B.x[b], B.angle[b]}, m)) return false;
  pa = pb = m.point;
  return true;
}

}  // namespace

int BondSet::make(const Bodies& B, const MaterialTable& materials, int a, int b, double stiffness,
                  double strength, double shearStrength) {
  const int idA = B.id[a], idB = B.id[b];
  if (a == b) throw Error("VALUE BOND", "an element cannot be bonded to itself");
  for (const Bond& x : bonds_)
    if ((x.idA == idA && x.idB == idB) || (x.idA == idB && x.idB == idA))
      throw Error("EXISTS BOND", "elements " + std::to_string(idA) + " and " + std::to_string(idB) +
                                     " are already bonded (bond " + std::to_string(x.id) + ")");
  for (double v : {stiffness, strength, shearStrength})
    if (!std::isfinite(v)) throw Error("VALUE BOND", "bond stiffness and strengths must be finite");
  Vec2 pa, pb;
  if (!closestPoints(B, a, b, std::numeric_limits<double>::infinity(), pa, pb))
    throw Error("VALUE BOND", "elements " + std::to_string(idA) + " and " + std::to_string(idB) +
                                  " cannot be bonded: they do not touch");
  const Material &ma = materials[B.material[a]], &mb = materials[B.material[b]];
  Bond x;
  x.idA = idA;
  x.idB = idB;
  x.anchorA = rotated(pa - B.x[a], -B.angle[a]);
  x.anchorB = rotated(pb - B.x[b], -B.angle[b]);
  Vec2 n = B.x[b] - B.x[a];
  if ((pb - pa).norm() > 1e-12 * n.norm()) n = pb - pa;
  x.normal0 = n.normalized();
  x.length = (pb - pa).dot(x.normal0);
  // Elements 1e300 apart: the distance overflows (found by the fuzzer).
  if (!x.anchorA.allFinite() || !x.anchorB.allFinite() || !x.normal0.allFinite() ||
      !std::isfinite(x.length))
    throw Error("VALUE BOND", "elements " + std::to_string(idA) + " and " + std::to_string(idB) +
                                  " cannot be bonded: they are too far apart for the bond's "
                                  "length to be finite");
  x.id = nextId_++;
  x.angleA0 = B.angle[a];
  x.angleB0 = B.angle[b];
  x.stiffness = stiffness >= 0 ? stiffness : std::min(ma.bondStiffness, mb.bondStiffness);
  x.strength = strength >= 0 ? strength : std::min(ma.bondStrength, mb.bondStrength);
  x.shearStrength = shearStrength >= 0 ? shearStrength : x.strength;
  const double meff = 1.0 / (B.invMass[a] + B.invMass[b]);
  const double zeta = combine(ma, mb).zeta;
  x.damping = std::isfinite(meff) ? 2 * zeta * std::sqrt(meff * x.stiffness) : 0.0;
  bonds_.push_back(x);
  return x.id;
}

int BondSet::makeAll(const Bodies& B, const MaterialTable& materials, const std::vector<int>& slots,
                     double gap) {
  std::vector<Box> boxes;
  for (int s : slots) {
    Box b = B.shape[s]->bounds(B.x[s], B.angle[s]);
    boxes.push_back({b.lo - Vec2::Constant(gap / 2), b.hi + Vec2::Constant(gap / 2)});
  }
  Dess sorter;
  std::vector<std::pair<int, int>> pairs;
  sorter.findPairs(boxes, pairs);
  // The pairs to bond, found first so that a gap that would bond far too
  // many is refused before any bond is made.
  std::vector<std::pair<int, int>> chosen;
  for (const auto& [i, j] : pairs) {
    const int a = slots[i], b = slots[j];
    const int idA = B.id[a], idB = B.id[b];
    const bool bonded = std::any_of(bonds_.begin(), bonds_.end(), [&](const Bond& x) {
      return (x.idA == idA && x.idB == idB) || (x.idA == idB && x.idB == idA);
    });
    const bool immovable = B.invMass[a] == 0 && B.invMass[b] == 0;
    Vec2 pa, pb;
    if (bonded || immovable || !canCollide(B.shape[a]->type(), B.shape[b]->type()) ||
        !closestPoints(B, a, b, gap, pa, pb))
      continue;
    chosen.emplace_back(std::min(idA, idB), std::max(idA, idB));
  }
  // A step keeps a second copy of the bonds (the ones that hold).
  const double total = double(bonds_.size() + chosen.size());
  checkMemory(2 * total * sizeof(Bond), "bonding " + std::to_string(chosen.size()) +
                                            " more pairs (" + formatNumber(total) +
                                            " bonds in all)");
  for (const auto& [idA, idB] : chosen) make(B, materials, B.slot(idA), B.slot(idB), -1, -1, -1);
  return int(chosen.size());
}

void BondSet::remove(int bondId) {
  auto it =
      std::find_if(bonds_.begin(), bonds_.end(), [&](const Bond& x) { return x.id == bondId; });
  if (it == bonds_.end()) throw Error("LOOKUP BOND", "no bond with id " + std::to_string(bondId));
  bonds_.erase(it);
}

void BondSet::forget(int id) {
  std::erase_if(bonds_, [&](const Bond& x) { return x.idA == id || x.idB == id; });
}

const Bond& BondSet::info(int bondId) const {
  auto it =
      std::find_if(bonds_.begin(), bonds_.end(), [&](const Bond& x) { return x.id == bondId; });
  if (it == bonds_.end()) throw Error("LOOKUP BOND", "no bond with id " + std::to_string(bondId));
  return *it;
}

// Spring between the anchors: along the bond's normal (which turns with the
// mean rotation of the two elements) it resists stretching from the rest
// separation; across it, the anchors' sideways offset. Damped like a contact.
void BondSet::addForces(Bodies& B, double time, double dt, const std::vector<Vec2>& v,
                        const std::vector<double>& w) {
  // The bonds that hold and the breaks are committed (commit()) once nothing
  // in the step can fail (a failed step keeps its bonds).
  std::vector<Bond>& kept = pendingBonds_;
  kept.clear();
  kept.reserve(bonds_.size());
  pendingBreaks_.clear();
  pending_ = true;
  for (Bond x : bonds_) {
    const int a = B.slot(x.idA), b = B.slot(x.idB);
    const Vec2 ra = rotated(x.anchorA, B.angle[a]), rb = rotated(x.anchorB, B.angle[b]);
    const Vec2 pa = B.x[a] + ra, pb = B.x[b] + rb;
    const Vec2 n = rotated(x.normal0, 0.5 * ((B.angle[a] - x.angleA0) + (B.angle[b] - x.angleB0)));
    const Vec2 d = pb - pa;
    const double stretch = d.dot(n) - x.length;
    const Vec2 offset = d - d.dot(n) * n;
    const Vec2 vrel = (v[b] + spin(w[b], rb)) - (v[a] + spin(w[a], ra));
    const double tension = x.stiffness * stretch;
    const double shear = x.stiffness * offset.norm();
    if (tension > x.strength || shear > x.shearStrength) {
      pendingBreaks_.push_back({time + dt, 0.5 * (pa + pb), std::atan2(n.y(), n.x()), x.id, x.idA,
                                x.idB, tension > x.strength});
      continue;
    }
    x.force = -x.stiffness * (stretch * n + offset) - x.damping * vrel;
    B.force[a] -= x.force;
    B.force[b] += x.force;
    B.torque[a] -= cross(ra, x.force);
    B.torque[b] += cross(rb, x.force);
    kept.push_back(x);
  }
}

void BondSet::commit() {
  if (!pending_) return;
  bonds_.swap(pendingBonds_);
  breaks_.insert(breaks_.end(), pendingBreaks_.begin(), pendingBreaks_.end());
  pending_ = false;
}

}  // namespace sf::dem
