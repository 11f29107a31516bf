#include <cmath>
#include <numbers>

#include "sandflow/dem/shape.hpp"

namespace sf::dem {

double Disc::area() const {
  return std::numbers::pi * radius_ * radius_;
}

Box Disc::bounds(const Vec2& x, double) const {
  const Vec2 r(radius_, radius_);
  return {x - r, x + r};
}

std::pair<Vec2, Vec2> Wall::ends(const Vec2& x, double angle) const {
  const Vec2 half = 0.5 * length_ * Vec2(std::cos(angle), std::sin(angle));
  return {x - half, x + half};
}

Box Wall::bounds(const Vec2& x, double angle) const {
  const auto [a, b] = ends(x, angle);
  return {a.cwiseMin(b), a.cwiseMax(b)};
}

}  // namespace sf::dem
