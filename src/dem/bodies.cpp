#include "sandflow/dem/bodies.hpp"

#include <limits>

#include "sandflow/core/assert.hpp"

namespace sf::dem {

int Bodies::slot(int elementId) const {
  const auto it = slotOf.find(elementId);
  if (it == slotOf.end()) return -1;
  SF_ASSERT(it->second >= 0 && it->second < size() && id[it->second] == elementId);
  return it->second;
}

void Bodies::push(int elementId) {
  slotOf[elementId] = size();
  id.push_back(elementId);
  shape.emplace_back();
  material.push_back(0);
  for (auto* a : {&x, &v, &vHalf, &force, &appliedForce, &acceleration, &fluidForce, &buoyancy})
    a->push_back(Vec2::Zero());
  for (auto* a : {&angle, &w, &wHalf, &torque, &appliedTorque, &mass, &inertia, &invMass,
                  &invInertia, &reach, &extent, &fluidTorque})
    a->push_back(0.0);
  hold.push_back(0);
  started.push_back(0);
  ghost.push_back(0);
  stress.push_back(std::numeric_limits<double>::quiet_NaN());
}

void Bodies::swapRemove(int s) {
  const int last = size() - 1;
  slotOf.erase(id[s]);
  auto move = [&](auto& a) {
    if (s != last) a[s] = std::move(a[last]);
    a.pop_back();
  };
  move(id);
  move(shape);
  move(material);
  for (auto* a : {&x, &v, &vHalf, &force, &appliedForce, &acceleration, &fluidForce, &buoyancy})
    move(*a);
  for (auto* a : {&angle, &w, &wHalf, &torque, &appliedTorque, &mass, &inertia, &invMass,
                  &invInertia, &reach, &extent, &fluidTorque})
    move(*a);
  move(hold);
  move(started);
  move(ghost);
  move(stress);
  if (s != last) slotOf[id[s]] = s;
}

}  // namespace sf::dem
