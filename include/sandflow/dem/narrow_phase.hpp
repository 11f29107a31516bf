#pragma once
// Narrow phase: one routine per pair of shape types, looked up in a table
// (reverse pairs reuse the routine with the roles swapped).
#include <cmath>

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

// Two discs (centres, radii): the commonest pair, inline so that the contact
// loop calls it without the table's dispatch.
inline bool collideDiscs(const Vec2& xa, double ra, const Vec2& xb, double rb, Manifold& m) {
  const Vec2 d = xb - xa;
  const double dist2 = d.squaredNorm(), reach = ra + rb;
  if (dist2 >= reach * reach) return false;
  const double dist = std::sqrt(dist2);
  m.normal = dist > 0 ? Vec2(d * (1.0 / dist)) : Vec2(1, 0);
  m.overlap = reach - dist;
  m.point = xa + m.normal * (ra - 0.5 * m.overlap);
  return true;
}

// Whether a pair of shape types can touch at all (walls do not touch walls).
bool canCollide(ShapeType a, ShapeType b);

}  // namespace sf::dem
