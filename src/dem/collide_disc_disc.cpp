#include <algorithm>
#include <cmath>

#include "collide.hpp"

namespace sf::dem {

bool collideDiscDisc(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, Manifold& m) {
  const double ra = static_cast<const Disc&>(a).radius(), rb = static_cast<const Disc&>(b).radius();
  const Vec2 d = pb.x - pa.x;
  const double dist2 = d.squaredNorm(), reach = ra + rb;
  if (dist2 >= reach * reach) return false;
  const double dist = std::sqrt(dist2);
  m.normal = dist > 0 ? Vec2(d / dist) : Vec2(1, 0);
  m.overlap = reach - dist;
  m.point = pa.x + m.normal * (ra - 0.5 * m.overlap);
  return true;
}

}  // namespace sf::dem
