#pragma once
// Bonds (cementation, physics.md §4): a spring between two points fixed in the
// frames of two elements -- where their surfaces were closest when the bond was
// made -- that resists pulling apart and some shear, and breaks when its force
// exceeds its strength. Breaks are events users count.
#include <vector>

#include "sandflow/geometry/vec2.hpp"

namespace sf::dem {

struct Bond {
  int id = 0;
  int idA = 0, idB = 0;             // element ids
  Vec2 anchorA, anchorB;            // attachment points in each element's own frame
  double length = 0;                // rest separation of the anchors along the normal (signed)
  Vec2 normal0;                     // bond direction (A to B) when made
  double angleA0 = 0, angleB0 = 0;  // element angles when made; the normal turns with their mean
  double damping = 0;               // normal and shear damping coefficient
  double stiffness = 0;
  double strength = 0;        // tensile (normal) strength
  double shearStrength = 0;   // shear strength
  Vec2 force = Vec2::Zero();  // last force on B (on A the opposite)
};

struct BondBreak {
  double time;
  Vec2 at;       // middle of the two anchors
  double angle;  // direction of the bond (from A to B), radians
  int bond, idA, idB;
  bool tension;  // broke in tension (else in shear)
};

}  // namespace sf::dem
