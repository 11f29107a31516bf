#pragma once
// The broad phase's candidate pairs and their contacts, stored in columns: the
// force loop runs down whole columns, several contacts in one vector register
// (src/dem/disc_contacts.cpp). Disc pairs with a linear law come first, in
// slot-pair order, then every other pair, in slot-pair order: the forces are
// summed in that fixed order whatever the thread count.
//
// The history a contact carries from step to step (touching, normal, shear
// spring) is kept twice. A step reads the current copy and writes the other;
// only a step that succeeds makes its copy current, so a step that stops
// (UNSTABLE ...) leaves the history as it was.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sf::dem {

struct ContactHistory {
  std::vector<std::int32_t> touching;  // 0 or 1 (as wide as the indices, for the vector pass)
  std::vector<double> nx, ny;          // unit normal from a to b
  std::vector<double> sx, sy;          // tangential spring force on b
};

struct ContactList {
  std::vector<int> a, b;      // slots, a < b
  std::vector<int> idA, idB;  // element ids (stable across deletions)
  std::vector<std::uint8_t> discs;
  // Cached from the elements and materials until either changes (see
  // ContactSet::prepareContact): the pair's law in the step's table, the normal
  // damping's cached part (dampingPart: the coefficient c_n itself for the
  // linear law, its ratio solved for the step, or a fixed -damping; 2 zeta
  // sqrt(m*) for Hertz with a restitution, whose c_n is that times sqrt(kn),
  // kn changing with the overlap; set for the step by ContactSet::prepareDamping
  // after each build and when the step changes), the smaller element's
  // contact size and the effective radius of curvature (Hertz).
  std::vector<int> law;
  std::vector<double> dampingPart, minSize, radius;
  // The normal force's mode, per contact so that the vector pass loads
  // rather than gathers it: the least normal force (0 compressive, -infinity
  // signed) and whether the normal dashpot is spanned (contact_force.hpp).
  // Set with the damping part, for the step (ContactSet::prepareDamping).
  std::vector<double> normalFloor;
  std::vector<std::int32_t> spanned;
  ContactHistory history[2];
  int current = 0;  // the history in force
  // The last evaluation: force on b (on a: the opposite), point, overlap, and
  // the torques of the force about a's centre (to be subtracted) and b's
  // (added). Meaningful where the current history says touching; zero force
  // and torques where it does not.
  std::vector<double> fx, fy, px, py, overlap, ta, tb;
  std::size_t vectorCount = 0;  // [0, vectorCount): disc pairs with a linear law

  std::size_t size() const { return a.size(); }
  void resize(std::size_t n);
  const ContactHistory& now() const { return history[current]; }
  bool touching(std::size_t k) const { return now().touching[k] != 0; }
};

}  // namespace sf::dem
