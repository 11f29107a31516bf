#pragma once
// Narrow phase: one routine per pair of shape types, looked up in a table
// (reverse pairs reuse the routine with the roles swapped).
#include "sandflow/dem/shape.hpp"

namespace sf::dem {

struct Pose {
  Vec2 x;
  double angle;
};

// A contact between a and b: unit normal from a towards b, overlap > 0, and the
// contact point (middle of the overlap).
struct Manifold {
  Vec2 normal = Vec2::Zero();
  double overlap = 0.0;
  Vec2 point = Vec2::Zero();
};

// True when the shapes overlap; fills `m`.
bool collide(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, Manifold& m);

// Whether a pair of shape types can touch at all (walls do not touch walls).
bool canCollide(ShapeType a, ShapeType b);

}  // namespace sf::dem
