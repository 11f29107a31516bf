#pragma once
// Exact area of a disc inside an axis-aligned rectangle (physics.md §3: the
// reference solid ratio of a lattice cell covered by a disc).
#include "sandflow/geometry/vec2.hpp"

namespace sf::geometry {

// Area of the disc (centre c, radius r) inside [lo.x, hi.x] x [lo.y, hi.y].
double circleRectangleArea(const Vec2& c, double r, const Vec2& lo, const Vec2& hi);

}  // namespace sf::geometry
