#pragma once
// Convex polygons: the shape of angular grains (and, with many sides, ellipses).
#include <vector>

#include "sandflow/dem/shape.hpp"

namespace sf::dem {

// A convex polygon given by its vertices counter-clockwise about its centroid.
class Polygon final : public Shape {
 public:
  // From vertices in any frame: checks convexity, orders them counter-clockwise
  // and moves the centroid to the origin; `centroid` receives where it was.
  // Throws sf::Error, with the reason, unless the outline is simple and convex
  // (checkConvexOutline, shape_checks.hpp).
  static Polygon fromVertices(std::vector<Vec2> vertices, Vec2& centroid);
  // From vertices already counter-clockwise about their centroid, and the
  // area fromVertices found for them: the same polygon, bit for bit, without
  // moving them again (a checkpoint's; check them with fromVertices first).
  static Polygon fromCentred(std::vector<Vec2> vertices, double area);

  const std::vector<Vec2>& vertices() const { return vertices_; }
  // Vertices in world coordinates for a pose.
  std::vector<Vec2> world(const Vec2& x, double angle) const;

  ShapeType type() const override { return ShapeType::polygon; }
  double area() const override { return area_; }
  double inertiaPerMass() const override { return inertiaPerMass_; }
  double boundingRadius() const override { return radius_; }
  double contactSize() const override { return inradius_; }
  Box bounds(const Vec2& x, double angle) const override;
  std::unique_ptr<Shape> clone() const override { return std::make_unique<Polygon>(*this); }

 private:
  Polygon() = default;
  std::vector<Vec2> vertices_;
  double area_ = 0, inertiaPerMass_ = 0, radius_ = 0, inradius_ = 0;
};

// Geometry shared by the polygon routines.
namespace geometry {
// Signed area (positive counter-clockwise) and centroid of a simple polygon.
double signedArea(const std::vector<Vec2>& p);
Vec2 centroid(const std::vector<Vec2>& p);
// The part of convex polygon `subject` inside convex polygon `clip` (both
// counter-clockwise), by Sutherland-Hodgman clipping.
std::vector<Vec2> clip(const std::vector<Vec2>& subject, const std::vector<Vec2>& clip);
// The part of `subject` on the left of the directed line a -> b.
std::vector<Vec2> clipHalfPlane(const std::vector<Vec2>& subject, const Vec2& a, const Vec2& b);
}  // namespace geometry

}  // namespace sf::dem
