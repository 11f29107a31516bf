#include <algorithm>
#include <cmath>

#include "collide.hpp"
#include "sandflow/dem/polygon.hpp"

namespace sf::dem {

// Polygon b against wall a: the part of the polygon behind the wall's line
// (the side away from the polygon's centroid), within the wall's extent, and
// the chord where the line crosses the polygon.
bool collideWallPolygon(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                        Manifold& m) {
  auto [p, q] = static_cast<const Wall&>(a).ends(pa.x, pa.angle);
  const std::vector<Vec2> poly = static_cast<const Polygon&>(b).world(pb.x, pb.angle);
  const Vec2 d = q - p;
  const double side = d.x() * (pb.x.y() - p.y()) - d.y() * (pb.x.x() - p.x());
  if (side > 0) std::swap(p, q);  // keep the polygon's centroid on the right of p -> q
  const Vec2 dir = (q - p).normalized(), normal(-dir.y(), dir.x());  // normal: behind the wall
  std::vector<Vec2> region = geometry::clipHalfPlane(poly, p, q);
  region = geometry::clipHalfPlane(region, p + normal, p);  // within the wall's ends
  region = geometry::clipHalfPlane(region, q, q + normal);
  if (region.size() < 3) return false;
  // The chord: where the line crosses the polygon, clamped to the wall.
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& u = poly[i];
    const Vec2& v = poly[(i + 1) % n];
    const double su = (u - p).dot(normal), sv = (v - p).dot(normal);
    if ((su > 0) == (sv > 0)) continue;
    const double t = (u + (v - u) * (su / (su - sv)) - p).dot(dir);
    lo = std::min(lo, t), hi = std::max(hi, t);
  }
  const double length = (q - p).norm();
  lo = std::clamp(lo, 0.0, length), hi = std::clamp(hi, 0.0, length);
  if (!(hi > lo)) {  // wholly behind the line: use the region's width along the wall
    lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Vec2& r : region)
      lo = std::min(lo, (r - p).dot(dir)), hi = std::max(hi, (r - p).dot(dir));
  }
  return areaContact(region, p + lo * dir, p + hi * dir, pb.x + normal, pb.x, m);
}

}  // namespace sf::dem
