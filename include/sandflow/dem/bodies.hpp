#pragma once
// Per-element state in dense arrays indexed by slot (hot data for the step),
// with each element's shape and settings beside it. Ids map to slots; deleting
// swap-removes so the arrays stay dense.
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "sandflow/dem/shape.hpp"

namespace sf::dem {

enum Hold : std::uint8_t { holdX = 1, holdY = 2, holdRotation = 4 };

struct Bodies {
  std::vector<int> id;
  std::vector<std::unique_ptr<Shape>> shape;
  std::vector<int> material;
  std::vector<Vec2> x, v, vHalf, force, appliedForce, acceleration;
  std::vector<double> angle, w, wHalf, torque, appliedTorque;
  // Set by the fluid coupling each step (zero without a lattice): the
  // hydrodynamic force and torque, and the static buoyancy -rho_f A g.
  std::vector<Vec2> fluidForce, buoyancy;
  std::vector<double> fluidTorque;
  std::vector<double> mass, inertia, invMass, invInertia;
  std::vector<double> reach, extent;  // cached: bounding radius and contact size of the shape
  std::vector<std::uint8_t> hold;     // Hold bits: those degrees of freedom keep v / w
  std::vector<std::uint8_t> started;  // half-step velocity initialised
  std::vector<std::uint8_t> ghost;    // a source's template: touches nothing
  std::vector<double> stress;         // a plate's target stress (walls; NaN: none)

  int size() const { return int(id.size()); }
  int slot(int elementId) const;  // -1 if none
  void push(int elementId);       // appends a slot with zeroed state
  void swapRemove(int slot);
  std::unordered_map<int, int> slotOf;
};

}  // namespace sf::dem
