#pragma once
// 2D vectors are Eigen fixed-size types; the few planar operations Eigen does
// not name are here, once.
#include <Eigen/Core>
#include <cmath>

namespace sf {
using Vec2 = Eigen::Vector2d;

// z component of the cross product a x b.
inline double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}
// Velocity of a point at r from the centre of a body spinning at w: w x r.
inline Vec2 spin(double w, const Vec2& r) {
  return Vec2(-w * r.y(), w * r.x());
}
// v turned counter-clockwise by angle.
inline Vec2 rotated(const Vec2& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}
}  // namespace sf
