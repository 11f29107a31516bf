#include <algorithm>
#include <cmath>

#include "collide.hpp"

namespace sf::dem {

bool collideWallDisc(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, Manifold& m) {
  const auto [p, q] = static_cast<const Wall&>(a).ends(pa.x, pa.angle);
  const double r = static_cast<const Disc&>(b).radius();
  const Vec2 seg = q - p;
  const double len2 = seg.squaredNorm();
  const double t = len2 > 0 ? std::clamp((pb.x - p).dot(seg) / len2, 0.0, 1.0) : 0.0;
  const Vec2 closest = p + t * seg;
  const Vec2 d = pb.x - closest;
  const double dist2 = d.squaredNorm();
  if (dist2 >= r * r) return false;
  const double dist = std::sqrt(dist2);
  // A centre exactly on the line: push along the wall's left normal.
  m.normal = dist > 0 ? Vec2(d / dist) : Vec2(Vec2(-seg.y(), seg.x()).normalized());
  m.overlap = r - dist;
  m.point = closest - 0.5 * m.overlap * m.normal;
  return true;
}

}  // namespace sf::dem
