#pragma once
// Superquadrics (superellipses) |x/a|^m + |y/b|^n = 1: rounded boxes to
// ellipses to lozenges. Contacts test the outline sampled at N points against
// the implicit function of the other shape (physics.md §4): the sample count is
// the accuracy knob.
#include <vector>

#include "sandflow/dem/shape.hpp"

namespace sf::dem {

class Superquadric final : public Shape {
 public:
  // Throws sf::Error unless the semi-axes and exponents pass checkSemiAxes and
  // checkExponents (shape_checks.hpp) and samples is 8 to 100000.
  Superquadric(double a, double b, double m, double n, int samples);

  double a() const { return a_; }
  double b() const { return b_; }
  double m() const { return m_; }
  double n() const { return n_; }
  int samples() const { return int(outline_.size()); }
  // Outline sample points in world coordinates.
  std::vector<Vec2> world(const Vec2& x, double angle) const;
  // Implicit function in the shape's own frame: < 0 inside, 0 on the outline.
  double implicit(const Vec2& local) const;
  // Penetration of a world point: depth > 0 inside, and the outward normal of
  // the nearest outline point (Newton steps along the gradient).
  bool penetration(const Vec2& x, double angle, const Vec2& point, double& depth,
                   Vec2& normal) const;

  ShapeType type() const override { return ShapeType::superquadric; }
  double area() const override { return area_; }
  double inertiaPerMass() const override { return inertiaPerMass_; }
  double boundingRadius() const override { return radius_; }
  double contactSize() const override { return std::min(a_, b_); }
  Box bounds(const Vec2& x, double angle) const override;
  std::unique_ptr<Shape> clone() const override { return std::make_unique<Superquadric>(*this); }

 private:
  Vec2 gradient(const Vec2& local) const;
  double a_, b_, m_, n_;
  std::vector<Vec2> outline_;
  double area_, inertiaPerMass_, radius_;
};

}  // namespace sf::dem
