// The area is integrated in x over the disc's chords: at abscissa X the chord
// spans |Y| <= s(X) = sqrt(r^2 - X^2), and the part of it in [y0, y1] has length
// clamp(y1, -s, s) - clamp(y0, -s, s). Each clamp integrates in closed form with
// the antiderivative of s, S(X) = (X s + r^2 asin(X/r)) / 2, split where s(X) = |y|.
#include "sandflow/geometry/circle_area.hpp"

#include <algorithm>
#include <cmath>

namespace sf::geometry {
namespace {

// S(x) for x in [-r, r]. asin(x/r) loses half its digits near x = +-r; atan2
// with s from the factored (r - x)(r + x) does not.
double antiderivative(double x, double r) {
  const double s = std::sqrt(std::max(0.0, (r - x) * (r + x)));
  return 0.5 * (x * s + r * r * std::atan2(x, s));
}

// Integral over [a, b] (inside [-r, r], a <= b) of clamp(y, -s(X), s(X)), given
// Sa = S(a) and Sb = S(b). S is odd and s(+-xy) = |y| at the points where the
// chord meets y, so each y costs at most one more arctangent.
double clampedIntegral(double y, double a, double b, double r, double Sa, double Sb) {
  const double sign = y < 0 ? -1.0 : 1.0;
  if (std::abs(y) >= r) return sign * (Sb - Sa);
  const double xy = std::sqrt((r - y) * (r + y));
  const double p1 = std::clamp(-xy, a, b), p2 = std::clamp(xy, a, b);
  double Sxy = 0;
  if ((p1 > a && p1 < b) || (p2 > a && p2 < b))
    Sxy = 0.5 * (xy * std::abs(y) + r * r * std::atan2(xy, std::abs(y)));
  const double S1 = p1 == a ? Sa : p1 == b ? Sb : -Sxy;
  const double S2 = p2 == a ? Sa : p2 == b ? Sb : Sxy;
  return sign * (S1 - Sa) + y * (p2 - p1) + sign * (Sb - S2);
}

}  // namespace

double circleRectangleArea(const Vec2& c, double r, const Vec2& lo, const Vec2& hi) {
  if (!(r > 0)) return 0.0;
  // In the disc's frame; the x range is cut to the disc's extent.
  const double a = std::max(lo.x() - c.x(), -r), b = std::min(hi.x() - c.x(), r);
  if (!(a < b) || !(lo.y() < hi.y())) return 0.0;
  const double y0 = lo.y() - c.y(), y1 = hi.y() - c.y();
  const double Sa = antiderivative(a, r), Sb = antiderivative(b, r);
  const double area = clampedIntegral(y1, a, b, r, Sa, Sb) - clampedIntegral(y0, a, b, r, Sa, Sb);
  return std::clamp(area, 0.0, (b - a) * (y1 - y0));
}

}  // namespace sf::geometry
