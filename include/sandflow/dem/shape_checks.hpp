#pragma once
// What makes a shape's definition usable, checked before the shape is made.
// A polygon's outline must be simple and convex; ellipse and superquadric
// semi-axes finite, positive and not too unequal; superquadric exponents
// where the shape stays convex and its contacts resolve its corners. Each
// refusal is an sf::Error (VALUE VERTICES, AXES or EXPONENTS) giving the
// reason and the values, without naming a command's options.
#include <vector>

#include "sandflow/geometry/vec2.hpp"

namespace sf::dem {

// The longer semi-axis may be at most this many times the shorter. Beyond it
// an ellipse's 10000-sided outline has vertices too near a straight line to
// tell from one (kStraightTurn), and the shape is a needle no contact resolves.
inline constexpr double kMaxAxisRatio = 1e6;
// Superquadric exponents: below 1 the shape is not convex; at 100 it already
// differs from its bounding box by 0.02% of the area, and beyond, the powers
// |x/a|^m its contacts evaluate under- and overflow (2^m does at m = 1024).
inline constexpr double kMinExponent = 1, kMaxExponent = 100;
// The sine of the smallest turn an outline may make at a vertex: less is a
// straight line (or a reversal), whatever the polygon's size.
inline constexpr double kStraightTurn = 1e-10;

// Throws unless `v` (in order, either way round) is a simple convex polygon:
// at least 3 finite vertices, no vertex repeated, no three in a row on one
// line, turning one way and going round once without crossing itself.
// Vertices are numbered from 1 in the order given.
void checkConvexOutline(const std::vector<Vec2>& v);

// `shape` names the shape in the message ("ellipse", "superquadric").
void checkSemiAxes(double a, double b, const char* shape);
void checkExponents(double m, double n);

}  // namespace sf::dem
