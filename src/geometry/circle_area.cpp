// The area of the convex set D ∩ R is the line integral (x dy - y dx) / 2
// round its boundary, in the disc's frame: a straight piece from P to Q gives
// (P x Q) / 2, an arc of angle t gives r^2 t / 2. The boundary runs ccw round
// the rectangle's edges clipped to the disc, and from the point where it leaves
// one edge along the circle to where it meets the next: at most one arctangent
// per arc, and a cell cut by the outline has one arc (the solid-ratio pass
// measures tens of thousands of such cells each step).
#include "sandflow/geometry/circle_area.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sf::geometry {
namespace {

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

}  // namespace

double circleRectangleArea(const Vec2& c, double r, const Vec2& lo, const Vec2& hi) {
  if (!(r > 0) || !(lo.x() < hi.x()) || !(lo.y() < hi.y())) return 0.0;
  const Vec2 a = lo - c, b = hi - c;  // the rectangle in the disc's frame
  const double r2 = r * r;
  // Nothing, or the whole disc, without any clipping.
  const double nx = std::clamp(0.0, a.x(), b.x()), ny = std::clamp(0.0, a.y(), b.y());
  if (nx * nx + ny * ny >= r2) return 0.0;
  if (a.x() <= -r && a.y() <= -r && b.x() >= r && b.y() >= r) return std::numbers::pi * r2;

  const Vec2 corner[4] = {a, Vec2(b.x(), a.y()), b, Vec2(a.x(), b.y())};  // ccw
  bool in[4];
  for (int k = 0; k < 4; ++k) in[k] = corner[k].squaredNorm() <= r2;
  if (in[0] && in[1] && in[2] && in[3]) return (b.x() - a.x()) * (b.y() - a.y());  // convexity
  // Each edge clipped to the disc: [enter, leave], or nothing. Corners are
  // classified once, so neighbouring edges agree on the point they share.
  Vec2 enter[4], leave[4];
  bool piece[4];
  // Near tangency the crossings carry the square root of the rounding error:
  // a piece shorter than `sliver` (the disc bulging past an edge by ~1e-14 of
  // its size, an area of ~1e-21) is dropped, so that no arc runs between two
  // such crossings. Points closer than `same` are one point.
  const double scale = std::max(r, (b - a).norm()), sliver = 1e-7 * scale, same = 1e-12 * scale;
  for (int k = 0; k < 4; ++k) {
    const Vec2 &p = corner[k], &q = corner[(k + 1) % 4];
    const Vec2 d = q - p;
    piece[k] = true;
    if (in[k] && in[(k + 1) % 4]) {  // convexity: the whole edge
      enter[k] = p, leave[k] = q;
      continue;
    }
    // |p + t d| = r: t = (-pd -+ root) / dd.
    const double dd = d.squaredNorm(), pd = p.dot(d), disc = pd * pd - dd * (p.squaredNorm() - r2);
    const double root = std::sqrt(std::max(0.0, disc));
    const double t0 = (-pd - root) / dd, t1 = (-pd + root) / dd;
    if (in[k]) {
      enter[k] = p, leave[k] = p + std::clamp(t1, 0.0, 1.0) * d;
    } else if (in[(k + 1) % 4]) {
      enter[k] = p + std::clamp(t0, 0.0, 1.0) * d, leave[k] = q;
    } else if (const double e0 = std::clamp(t0, 0.0, 1.0), e1 = std::clamp(t1, 0.0, 1.0);
               disc > 0 && (e1 - e0) * std::sqrt(dd) > sliver) {  // in and out again
      enter[k] = p + e0 * d, leave[k] = p + e1 * d;
    } else {
      piece[k] = false;  // misses the disc, or touches it at a point
    }
  }
  double twice = 0;  // twice the area
  int first = -1;
  for (int k = 0; k < 4; ++k)
    if (piece[k]) {
      twice += cross(enter[k], leave[k]);
      if (first < 0) first = k;
    }
  // No edge cuts the disc: it lies inside (the centre does), or outside.
  if (first < 0)
    return a.x() <= 0 && b.x() >= 0 && a.y() <= 0 && b.y() >= 0 ? std::numbers::pi * r2 : 0.0;
  // Arcs: from where an edge's piece leaves to where the next piece enters.
  for (int k = first;;) {
    int next = (k + 1) % 4;
    while (!piece[next]) next = (next + 1) % 4;
    const Vec2 &from = leave[k], &to = enter[next];
    // A corner inside the disc ends one piece and starts the next: no arc.
    const bool sharedCorner = next == (k + 1) % 4 && in[next];
    if (!sharedCorner) {
      double t = std::atan2(cross(from, to), from.dot(to));
      if (t < 0) t += 2 * std::numbers::pi;
      if ((to - from).squaredNorm() <= same * same && next != k) t = 0;
      twice += r2 * t;
    }
    k = next;
    if (k == first) break;
  }
  return std::clamp(0.5 * twice, 0.0, (b.x() - a.x()) * (b.y() - a.y()));
}

}  // namespace sf::geometry
