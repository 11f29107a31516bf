#include <cmath>
#include <limits>

#include "collide.hpp"
#include "sandflow/dem/polygon.hpp"

namespace sf::dem {

// Disc b against polygon a: the nearest point of the outline to the disc's
// centre; a centre inside the polygon pushes out through the nearest edge.
bool collidePolygonDisc(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                        Manifold& m) {
  const std::vector<Vec2> p = static_cast<const Polygon&>(a).world(pa.x, pa.angle);
  const double r = static_cast<const Disc&>(b).radius();
  const Vec2 c = pb.x;
  const std::size_t n = p.size();
  double deepest = -std::numeric_limits<double>::infinity();  // largest signed edge distance
  std::size_t edge = 0;
  double nearest2 = std::numeric_limits<double>::infinity();
  Vec2 nearest = p[0];
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 e = p[(i + 1) % n] - p[i];
    const double len = e.norm();
    const Vec2 outward(e.y() / len, -e.x() / len);  // counter-clockwise outline
    const double d = (c - p[i]).dot(outward);
    if (d > deepest) deepest = d, edge = i;
    const double t = std::clamp((c - p[i]).dot(e) / (len * len), 0.0, 1.0);
    const Vec2 q = p[i] + t * e;
    const double d2 = (c - q).squaredNorm();
    if (d2 < nearest2) nearest2 = d2, nearest = q;
  }
  if (deepest <= 0) {  // centre inside
    const Vec2 e = (p[(edge + 1) % n] - p[edge]).normalized();
    m.normal = Vec2(e.y(), -e.x());
    m.overlap = r - deepest;
    m.point = c - deepest * m.normal - 0.5 * m.overlap * m.normal;
    return true;
  }
  if (nearest2 >= r * r) return false;
  const double d = std::sqrt(nearest2);
  m.normal = (c - nearest) / d;
  m.overlap = r - d;
  m.point = nearest - 0.5 * m.overlap * m.normal;
  return true;
}

}  // namespace sf::dem
