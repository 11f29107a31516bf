#include <algorithm>
#include <cmath>

#include "collide.hpp"
#include "sandflow/dem/polygon.hpp"

namespace sf::dem {
namespace {

// Crossing of segments p0p1 and q0q1, if any.
bool crossing(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1, Vec2& at) {
  const Vec2 r = p1 - p0, s = q1 - q0;
  const double den = r.x() * s.y() - r.y() * s.x();
  if (den == 0) return false;
  const Vec2 d = q0 - p0;
  const double t = (d.x() * s.y() - d.y() * s.x()) / den;
  const double u = (d.x() * r.y() - d.y() * r.x()) / den;
  if (t < 0 || t > 1 || u < 0 || u > 1) return false;
  at = p0 + t * r;
  return true;
}

}  // namespace

bool areaContact(const std::vector<Vec2>& region, const Vec2& chordFrom, const Vec2& chordTo,
                 const Vec2& from, const Vec2& to, Manifold& m) {
  if (region.size() < 3) return false;
  const double area = geometry::signedArea(region);
  if (!(area > 0)) return false;
  const Vec2 chord = chordTo - chordFrom;
  const double length = chord.norm();
  if (!(length > 0)) return false;
  Vec2 n(chord.y() / length, -chord.x() / length);
  if (n.dot(to - from) < 0) n = -n;
  m.normal = n;
  m.overlap = area / length;
  m.point = geometry::centroid(region);
  return true;
}

// Polygon b against polygon a: the overlap region and the chord joining the
// two points where the outlines cross (the usual 2D polygon-DEM law).
bool collidePolygonPolygon(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                           Manifold& m) {
  const std::vector<Vec2> p = static_cast<const Polygon&>(a).world(pa.x, pa.angle);
  const std::vector<Vec2> q = static_cast<const Polygon&>(b).world(pb.x, pb.angle);
  const std::vector<Vec2> region = geometry::clip(p, q);
  if (region.size() < 3) return false;
  // Crossings of the outlines; in a deep or odd overlap there may be more than
  // two: the chord joins the two farthest apart.
  std::vector<Vec2> cross;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < q.size(); ++j) {
      Vec2 at;
      if (crossing(p[i], p[(i + 1) % p.size()], q[j], q[(j + 1) % q.size()], at))
        cross.push_back(at);
    }
  if (cross.size() < 2) {
    // One outline inside the other: push along the line of centres.
    const Vec2 d = (pb.x - pa.x).norm() > 0 ? Vec2((pb.x - pa.x).normalized()) : Vec2(1, 0);
    const Vec2 c = geometry::centroid(region);
    return areaContact(region, c - Vec2(-d.y(), d.x()), c + Vec2(-d.y(), d.x()), pa.x, pb.x, m);
  }
  // Two crossings make the chord; more (touching corners, collinear edges, a
  // deep overlap) are reduced to their principal axis and extent along it.
  Vec2 mean = Vec2::Zero();
  for (const Vec2& x : cross) mean += x;
  mean /= double(cross.size());
  double cxx = 0, cxy = 0, cyy = 0;
  for (const Vec2& x : cross) {
    const Vec2 d = x - mean;
    cxx += d.x() * d.x(), cxy += d.x() * d.y(), cyy += d.y() * d.y();
  }
  const double theta = 0.5 * std::atan2(2 * cxy, cxx - cyy);
  const Vec2 dir(std::cos(theta), std::sin(theta));
  double lo = 0, hi = 0;
  for (const Vec2& x : cross)
    lo = std::min(lo, (x - mean).dot(dir)), hi = std::max(hi, (x - mean).dot(dir));
  return areaContact(region, mean + lo * dir, mean + hi * dir, pa.x, pb.x, m);
}

}  // namespace sf::dem
