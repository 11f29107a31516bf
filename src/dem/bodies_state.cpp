// The bodies in a checkpoint and their invariants.
#include <cmath>

#include "column_bytes.hpp"
#include "sandflow/dem/bodies.hpp"
#include "sandflow/dem/material.hpp"
#include "sandflow/geometry/vec2_bytes.hpp"
#include "shape_state.hpp"

namespace sf::dem {
namespace {

using detail::getColumn;

bool allFinite(const std::vector<double>& column) {
  for (double v : column)
    if (!std::isfinite(v)) return false;
  return true;
}

bool allFinite(const std::vector<Vec2>& column) {
  for (const Vec2& v : column)
    if (!v.allFinite()) return false;
  return true;
}

std::string element(int id) {
  return "element " + std::to_string(id);
}

}  // namespace

void Bodies::save(ByteWriter& out) const {
  out.put(id);
  for (int s = 0; s < size(); ++s) saveShape(out, *shape[s]);
  out.put(material);
  for (const auto* c :
       {&x, &v, &vHalf, &force, &appliedForce, &acceleration, &fluidForce, &buoyancy})
    putVec2s(out, *c);
  for (const auto* c : {&angle, &w, &wHalf, &torque, &appliedTorque, &fluidTorque, &stress})
    out.put(*c);
  out.put(hold), out.put(started), out.put(ghost);
}

void Bodies::load(ByteReader& in) {
  std::vector<int> ids;
  in.get(ids, "element ids");
  const std::size_t n = ids.size();
  for (std::size_t s = 0; s < n; ++s) {
    if (ids[s] < 0 || slot(ids[s]) >= 0)
      ByteReader::fail("it holds element id " + std::to_string(ids[s]) + " twice or negative");
    push(ids[s]);
  }
  for (std::size_t s = 0; s < n; ++s) shape[s] = loadShape(in);
  getColumn(in, material, n, "materials");
  for (auto* c : {&x, &v, &vHalf, &force, &appliedForce, &acceleration, &fluidForce, &buoyancy}) {
    getColumn(in, *c, n, "element vectors");
    if (!allFinite(*c)) ByteReader::fail("it holds an element value that is not finite");
  }
  for (auto* c : {&angle, &w, &wHalf, &torque, &appliedTorque, &fluidTorque}) {
    getColumn(in, *c, n, "element values");
    if (!allFinite(*c)) ByteReader::fail("it holds an element value that is not finite");
  }
  getColumn(in, stress, n, "plate stresses");  // NaN: no servo
  for (double value : stress)
    if (std::isinf(value)) ByteReader::fail("it holds an infinite plate stress");
  getColumn(in, hold, n, "holds");
  getColumn(in, started, n, "element flags");
  getColumn(in, ghost, n, "element flags");
}

std::vector<std::string> Bodies::validate(const MaterialTable& materials) const {
  std::vector<std::string> problems;
  auto problem = [&](const std::string& p) { problems.push_back(p); };
  const std::size_t n = id.size();
  bool columns = shape.size() == n && material.size() == n && hold.size() == n &&
                 started.size() == n && ghost.size() == n && slotOf.size() == n;
  for (const auto* c :
       {&x, &v, &vHalf, &force, &appliedForce, &acceleration, &fluidForce, &buoyancy})
    columns &= c->size() == n;
  for (const auto* c : {&angle, &w, &wHalf, &torque, &appliedTorque, &mass, &inertia, &invMass,
                        &invInertia, &reach, &extent, &fluidTorque, &stress})
    columns &= c->size() == n;
  if (!columns) return {"the element columns differ in length"};

  for (std::size_t s = 0; s < n; ++s) {
    const int i = id[s];
    // slotOf read directly: slot() asserts this very invariant.
    const auto at = slotOf.find(i);
    if (at == slotOf.end() || at->second != int(s))
      problem(element(i) + " is not found at its slot");
    if (!shape[s]) {
      problem(element(i) + " has no shape");
      continue;
    }
    if (material[s] < 0 || material[s] >= materials.size())
      problem(element(i) + " has no material");
    if (!(std::isfinite(mass[s]) && mass[s] > 0 && std::isfinite(inertia[s]) && inertia[s] > 0))
      problem(element(i) + " has mass " + formatNumber(mass[s]) + " and inertia " +
              formatNumber(inertia[s]));
    if (!x[s].allFinite() || !std::isfinite(angle[s]) || !v[s].allFinite() ||
        !std::isfinite(w[s]) || !vHalf[s].allFinite() || !std::isfinite(wHalf[s]) ||
        !force[s].allFinite() || !std::isfinite(torque[s]))
      problem(element(i) + " has a position, velocity or force that is not finite");
    const bool heldXY = (hold[s] & holdX) && (hold[s] & holdY);
    if (invMass[s] != (heldXY ? 0.0 : 1.0 / mass[s]) ||
        invInertia[s] != ((hold[s] & holdRotation) ? 0.0 : 1.0 / inertia[s]))
      problem(element(i) + "'s inverse mass does not follow its mass and holds");
    // The broad phase and the contacts read these instead of the shape.
    if (reach[s] != shape[s]->boundingRadius() || extent[s] != shape[s]->contactSize())
      problem(element(i) + "'s cached size does not follow its shape");
    if (hold[s] > (holdX | holdY | holdRotation) || started[s] > 1 || ghost[s] > 1)
      problem(element(i) + " has a bad flag");
  }
  return problems;
}

}  // namespace sf::dem
