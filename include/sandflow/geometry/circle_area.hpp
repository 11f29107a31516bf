#pragma once
// Exact area of a disc inside an axis-aligned rectangle (physics.md §3: the
// reference solid ratio of a lattice cell covered by a disc).
#include "sandflow/geometry/vec2.hpp"

namespace sf::geometry {

// Area of the disc (centre c, radius r) inside [lo.x, hi.x] x [lo.y, hi.y].
double circleRectangleArea(const Vec2& c, double r, const Vec2& lo, const Vec2& hi);

}  // namespace sf::geometry

namespace sf::geometry {

// The disc's area in cells of one horizontal band y0 <= y <= y1: its height
// in the band is a constant or the circle's half-chord between breakpoints
// found once for the band, so a cell costs one or two arcsines (and the same
// relative accuracy as circleRectangleArea, whatever the disc's size).
class DiscBand {
 public:
  DiscBand(const Vec2& c, double r, double y0, double y1);
  // Area of the disc in [xa, xb] x [y0, y1].
  double area(double xa, double xb) const;
  // area(x0 + i h, x0 + (i + 1) h) for i = first..last into out[i - first],
  // the same to the bit: neighbouring cells share the half-chord at their
  // common edge, worked out once.
  void areas(double x0, double h, int first, int last, double* out) const;

 private:
  // clamp(s(t), lo, hi) with s(t) = sqrt(r^2 - t^2), t = x - cx: the band's
  // part above the centre line (lo, hi = y0 - cy, y1 - cy) or below it
  // (-(y1 - cy), -(y0 - cy)); s < lo beyond |t| = tl and s > hi within th.
  struct Clamped {
    double lo, hi, tl, th;
  };
  Clamped clamped(double lo, double hi) const;
  // sa, sb: s at a and b.
  double part(const Clamped& c, double a, double b, double sa, double sb) const;
  // The area over a <= t <= b (in the disc's frame, clamped to [-r, r]).
  double between(double a, double b, double sa, double sb) const;
  // Integral of s over [p, q], one side of the centre, s known at both ends.
  double arc(double p, double q, double sp, double sq) const;
  double s(double t) const;

  double cx_, r_;
  Clamped above_, below_;
};

}  // namespace sf::geometry
