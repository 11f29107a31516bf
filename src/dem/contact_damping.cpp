#include "sandflow/dem/contact_damping.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace sf::dem {
namespace {

constexpr double pi = std::numbers::pi;

// The zeta in [0, top] whose restitution is e, the restitution falling with
// zeta there; top when even top rebounds more (e out of reach).
template <class Restitution>
double solve(Restitution restitution, double e, double top) {
  if (e >= 1) return 0.0;
  if (restitution(top) >= e) return top;
  double lo = 0, hi = top;
  for (int i = 0; i < 200 && hi - lo > 1e-13 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (restitution(mid) > e ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The largest zeta searched. Signed: past critical damping nothing rebounds.
// Compressive: the rebound only tends to 0. And 2 zeta h < 0.9, the dashpot
// alone not reversing the velocity in one step (beyond, the map stops being
// monotone in zeta).
double topRatio(bool compressive, double h) {
  const double top = compressive ? 20.0 : 1.5;
  return h > 0 ? std::min(top, 0.45 / h) : top;
}

}  // namespace

double discreteRestitution(double h, double zeta, bool compressive) {
  const double k = h * h, c = 2 * zeta * h;  // per unit mass, dt = 1
  const long steps = long(8 * pi / h) + 64;  // over 4 undamped contact durations
  // The midpoint rule over entry phases: the rebound is continuous in the
  // phase (the dashpot is weighted by the part of the step the contact
  // spans), so 32 phases give the mean within 3e-5 at h = 0.28.
  constexpr int phases = 32;
  double sum = 0;
  for (int i = 0; i < phases; ++i) {
    double d = (i + 0.5) / phases, u = 1;  // overlap and approach speed
    for (long n = 0; n < steps && d > 0; ++n) {
      const double span = std::abs(u) > d ? d / std::abs(u) : 1.0;
      const double f = k * d + c * span * u;
      if (compressive && f <= 0) break;  // no force from here on: u stays
      u -= f, d += u;
    }
    sum -= u;
  }
  return sum / phases;
}

double linearRestitution(double z, bool compressive) {
  if (z <= 0) return 1.0;
  if (!compressive) return z < 1 ? std::exp(-pi * z / std::sqrt(1 - z * z)) : 0.0;
  // m* = kn = 1, approach speed 1: the contact ends where d + 2 z d' first
  // vanishes, d = exp(-z t) sin(wd t)/wd (or its overdamped form).
  if (std::abs(z - 1) < 1e-6) return std::exp(-2.0);  // d = t exp(-t): ends at t = 2
  if (z < 1) {
    const double wd = std::sqrt(1 - z * z), t = (pi - 2 * std::asin(z)) / wd;
    return -std::exp(-z * t) * (wd * std::cos(wd * t) - z * std::sin(wd * t)) / wd;
  }
  const double s = std::sqrt(z * z - 1), r1 = -z + s, r2 = -z - s;
  const double t = std::log((1 + 2 * z * r2) / (1 + 2 * z * r1)) / (2 * s);
  return -(r1 * std::exp(r1 * t) - r2 * std::exp(r2 * t)) / (2 * s);
}

double hertzRestitution(double zeta, bool compressive) {
  // m* = 1, Fn = d^1.5 + 2 zeta sqrt(kn) u with kn = 1.5 d^0.5, approach
  // speed 1 (the rebound does not depend on it), by RK4 over about 15000
  // steps of an undamped contact (duration 2.94): within 2e-6 of the rebound
  // (d^0.25 at the start slows convergence); the end interpolated linearly.
  const double c = 2 * zeta * std::sqrt(1.5), dt = 2e-4;
  auto force = [&](double d, double u) {
    return d > 0 ? d * std::sqrt(d) + c * std::sqrt(std::sqrt(d)) * u : 0.0;
  };
  auto accel = [&](double d, double u) {
    const double f = force(d, u);
    return compressive ? -std::max(f, 0.0) : -f;
  };
  // The contact goes on while this is > 0: the overlap, or the force.
  auto going = [&](double d, double u) { return compressive ? force(d, u) : d; };
  double d = 0, u = 1;
  for (int n = 0; n < 300000; ++n) {
    const double d1 = u, u1 = accel(d, u);
    const double d2 = u + 0.5 * dt * u1, u2 = accel(d + 0.5 * dt * d1, d2);
    const double d3 = u + 0.5 * dt * u2, u3 = accel(d + 0.5 * dt * d2, d3);
    const double d4 = u + dt * u3, u4 = accel(d + dt * d3, d4);
    const double before = going(d, u), uBefore = u;
    d += dt / 6 * (d1 + 2 * d2 + 2 * d3 + d4);
    u += dt / 6 * (u1 + 2 * u2 + 2 * u3 + u4);
    const double after = going(d, u);
    if (n > 0 && after <= 0) {
      const double s = before / (before - after);
      return -(uBefore + s * (u - uBefore));
    }
  }
  return -u;  // overdamped, still in
}

DampingRatios::Table& DampingRatios::table(double e, bool compressive) {
  auto is = [&](const Table& t) { return t.e == e && t.compressive == compressive; };
  if (last_ < tables_.size() && is(tables_[last_])) return tables_[last_];
  for (last_ = 0; last_ < tables_.size(); ++last_)
    if (is(tables_[last_])) return tables_[last_];
  const double unsolved = std::numeric_limits<double>::quiet_NaN();
  const int nodes = int(largestSolvedStep / stepNode) + 2;
  tables_.push_back({e, compressive, unsolved, unsolved, std::vector<double>(nodes, unsolved)});
  return tables_.back();
}

double DampingRatios::continuous(Table& t) {
  if (std::isnan(t.continuous)) {
    const double e = t.e;
    if (e <= 0 && !t.compressive)
      t.continuous = 1.0;  // critical damping: no rebound
    else if (!t.compressive)
      t.continuous = -std::log(e) / std::sqrt(pi * pi + std::log(e) * std::log(e));
    else
      t.continuous =
          solve([&](double x) { return linearRestitution(x, true); }, e, topRatio(true, 0));
  }
  return t.continuous;
}

double DampingRatios::node(Table& t, int j) {
  double& z = t.nodes[j];
  if (std::isnan(z)) {
    const double h = j * stepNode;
    z = t.e <= 0 && !t.compressive
            ? 1.0
            : solve([&](double x) { return discreteRestitution(h, x, t.compressive); }, t.e,
                    topRatio(t.compressive, h));
  }
  return z;
}

double DampingRatios::linear(double e, bool compressive, double h) {
  Table& t = table(e, compressive);
  if (!(h > 0) || h > largestSolvedStep) return continuous(t);  // NaN and infinity too
  const double at = h / stepNode;                               // exact: stepNode is a power of 2
  if (at < firstNode) {
    const double z0 = continuous(t);
    return z0 + (node(t, firstNode) - z0) * (at / firstNode);
  }
  const int j = int(at);
  const double z0 = node(t, j);
  return z0 + (node(t, j + 1) - z0) * (at - j);
}

double DampingRatios::hertz(double e, bool compressive) {
  Table& t = table(e, compressive);
  if (std::isnan(t.hertz))
    t.hertz = e <= 0 && !compressive
                  ? 1.0
                  : solve([&](double x) { return hertzRestitution(x, compressive); }, e,
                          topRatio(compressive, 0));
  return t.hertz;
}

}  // namespace sf::dem
