#pragma once
// Per-element state in dense arrays indexed by slot (hot data for the step),
// with each element's shape and settings beside it. Ids map to slots; deleting
// swap-removes so the arrays stay dense.
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "sandflow/core/byte_stream.hpp"
#include "sandflow/dem/shape.hpp"

namespace sf::dem {

class MaterialTable;

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

  // Checkpoints: the ids, shapes and columns in slot order (part of
  // "ELEM"). `load` fills empty bodies, refusing repeated or negative ids,
  // short columns and values that are not finite; the caller checks the
  // materials and flags and computes the masses.
  void save(ByteWriter& out) const;
  void load(ByteReader& in);
  // Columns of one length, ids at their slots, a shape and material each,
  // finite and positive masses that the holds and shapes follow, finite
  // motion: what is wrong, in words.
  std::vector<std::string> validate(const MaterialTable& materials) const;
};

}  // namespace sf::dem
