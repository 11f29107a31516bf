#pragma once
// The local collision of one node, in lattice units (h = dt = 1, c_s^2 = 1/3),
// shared by the bulk fluid loop and every boundary kind that collides. Inline and
// branch-free on the hot path so that the bulk loop vectorizes.
//
// BGK:  f_i <- f_i - omega (f_i - f_i^eq) + S_i
// TRT:  the symmetric and antisymmetric parts relax with omega+ = 1/tau and
//       omega- chosen from the "magic" product Lambda = (1/omega+ - 1/2)(1/omega- - 1/2).
// Forcing (force density F per node):
//   nodal (thesis): S_i = 3 w_i e_i.F, velocity u = sum(f e)/rho;
//   Guo (2002):     S_i = (1 - omega/2) w_i [3 (e_i - u).F + 9 (e_i.u)(e_i.F)],
//                   velocity u = (sum(f e) + F/2)/rho; second order in time.
#include "sandflow/lb/d2q9.hpp"

namespace sf::lb {

enum class Collision { bgk, trt };
enum class ForceScheme { nodal, guo };

struct CollisionParams {
  double omegaPlus = 1.0;     // 1/tau
  double omegaMinus = 1.0;    // TRT only
  double fx = 0.0, fy = 0.0;  // force density per node, lattice units
};

// Equilibrium f_i^eq(rho, u) for the standard D2Q9 second-order expansion.
inline double equilibrium(int i, double rho, double ux, double uy) {
  const double eu = d2q9::ex[i] * ux + d2q9::ey[i] * uy;
  return d2q9::w[i] * rho * (1.0 + 3.0 * eu + 4.5 * eu * eu - 1.5 * (ux * ux + uy * uy));
}

// Velocity that enters the equilibrium, from density and the raw first moment.
template <ForceScheme S>
inline void velocityFromMoments(double rho, double jx, double jy, const CollisionParams& p,
                                double& ux, double& uy) {
  const double inv = 1.0 / rho;
  if constexpr (S == ForceScheme::guo) {
    ux = (jx + 0.5 * p.fx) * inv;
    uy = (jy + 0.5 * p.fy) * inv;
  } else {
    ux = jx * inv;
    uy = jy * inv;
  }
}

// Collides f in place. Returns the density; u2 receives |u|^2 (lattice units).
template <Collision C, ForceScheme S>
inline double collide(double (&f)[d2q9::Q], const CollisionParams& p, double& u2) {
  using namespace d2q9;
  double rho = 0.0, jx = 0.0, jy = 0.0;
#pragma GCC unroll 9
  for (int i = 0; i < Q; ++i) {
    rho += f[i];
    jx += ex[i] * f[i];
    jy += ey[i] * f[i];
  }
  double ux, uy;
  velocityFromMoments<S>(rho, jx, jy, p, ux, uy);
  u2 = ux * ux + uy * uy;

  // sym[i]: the symmetric part of the Guo source (zero for nodal forcing); the
  // antisymmetric part is 3 w_i e_i.F for both schemes.
  double feq[Q], sym[Q], anti[Q];
#pragma GCC unroll 9
  for (int i = 0; i < Q; ++i) {
    feq[i] = equilibrium(i, rho, ux, uy);
    anti[i] = 3.0 * w[i] * (ex[i] * p.fx + ey[i] * p.fy);
    if constexpr (S == ForceScheme::guo) {
      const double eu = ex[i] * ux + ey[i] * uy;
      sym[i] = w[i] * (9.0 * eu * (ex[i] * p.fx + ey[i] * p.fy) - 3.0 * (ux * p.fx + uy * p.fy));
    } else {
      sym[i] = 0.0;
    }
  }

  if constexpr (C == Collision::bgk) {
    const double om = p.omegaPlus;
    const double g = (S == ForceScheme::guo) ? 1.0 - 0.5 * om : 1.0;
#pragma GCC unroll 9
    for (int i = 0; i < Q; ++i) f[i] += -om * (f[i] - feq[i]) + g * (anti[i] + sym[i]);
  } else {
    const double op = p.omegaPlus, om = p.omegaMinus;
    const double gp = (S == ForceScheme::guo) ? 1.0 - 0.5 * op : 1.0;
    const double gm = (S == ForceScheme::guo) ? 1.0 - 0.5 * om : 1.0;
    f[0] += -op * (f[0] - feq[0]) + gp * sym[0];
#pragma GCC unroll 4
    for (int i = 1; i <= 4; ++i) {
      const int o = i + 4;  // opposite of i
      const double dp = -op * 0.5 * (f[i] + f[o] - feq[i] - feq[o]) + gp * sym[i];
      const double dm = -om * 0.5 * (f[i] - f[o] - feq[i] + feq[o]) + gm * anti[i];
      f[i] += dp + dm;
      f[o] += dp - dm;
    }
  }
  return rho;
}

}  // namespace sf::lb
