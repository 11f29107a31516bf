#pragma once
// The sums of the step's forces onto each element: its own loads (applied,
// gravity, the fluid's) and then its contacts' forces and torques, gathered
// in the contact list's order (ContactsByElement). Each element is summed on
// its own, so a block of slots runs on any thread and the bits do not
// depend on how the slots are split.
#include <cstdint>

#include "sandflow/geometry/vec2.hpp"

namespace sf::dem::detail {

struct SumInputs {
  // The elements' own loads.
  const Vec2 *applied, *acceleration, *fluid, *buoyancy;
  const double *mass, *appliedTorque, *fluidTorque;
  Vec2 gravity;
  // The evaluated contacts (ContactList: force on b, torques about a's and
  // b's centres, touching in the step's new history) and each slot's.
  const std::uint32_t *start, *entry;
  const double *fx, *fy, *ta, *tb;
  const std::int32_t* touches;
  // Out: the totals, and whether the element touches anything.
  Vec2* force;
  double* torque;
  char* touching;
};

// Slots [begin, end). Returns 0 when every force and torque there is finite
// (else NaN): a probe, so that a bad slot is looked for only when there is one.
double sumElements(const SumInputs& in, int begin, int end);

}  // namespace sf::dem::detail
