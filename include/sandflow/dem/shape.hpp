#pragma once
// Element shapes in their own frame (centroid at the origin). An element's
// shape is its cold data; its pose and motion live in dem::Bodies.
#include <cstdint>
#include <memory>

#include "sandflow/geometry/vec2.hpp"

namespace sf::dem {

enum class ShapeType : std::uint8_t { disc = 0, polygon = 1, superquadric = 2, wall = 3 };
inline constexpr int kShapeTypes = 4;
// Null-terminated: also the table of "element ids -type" (Tcl_GetIndexFromObjStruct).
inline constexpr const char* shapeTypeNames[kShapeTypes + 1] = {"disc", "polygon", "superquadric",
                                                                "wall", nullptr};

struct Box {
  Vec2 lo, hi;
  bool overlaps(const Box& o) const {
    return lo.x() <= o.hi.x() && o.lo.x() <= hi.x() && lo.y() <= o.hi.y() && o.lo.y() <= hi.y();
  }
};

class Shape {
 public:
  virtual ~Shape() = default;
  virtual ShapeType type() const = 0;
  virtual double area() const = 0;            // mass = density * area (per unit thickness)
  virtual double inertiaPerMass() const = 0;  // polar moment about the centroid / mass
  virtual double boundingRadius() const = 0;  // farthest point from the centroid
  virtual double contactSize() const = 0;     // length scale that overlaps are judged by
  virtual Box bounds(const Vec2& x, double angle) const = 0;
  virtual std::unique_ptr<Shape> clone() const = 0;
};

class Disc final : public Shape {
 public:
  explicit Disc(double radius) : radius_(radius) {}
  double radius() const { return radius_; }
  ShapeType type() const override { return ShapeType::disc; }
  double area() const override;
  double inertiaPerMass() const override { return 0.5 * radius_ * radius_; }
  double boundingRadius() const override { return radius_; }
  double contactSize() const override { return radius_; }
  Box bounds(const Vec2& x, double angle) const override;
  std::unique_ptr<Shape> clone() const override { return std::make_unique<Disc>(*this); }

 private:
  double radius_;
};

// A line segment along the local x axis, from -L/2 to L/2. Its mass is that of a
// strip `thickness` wide, for when it is set free.
class Wall final : public Shape {
 public:
  Wall(double length, double thickness) : length_(length), thickness_(thickness) {}
  // A wall made without a thickness: 1/20 of its length.
  static double defaultThickness(double length) { return length / 20; }
  double length() const { return length_; }
  double thickness() const { return thickness_; }
  // World end points for a pose.
  std::pair<Vec2, Vec2> ends(const Vec2& x, double angle) const;
  ShapeType type() const override { return ShapeType::wall; }
  double area() const override { return length_ * thickness_; }
  double inertiaPerMass() const override { return length_ * length_ / 12.0; }
  double boundingRadius() const override { return 0.5 * length_; }
  double contactSize() const override { return 0.5 * length_; }
  Box bounds(const Vec2& x, double angle) const override;
  std::unique_ptr<Shape> clone() const override { return std::make_unique<Wall>(*this); }

 private:
  double length_, thickness_;
};

}  // namespace sf::dem
