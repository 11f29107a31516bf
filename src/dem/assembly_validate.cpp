// Assembly::validate: the invariants the step relies on, checked afresh.
#include <cmath>
#include <set>

#include "sandflow/dem/assembly.hpp"

namespace sf::dem {
namespace {

std::string element(int id) {
  return "element " + std::to_string(id);
}

}  // namespace

std::vector<std::string> Assembly::validate() const {
  std::vector<std::string> problems;
  auto problem = [&](const std::string& p) { problems.push_back(p); };
  const Bodies& b = bodies_;
  const std::size_t n = b.id.size();
  for (const auto* c : {&b.x, &b.v, &b.vHalf, &b.force, &b.appliedForce, &b.acceleration,
                        &b.fluidForce, &b.buoyancy})
    if (c->size() != n) problem("the element columns differ in length");
  for (const auto* c : {&b.angle, &b.w, &b.wHalf, &b.torque, &b.appliedTorque, &b.mass, &b.inertia,
                        &b.invMass, &b.invInertia, &b.reach, &b.extent, &b.fluidTorque, &b.stress})
    if (c->size() != n) problem("the element columns differ in length");
  if (b.shape.size() != n || b.material.size() != n || b.hold.size() != n ||
      b.started.size() != n || b.ghost.size() != n || b.slotOf.size() != n)
    problem("the element columns differ in length");
  if (!problems.empty()) return problems;

  for (std::size_t s = 0; s < n; ++s) {
    const int id = b.id[s];
    if (b.slot(id) != int(s)) problem(element(id) + " is not found at its slot");
    if (!b.shape[s]) {
      problem(element(id) + " has no shape");
      continue;
    }
    if (b.material[s] < 0 || b.material[s] >= materials_.size())
      problem(element(id) + " has no material");
    if (!(std::isfinite(b.mass[s]) && b.mass[s] > 0 && std::isfinite(b.inertia[s]) &&
          b.inertia[s] > 0))
      problem(element(id) + " has mass " + formatNumber(b.mass[s]) + " and inertia " +
              formatNumber(b.inertia[s]));
    if (!b.x[s].allFinite() || !std::isfinite(b.angle[s]) || !b.v[s].allFinite() ||
        !std::isfinite(b.w[s]) || !b.vHalf[s].allFinite() || !std::isfinite(b.wHalf[s]) ||
        !b.force[s].allFinite() || !std::isfinite(b.torque[s]))
      problem(element(id) + " has a position, velocity or force that is not finite");
    const bool heldXY = (b.hold[s] & holdX) && (b.hold[s] & holdY);
    if (b.invMass[s] != (heldXY ? 0.0 : 1.0 / b.mass[s]) ||
        b.invInertia[s] != ((b.hold[s] & holdRotation) ? 0.0 : 1.0 / b.inertia[s]))
      problem(element(id) + "'s inverse mass does not follow its mass and holds");
    if (!std::isnan(b.stress[s]) && b.shape[s]->type() != ShapeType::wall)
      problem(element(id) + " has a plate stress but is not a wall");
  }

  // The contact list: pairs of live slots, a < b, named by their ids, each
  // once, in slot-pair order within each run; the vector run linear discs only.
  // After a deletion the list still holds the old slots until the next step
  // rebuilds it by id (slotsMoved_), so only then do its slots mean anything.
  const ContactList& l = list_;
  std::set<std::pair<int, int>> seen;
  for (std::size_t k = 0; k < (slotsMoved_ ? 0 : l.size()); ++k) {
    const int i = l.a[k], j = l.b[k];
    const std::string which = "contact " + std::to_string(k);
    if (i < 0 || i >= j || std::size_t(j) >= n) {
      problem(which + " joins slots " + std::to_string(i) + " and " + std::to_string(j));
      continue;
    }
    if (l.idA[k] != b.id[i] || l.idB[k] != b.id[j])
      problem(which + " names elements " + std::to_string(l.idA[k]) + " and " +
              std::to_string(l.idB[k]) + " that are not at its slots");
    if (!seen.insert({i, j}).second) problem(which + " is a second copy of its pair");
    if (k > 0 && k != l.vectorCount && std::pair(l.a[k - 1], l.b[k - 1]) >= std::pair(i, j))
      problem(which + " is out of slot-pair order");
    const bool discs =
        b.shape[i]->type() == ShapeType::disc && b.shape[j]->type() == ShapeType::disc;
    if (k < l.vectorCount && !discs) problem(which + " is in the disc run but is not two discs");
    const int touching = l.now().touching[k];
    if (touching != 0 && touching != 1) problem(which + " has a bad touching flag");
  }
  if (l.vectorCount > l.size()) problem("the contact list's disc run is longer than the list");

  std::set<int> bondIds;
  for (const Bond& bond : bonds_) {
    if (!bondIds.insert(bond.id).second) problem("bond " + std::to_string(bond.id) + " twice");
    if (b.slot(bond.idA) < 0 || b.slot(bond.idB) < 0)
      problem("bond " + std::to_string(bond.id) + " joins an element that is gone");
    if (!bond.force.allFinite())
      problem("bond " + std::to_string(bond.id) + "'s force is not finite");
    if (bond.id >= nextBondId_)
      problem("bond " + std::to_string(bond.id) + " is above the next id");
  }
  for (const Source& src : sources_)
    if (b.slot(src.id) < 0 || !b.ghost[b.slot(src.id)])
      problem("source " + std::to_string(src.id) + " is not a ghost element");
  if (!std::isfinite(time_)) problem("the elements' clock is not finite");
  return problems;
}

}  // namespace sf::dem
