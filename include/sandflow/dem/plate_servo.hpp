#pragma once
// Plates: a wall with a target stress s (Bodies::stress, NaN: none) moves
// along its left normal (from -> to turned a quarter counter-clockwise) so
// that the contact load on it is s x length. The servo keeps only the list of
// plates, found again when the elements change; the stresses are the
// elements' own (and are saved with them).
#include <cstdint>
#include <string>
#include <vector>

#include "sandflow/dem/bodies.hpp"
#include "sandflow/dem/contact_list.hpp"
#include "sandflow/dem/material.hpp"

namespace sf::dem {

class PlateServo {
 public:
  // Checks and sets the stress of the element at `slot`; a plate is held
  // whole (the caller updates its mass). NaN removes the servo (the wall
  // keeps its last velocity).
  static void set(Bodies& b, int slot, double stress);
  // Each plate's velocity for the next step from the contact loads on it.
  // `generation` changes with the element set (Assembly).
  void servo(Bodies& b, const MaterialTable& materials, const ContactList& contacts,
             std::uint64_t generation, double dt);
  // Stresses finite and on walls only: what is wrong, in words.
  static std::vector<std::string> validate(const Bodies& b);

 private:
  std::vector<int> plates_;  // slots with a servo, found again when the generation changes
  std::uint64_t platesAt_ = 0;
};

}  // namespace sf::dem
