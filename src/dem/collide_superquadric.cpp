// Superquadrics against every shape: the sampled outline of each shape is
// tested against the other's inside test, and the deepest point makes the
// contact (overlap = its depth, normal = the outward normal there).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "collide.hpp"
#include "sandflow/dem/polygon.hpp"
#include "sandflow/dem/superquadric.hpp"

namespace sf::dem {
namespace {

// Penetration of a world point into any non-wall shape.
bool penetrates(const Shape& s, const Pose& pose, const Vec2& p, double& depth, Vec2& normal) {
  switch (s.type()) {
    case ShapeType::disc: {
      const double r = static_cast<const Disc&>(s).radius();
      const Vec2 d = p - pose.x;
      const double dist = d.norm();
      if (dist >= r) return false;
      depth = r - dist;
      normal = dist > 0 ? Vec2(d / dist) : Vec2(1, 0);
      return true;
    }
    case ShapeType::polygon: {
      const std::vector<Vec2> v = static_cast<const Polygon&>(s).world(pose.x, pose.angle);
      double best = -std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < v.size(); ++i) {
        const Vec2 e = (v[(i + 1) % v.size()] - v[i]).normalized();
        const Vec2 out(e.y(), -e.x());
        const double d = (p - v[i]).dot(out);
        if (d >= 0) return false;
        if (d > best) best = d, normal = out;
      }
      depth = -best;
      return true;
    }
    case ShapeType::superquadric:
      return static_cast<const Superquadric&>(s).penetration(pose.x, pose.angle, p, depth, normal);
    case ShapeType::wall:
      return false;
  }
  return false;
}

// Sample points of a shape's outline: a superquadric's own samples; the
// vertices of a polygon; `count` points round a disc.
std::vector<Vec2> outline(const Shape& s, const Pose& pose, int count) {
  switch (s.type()) {
    case ShapeType::superquadric:
      return static_cast<const Superquadric&>(s).world(pose.x, pose.angle);
    case ShapeType::polygon:
      return static_cast<const Polygon&>(s).world(pose.x, pose.angle);
    case ShapeType::disc: {
      std::vector<Vec2> out;
      const double r = static_cast<const Disc&>(s).radius();
      for (int k = 0; k < count; ++k) {
        const double t = pose.angle + 2 * std::numbers::pi * k / count;
        out.push_back(pose.x + r * Vec2(std::cos(t), std::sin(t)));
      }
      return out;
    }
    case ShapeType::wall:
      break;
  }
  return {};
}

}  // namespace

bool collideSuperquadric(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                         Manifold& m) {
  const int count = a.type() == ShapeType::superquadric
                        ? static_cast<const Superquadric&>(a).samples()
                        : static_cast<const Superquadric&>(b).samples();
  double deepest = 0, depth;
  Vec2 normal;
  bool found = false;
  for (const Vec2& p : outline(a, pa, count))  // a's points inside b: b pushes a away
    if (penetrates(b, pb, p, depth, normal) && depth > deepest) {
      deepest = depth, found = true;
      m.normal = -normal;
      m.point = p + 0.5 * depth * normal;
    }
  for (const Vec2& p : outline(b, pb, count))  // b's points inside a
    if (penetrates(a, pa, p, depth, normal) && depth > deepest) {
      deepest = depth, found = true;
      m.normal = normal;
      m.point = p + 0.5 * depth * normal;
    }
  m.overlap = deepest;
  return found;
}

// Superquadric b against wall a: its samples behind the wall's line (the side
// away from its centre), within the wall's ends.
bool collideWallSuperquadric(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                             Manifold& m) {
  auto [p, q] = static_cast<const Wall&>(a).ends(pa.x, pa.angle);
  const Vec2 dir = (q - p).normalized();
  Vec2 inward(-dir.y(), dir.x());  // from the wall towards the superquadric's centre
  if ((pb.x - p).dot(inward) < 0) inward = -inward;
  const double length = (q - p).norm();
  double deepest = 0;
  bool found = false;
  for (const Vec2& s : static_cast<const Superquadric&>(b).world(pb.x, pb.angle)) {
    const double along = (s - p).dot(dir), depth = -(s - p).dot(inward);
    if (depth <= deepest || along < 0 || along > length) continue;
    deepest = depth, found = true;
    m.point = s + 0.5 * depth * inward;
  }
  m.normal = inward;
  m.overlap = deepest;
  return found;
}

}  // namespace sf::dem
