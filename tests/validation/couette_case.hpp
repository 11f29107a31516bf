#pragma once
// Cylindrical Couette flow (thesis case B, §5.1), shared by the kernel test and
// the full validation driver: an inner cylinder of radius r1 and an outer one
// of radius r2 in a 1 x 1 periodic lattice, both circular walls of the lattice
// (lattice obstacle circle) turning at omega1 and omega2 and translating
// together.
#include <chrono>
#include <cmath>
#include <numbers>
#include <vector>

#include "sandflow/sim/manager.hpp"

namespace sf::validation {

struct CouetteSetup {
  int cells = 40;  // across the unit square
  double tau = 1.0;
  double nu = 4.166e-2;
  double r1 = 0.1, r2 = 0.3;
  double omega1 = 0.0, omega2 = 0.1;
  Vec2 translate = Vec2::Zero();  // both cylinders
  double time = 2.5;              // physical time to run
  Vec2 origin = Vec2::Zero();     // lattice origin (-h/2: nodes on multiples of h)
  coupling::Settings coupling;
};

struct CouetteResult {
  double velocityError = 0;  // relative L2 over the fluid nodes between the walls
  double maxError = 0;       // largest |u - u_exact| / (omega2 r2 + |omega1| r1)
  double torqueError = 0;    // relative, on the inner cylinder
  double netForce = 0;       // |force| on the inner cylinder / (exact torque / r1)
  double torque = 0, exactTorque = 0;
  long steps = 0;
  double seconds = 0;
};

inline double couetteSpeed(const CouetteSetup& s, double r) {
  const double d = s.r2 * s.r2 - s.r1 * s.r1;
  const double A = (s.omega2 * s.r2 * s.r2 - s.omega1 * s.r1 * s.r1) / d;
  const double B = (s.omega1 - s.omega2) * s.r1 * s.r1 * s.r2 * s.r2 / d;
  return A * r + B / r;
}

inline double couetteTorque(const CouetteSetup& s) {
  return 4 * std::numbers::pi * 1.0 * s.nu * (s.omega2 - s.omega1) * s.r1 * s.r1 * s.r2 * s.r2 /
         (s.r2 * s.r2 - s.r1 * s.r1);
}

// The manager holding the cell, ready to run (inner obstacle id 0).
inline void buildCouette(sim::Manager& m, const CouetteSetup& s) {
  lb::LatticeDef def;
  def.origin = s.origin;
  def.size = Vec2(1, 1);
  def.cells = s.cells;
  def.viscosity = s.nu;
  def.tau = s.tau;
  for (auto& side : def.sides) side = lb::SideDef{lb::SideKind::periodic};
  m.createLattice(def);
  m.setCouplingSettings(s.coupling);
  lb::Lattice& l = m.lattice();
  l.addCircle({0, Vec2(0.5, 0.5), s.r1, false, s.translate, s.omega1});
  l.addCircle({1, Vec2(0.5, 0.5), s.r2, true, s.translate, s.omega2});
}

inline CouetteResult measureCouette(const sim::Manager& m, const CouetteSetup& s) {
  const lb::Lattice& l = m.lattice();
  const Vec2 c = l.circles()[0].centre;
  double err = 0, norm = 0, worst = 0;
  for (int j = 0; j < l.ny(); ++j)
    for (int i = 0; i < l.nx(); ++i) {
      if (l.solidRatio(i, j) > 0) continue;
      Vec2 d = l.position(i, j) - c;
      d -= Vec2(std::round(d.x()), std::round(d.y()));  // nearest periodic image
      const double r = d.norm();
      if (r <= s.r1 || r >= s.r2) continue;
      const Vec2 swirl = couetteSpeed(s, r) * Vec2(-d.y(), d.x()) / r;
      const Vec2 e = l.velocity(i, j) - (s.translate + swirl);
      err += e.squaredNorm();
      norm += swirl.squaredNorm();
      worst = std::max(worst, e.norm());
    }
  CouetteResult out;
  const lb::ObstacleInfo in = l.obstacleInfo(0);
  out.exactTorque = couetteTorque(s);
  out.torque = in.torque;
  out.velocityError = std::sqrt(err / norm);
  out.maxError = worst / (s.omega2 * s.r2 + std::abs(s.omega1) * s.r1);
  out.torqueError = std::abs(in.torque - out.exactTorque) / std::abs(out.exactTorque);
  out.netForce = in.force.norm() * s.r1 / std::abs(out.exactTorque);
  return out;
}

inline CouetteResult runCouette(const CouetteSetup& s) {
  sim::Manager m;
  buildCouette(m, s);
  const long steps = std::lround(s.time / m.lattice().params().dt);
  const auto t0 = std::chrono::steady_clock::now();
  for (long k = 0; k < steps; ++k) m.step();
  CouetteResult r = measureCouette(m, s);
  r.steps = steps;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

// u_t = nu (u_rr + u_r / r - u / r^2) on [r1, r2], u(r1) = 0, u(r2) = omega2 r2
// from rest, Crank-Nicolson on n intervals: the profile at each requested time.
inline std::vector<std::vector<double>> stokesLayer(const CouetteSetup& s,
                                                    const std::vector<double>& times, int n,
                                                    double& dr) {
  dr = (s.r2 - s.r1) / n;
  std::vector<double> u(n + 1, 0.0), r(n + 1);
  for (int k = 0; k <= n; ++k) r[k] = s.r1 + k * dr;
  u[n] = s.omega2 * s.r2;
  std::vector<std::vector<double>> out;
  double t = 0;
  const double dtMax = 0.25 * dr * dr / s.nu * 50;  // CN is stable; keep it accurate
  for (double target : times) {
    const int steps = std::max(1, int(std::ceil((target - t) / dtMax)));
    const double dt = (target - t) / steps;
    for (int step = 0; step < steps; ++step) {
      // (I - dt/2 L) u' = (I + dt/2 L) u; L u_k = nu (a u_{k-1} + b u_k + c u_{k+1})
      std::vector<double> a(n + 1), b(n + 1), c(n + 1), d(n + 1);
      for (int k = 1; k < n; ++k) {
        const double lo = 1 / (dr * dr) - 1 / (2 * r[k] * dr),
                     hi = 1 / (dr * dr) + 1 / (2 * r[k] * dr);
        const double mid = -2 / (dr * dr) - 1 / (r[k] * r[k]);
        const double h = 0.5 * dt * s.nu;
        a[k] = -h * lo, b[k] = 1 - h * mid, c[k] = -h * hi;
        d[k] = u[k] + h * (lo * u[k - 1] + mid * u[k] + hi * u[k + 1]);
      }
      d[1] -= a[1] * u[0];
      d[n - 1] -= c[n - 1] * u[n];
      for (int k = 2; k < n; ++k) {  // Thomas
        const double w = a[k] / b[k - 1];
        b[k] -= w * c[k - 1];
        d[k] -= w * d[k - 1];
      }
      u[n - 1] = d[n - 1] / b[n - 1];
      for (int k = n - 2; k >= 1; --k) u[k] = (d[k] - c[k] * u[k + 1]) / b[k];
    }
    t = target;
    out.push_back(u);
  }
  return out;
}

// The transient of §5.1: h = 6.25e-3, the impulsively started outer cylinder,
// relative L2 errors along theta = 90 degrees (31 interior nodes) at t = 10
// and 20 steps of dt = 1.5625e-4, with dt (tau = 1) or dt/2 (tau = 0.75, the
// same viscosity), against Crank-Nicolson on 4000 intervals.
struct TransientErrors {
  double dt, tau, at10, at20;
};

inline TransientErrors transientErrors(bool halfStep) {
  const double h = 6.25e-3, dt0 = 1.5625e-4;
  CouetteSetup s;
  s.cells = 160;
  s.origin = Vec2(-0.5 * h, -0.5 * h);  // nodes at multiples of h: r = k h on the vertical
  s.tau = halfStep ? 0.75 : 1.0;
  const double dt = halfStep ? dt0 / 2 : dt0;
  s.nu = (2 * s.tau - 1) / 6 * h * h / dt;
  sim::Manager m;
  buildCouette(m, s);
  const std::vector<double> times = {10 * dt0, 20 * dt0};
  double dr = 0;
  const int n = 4000;
  const auto fd = stokesLayer(s, times, n, dr);
  double errs[2];
  long done = 0;
  for (int q = 0; q < 2; ++q) {
    const long target = std::lround(times[q] / dt);
    for (; done < target; ++done) m.step();
    double e = 0, norm = 0;
    for (int k = 17; k <= 47; ++k) {  // r = k h, r1 = 16 h, r2 = 48 h
      const double r = k * h;
      const auto node = m.lattice().nodeAt(Vec2(0.5, 0.5 + r));
      const double lb = -m.lattice().velocity(node->first, node->second).x();
      const double x = (r - s.r1) / dr;
      const int i = std::min(n - 1, int(x));
      const double ref = fd[q][i] + (x - i) * (fd[q][i + 1] - fd[q][i]);
      e += (lb - ref) * (lb - ref);
      norm += ref * ref;
    }
    errs[q] = std::sqrt(e / norm);
  }
  return {dt, s.tau, errs[0], errs[1]};
}

}  // namespace sf::validation
