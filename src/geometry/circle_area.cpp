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

namespace sf::geometry {

// The disc's height inside the band at t = x - cx is
//   clamp(s, y0 - cy, y1 - cy) + clamp(s, -(y1 - cy), -(y0 - cy)),
// zero where the disc misses the band; each term is constant or s(t) between
// the breakpoints where s meets its bounds.
DiscBand::DiscBand(const Vec2& c, double r, double y0, double y1) : cx_(c.x()), r_(r) {
  const double p0 = y0 - c.y(), p1 = y1 - c.y();
  above_ = clamped(p0, p1);
  below_ = clamped(-p1, -p0);
}

[[gnu::always_inline]] inline double DiscBand::s(double t) const {
  return std::sqrt(std::max(0.0, (r_ - t) * (r_ + t)));
}

DiscBand::Clamped DiscBand::clamped(double lo, double hi) const {
  Clamped c{lo, hi, r_, 0.0};
  if (lo > 0 && lo < r_) c.tl = s(lo);
  if (hi > 0 && hi < r_) c.th = s(hi);
  return c;
}

// (q s_q - p s_p + r^2 (asin(q/r) - asin(p/r))) / 2, each difference written
// as (q - p) times a well-conditioned factor: no cancellation however close
// p and q are, or however large the disc is against the cell.
[[gnu::always_inline]] inline double DiscBand::arc(double p, double q, double sp, double sq) const {
  if (!(q > p)) return 0.0;
  const double d = q - p, sum = sp + sq;
  if (!(sum > 0)) return 0.0;             // p = q = +-r
  const double k = (p + q) / sum;         // (s_p - s_q) / (q - p)
  const double chord = d * (sq - p * k);  // q s_q - p s_p
  const double angle = std::asin(std::clamp(d * (sp + p * k) / (r_ * r_), -1.0, 1.0));
  return 0.5 * (chord + r_ * r_ * angle);
}

[[gnu::always_inline]] inline double DiscBand::part(const Clamped& c, double a, double b, double sa,
                                                    double sb) const {
  if (c.hi <= 0) return c.hi * (b - a);
  if (c.lo >= r_) return c.lo * (b - a);
  auto overlap = [&](double lo, double hi) {
    return std::max(0.0, std::min(b, hi) - std::max(a, lo));
  };
  // lo on [-r, -tl] and [tl, r], s on [-tl, -th] and [th, tl], hi on [-th, th].
  double sum = c.lo * (overlap(-r_, -c.tl) + overlap(c.tl, r_)) + c.hi * overlap(-c.th, c.th);
  const double sTl = c.tl < r_ ? c.lo : 0.0, sTh = c.th > 0 ? c.hi : r_;  // s at the breakpoints
  // An arc's end is a breakpoint or the cell's edge a or b.
  auto end = [&](double t, double at, double known) { return t == at ? known : t == a ? sa : sb; };
  if (const double p = std::max(a, -c.tl), q = std::min(b, -c.th); q > p)
    sum += arc(p, q, end(p, -c.tl, sTl), end(q, -c.th, sTh));
  if (const double p = std::max(a, c.th), q = std::min(b, c.tl); q > p)
    sum += arc(p, q, end(p, c.th, sTh), end(q, c.tl, sTl));
  return sum;
}

[[gnu::always_inline]] inline double DiscBand::between(double a, double b, double sa,
                                                       double sb) const {
  return b > a ? std::max(0.0, part(above_, a, b, sa, sb) + part(below_, a, b, sa, sb)) : 0.0;
}

double DiscBand::area(double xa, double xb) const {
  const double a = std::clamp(xa - cx_, -r_, r_), b = std::clamp(xb - cx_, -r_, r_);
  return between(a, b, s(a), s(b));
}

void DiscBand::areas(double x0, double h, int first, int last, double* out) const {
  if (first > last) return;
  double a = std::clamp(x0 + first * h - cx_, -r_, r_), sa = s(a);
  for (int i = first; i <= last; ++i) {
    const double b = std::clamp(x0 + (i + 1) * h - cx_, -r_, r_), sb = s(b);
    out[i - first] = between(a, b, sa, sb);
    a = b, sa = sb;
  }
}

}  // namespace sf::geometry
