#include "sandflow/dem/shape_checks.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "sandflow/core/error.hpp"

namespace sf::dem {
namespace {

[[noreturn]] void refuse(const std::string& message) {
  throw Error("VALUE VERTICES", message);
}

std::string number(std::size_t k) {
  return std::to_string(k + 1);  // vertices are numbered from 1
}

std::string pair(double x, double y) {
  std::string s = "{";  // appended, not "{" + ...: GCC 12 warns falsely (-Wrestrict) on that
  s += formatNumber(x);
  s += ' ';
  s += formatNumber(y);
  s += '}';
  return s;
}

double cross(const Vec2& u, const Vec2& v) {
  return u.x() * v.y() - u.y() * v.x();
}

// Whether segments p1-p2 and p3-p4 meet (cross, or touch within `tol`).
bool meet(const Vec2& p1, const Vec2& p2, const Vec2& p3, const Vec2& p4, double tol) {
  const double d1 = cross(p4 - p3, p1 - p3), d2 = cross(p4 - p3, p2 - p3);
  const double d3 = cross(p2 - p1, p3 - p1), d4 = cross(p2 - p1, p4 - p1);
  if (((d1 > tol && d2 < -tol) || (d1 < -tol && d2 > tol)) &&
      ((d3 > tol && d4 < -tol) || (d3 < -tol && d4 > tol)))
    return true;
  // A point within tol of the line through the other segment, and inside it.
  auto on = [tol](const Vec2& a, const Vec2& b, const Vec2& p, double d) {
    return std::abs(d) <= tol && (p - a).dot(b - a) >= -tol && (p - b).dot(a - b) >= -tol;
  };
  return on(p3, p4, p1, d1) || on(p3, p4, p2, d2) || on(p1, p2, p3, d3) || on(p1, p2, p4, d4);
}

// The first pair of edges that are not neighbours and meet, as "i-j and k-l";
// "" for a simple outline. O(n^2): it runs only for outlines that are not
// convex, to say which of the two they are.
std::string crossingEdges(const std::vector<Vec2>& q) {
  const std::size_t n = q.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours across the wrap
      if (meet(q[i], q[(i + 1) % n], q[j], q[(j + 1) % n], 1e-12))
        return number(i) + "-" + number((i + 1) % n) + " and " + number(j) + "-" +
               number((j + 1) % n);
    }
  return "";
}

}  // namespace

void checkConvexOutline(const std::vector<Vec2>& v) {
  const std::size_t n = v.size();
  if (n < 3) refuse("a polygon needs at least 3 vertices, got " + std::to_string(n));
  for (std::size_t k = 0; k < n; ++k)
    if (!v[k].allFinite())
      refuse("polygon vertex " + number(k) + " is not finite: " + pair(v[k].x(), v[k].y()));

  // Work in the unit box about the outline's middle: every tolerance below is
  // then relative to its size, wherever it lies and whatever the units.
  Vec2 lo = v[0], hi = v[0];
  for (const Vec2& p : v) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double scale = (hi - lo).maxCoeff();
  if (!std::isfinite(scale))
    refuse("polygon is too large: its vertices span more than a double holds");
  if (scale == 0) refuse("polygon vertices are all one point: it has no area");
  const Vec2 middle = lo + 0.5 * (hi - lo);
  std::vector<Vec2> q(n);
  for (std::size_t k = 0; k < n; ++k) q[k] = (v[k] - middle) / scale;

  for (std::size_t k = 0; k < n; ++k)
    if ((q[(k + 1) % n] - q[k]).norm() <= 1e-12)
      refuse("polygon vertices " + number(k) + " and " + number((k + 1) % n) +
             " are the same point: give each corner once");

  // All on one line (to 1e-10 of the size): no area, whatever the order.
  std::size_t far = 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((q[k] - q[0]).norm() > (q[far] - q[0]).norm()) far = k;
  const Vec2 axis = (q[far] - q[0]).normalized();
  bool oneLine = true;
  for (std::size_t k = 0; k < n && oneLine; ++k)
    oneLine = std::abs(cross(axis, q[k] - q[0])) <= kStraightTurn;
  if (oneLine) refuse("polygon vertices are all on one line: it has no area");

  // The turn at each vertex, from the edge that arrives to the edge that leaves.
  std::vector<double> turn(n);
  int left = 0, right = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t before = (k + n - 1) % n, after = (k + 1) % n;
    const Vec2 in = (q[k] - q[before]).normalized(), out = (q[after] - q[k]).normalized();
    const double s = cross(in, out), c = in.dot(out);
    if (std::abs(s) <= kStraightTurn) {
      if (c > 0)
        refuse("polygon vertex " + number(k) + " lies on the straight line from vertex " +
               number(before) + " to vertex " + number(after) + ": leave it out");
      refuse("polygon outline doubles back on itself at vertex " + number(k) +
             " (self-intersecting)");
    }
    turn[k] = std::atan2(s, c);
    (s > 0 ? left : right) += 1;
  }

  if (left > 0 && right > 0) {
    const std::string edges = crossingEdges(q);
    if (!edges.empty())
      refuse("polygon outline crosses itself (self-intersecting): edges " + edges + " meet");
    // Simple but not convex: the first vertex that turns against the outline's
    // way round (the sign of its area).
    double area = 0;
    for (std::size_t k = 0; k < n; ++k) area += cross(q[k], q[(k + 1) % n]);
    for (std::size_t k = 0; k < n; ++k)
      if ((turn[k] > 0) != (area > 0)) refuse("polygon is not convex at vertex " + number(k));
  }

  // Turning one way, the outline goes round a whole number of times; only
  // once is it convex. More is a star or an outline traced twice.
  double total = 0;
  for (double t : turn) total += t;
  const long rounds = std::lround(std::abs(total) / (2 * std::numbers::pi));
  if (rounds != 1)
    refuse("polygon outline winds " + std::to_string(rounds) +
           " times around (self-intersecting): a convex outline goes round once");
}

void checkSemiAxes(double a, double b, const char* shape) {
  if (!(a > 0 && b > 0) || !std::isfinite(a) || !std::isfinite(b))
    throw Error("VALUE AXES",
                std::string(shape) + " semi-axes must be finite and > 0, got " + pair(a, b));
  const double ratio = std::max(a, b) / std::min(a, b);
  if (!(ratio <= kMaxAxisRatio))
    throw Error("VALUE AXES", std::string(shape) + " semi-axes " + pair(a, b) +
                                  " differ by a factor of " + formatNumber(ratio) + ": at most " +
                                  formatNumber(kMaxAxisRatio) + " is allowed");
}

void checkExponents(double m, double n) {
  if (!(m >= kMinExponent && m <= kMaxExponent && n >= kMinExponent && n <= kMaxExponent))
    throw Error("VALUE EXPONENTS",
                "superquadric exponents must be " + formatNumber(kMinExponent) + " to " +
                    formatNumber(kMaxExponent) + " (1 a lozenge, 2 an ellipse, " +
                    formatNumber(kMaxExponent) + " nearly a box; below 1 it is not convex), got " +
                    pair(m, n));
}

}  // namespace sf::dem
