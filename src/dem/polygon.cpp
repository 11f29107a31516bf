#include "sandflow/dem/polygon.hpp"

#include <algorithm>
#include <cmath>

#include "sandflow/core/error.hpp"
#include "sandflow/dem/shape_checks.hpp"

namespace sf::dem {

namespace geometry {

double signedArea(const std::vector<Vec2>& p) {
  double a = 0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const Vec2& u = p[i];
    const Vec2& v = p[(i + 1) % n];
    a += u.x() * v.y() - v.x() * u.y();
  }
  return 0.5 * a;
}

Vec2 centroid(const std::vector<Vec2>& p) {
  // Relative to the first vertex, to keep round-off small far from the origin.
  Vec2 c = Vec2::Zero();
  double a = 0;
  const Vec2 o = p[0];
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const Vec2 u = p[i] - o, v = p[i + 1] - o;
    const double t = u.x() * v.y() - v.x() * u.y();
    a += t;
    c += t * (u + v);
  }
  return o + c / (3 * a);
}

std::vector<Vec2> clipHalfPlane(const std::vector<Vec2>& subject, const Vec2& a, const Vec2& b) {
  std::vector<Vec2> out;
  const std::size_t n = subject.size();
  if (n == 0) return out;
  out.reserve(n + 1);
  const Vec2 d = b - a;
  auto side = [&](const Vec2& p) { return d.x() * (p.y() - a.y()) - d.y() * (p.x() - a.x()); };
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& p = subject[i];
    const Vec2& q = subject[(i + 1) % n];
    const double sp = side(p), sq = side(q);
    if (sp >= 0) out.push_back(p);
    if ((sp >= 0) != (sq >= 0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
  }
  return out;
}

std::vector<Vec2> clip(const std::vector<Vec2>& subject, const std::vector<Vec2>& clipper) {
  std::vector<Vec2> out = subject;
  for (std::size_t i = 0, n = clipper.size(); i < n && !out.empty(); ++i)
    out = clipHalfPlane(out, clipper[i], clipper[(i + 1) % n]);
  return out;
}

}  // namespace geometry

Polygon Polygon::fromVertices(std::vector<Vec2> v, Vec2& centroid) {
  checkConvexOutline(v);  // simple and convex, or the reason why not
  double area = geometry::signedArea(v);
  if (area < 0) {
    std::reverse(v.begin(), v.end());
    area = -area;
  }
  centroid = geometry::centroid(v);
  for (Vec2& p : v) p -= centroid;
  return fromCentred(std::move(v), area);
}

Polygon Polygon::fromCentred(std::vector<Vec2> v, double area) {
  const std::size_t n = v.size();
  Polygon poly;
  poly.vertices_ = v;
  poly.area_ = area;
  // Polar second moment of area about the centroid, by triangles from it.
  double j = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& p = v[i];
    const Vec2& q = v[(i + 1) % n];
    const double cross = p.x() * q.y() - q.x() * p.y();
    j += cross * (p.squaredNorm() + p.dot(q) + q.squaredNorm());
  }
  poly.inertiaPerMass_ = j / 12.0 / area;
  poly.radius_ = 0;
  poly.inradius_ = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& p = v[i];
    const Vec2 e = (v[(i + 1) % n] - p).normalized();
    poly.radius_ = std::max(poly.radius_, p.norm());
    poly.inradius_ = std::min(poly.inradius_, std::abs(e.x() * p.y() - e.y() * p.x()));
  }
  return poly;
}

std::vector<Vec2> Polygon::world(const Vec2& x, double angle) const {
  const double c = std::cos(angle), s = std::sin(angle);
  std::vector<Vec2> out;
  out.reserve(vertices_.size());
  for (const Vec2& p : vertices_)
    out.emplace_back(x.x() + c * p.x() - s * p.y(), x.y() + s * p.x() + c * p.y());
  return out;
}

Box Polygon::bounds(const Vec2& x, double angle) const {
  const std::vector<Vec2> w = world(x, angle);
  Box b{w[0], w[0]};
  for (const Vec2& p : w) b.lo = b.lo.cwiseMin(p), b.hi = b.hi.cwiseMax(p);
  return b;
}

}  // namespace sf::dem
