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
//
// Directions i and -i (= i + 4) are relaxed together: their equilibria share
// the even part w rho (1 - 3/2 u.u + 9/2 (e.u)^2) and differ in the sign of the
// odd part 3 w rho e.u. The populations travel as nine scalars, not an array:
// inside an `omp simd` loop an array becomes per-lane memory and the loop runs at
// two thirds of the speed.
#include "sandflow/lb/d2q9.hpp"

namespace sf::lb {

// Inlined whatever the caller's instruction set (kernel_isa.hpp): a call from a
// vector loop would stop it vectorizing.
#define SF_ALWAYS_INLINE [[gnu::always_inline]] inline

enum class Collision { bgk, trt };
enum class ForceScheme { nodal, guo };

struct CollisionParams {
  double omegaPlus = 1.0;     // 1/tau
  double omegaMinus = 1.0;    // TRT only
  double fx = 0.0, fy = 0.0;  // force density per node, lattice units
};

// Equilibrium f_i^eq(rho, u) for the standard D2Q9 second-order expansion.
SF_ALWAYS_INLINE double equilibrium(int i, double rho, double ux, double uy) {
  const double eu = d2q9::ex[i] * ux + d2q9::ey[i] * uy;
  return d2q9::w[i] * rho * (1.0 + 3.0 * eu + 4.5 * eu * eu - 1.5 * (ux * ux + uy * uy));
}

// All nine equilibria at once, sharing the even and odd parts of each pair.
SF_ALWAYS_INLINE void equilibria(double rho, double ux, double uy, double (&feq)[d2q9::Q]) {
  const double even = 1.0 - 1.5 * (ux * ux + uy * uy);
  feq[0] = d2q9::w[0] * rho * even;
  for (int i = 1; i <= 4; ++i) {
    const double eu = d2q9::ex[i] * ux + d2q9::ey[i] * uy;
    const double wr = d2q9::w[i] * rho, e = even + 4.5 * eu * eu, o = 3.0 * eu;
    feq[i] = wr * (e + o);
    feq[i + 4] = wr * (e - o);
  }
}

// Velocity that enters the equilibrium, from density and the raw first moment.
template <ForceScheme S>
SF_ALWAYS_INLINE void velocityFromMoments(double rho, double jx, double jy,
                                          const CollisionParams& p, double& ux, double& uy) {
  const double inv = 1.0 / rho;
  if constexpr (S == ForceScheme::guo) {
    ux = (jx + 0.5 * p.fx) * inv;
    uy = (jy + 0.5 * p.fy) * inv;
  } else {
    ux = jx * inv;
    uy = jy * inv;
  }
}

namespace detail {

struct NodeMoments {
  double rho, ux, uy;
  double even;  // 1 - 3/2 u.u
  double uF;    // u.F (Guo only)
};

// Relaxes the pair (I, I + 4), 1 <= I <= 4.
template <Collision C, ForceScheme S, int I>
SF_ALWAYS_INLINE void relaxPair(double& fi, double& fo, const NodeMoments& n,
                                const CollisionParams& p) {
  constexpr double wi = d2q9::w[I];
  constexpr int cx = d2q9::ex[I], cy = d2q9::ey[I];
  const double eu = cx * n.ux + cy * n.uy;
  const double eF = cx * p.fx + cy * p.fy;
  const double even = n.even + 4.5 * eu * eu, odd = 3.0 * eu;
  const double anti = 3.0 * wi * eF;  // antisymmetric source, both schemes
  const double sym = S == ForceScheme::guo ? wi * (9.0 * eu * eF - 3.0 * n.uF) : 0.0;
  const double op = p.omegaPlus;
  if constexpr (C == Collision::bgk) {
    const double g = S == ForceScheme::guo ? 1.0 - 0.5 * op : 1.0;
    const double keep = 1.0 - op, r = op * wi * n.rho;
    const double si = g * (sym + anti), so = g * (sym - anti);
    fi = keep * fi + r * (even + odd) + si;
    fo = keep * fo + r * (even - odd) + so;
  } else {
    // P = omega+ (f+ - f+eq), M = omega- (f- - f-eq), f+- = (fi +- fo)/2.
    const double om = p.omegaMinus;
    const double P = 0.5 * op * (fi + fo) - op * wi * n.rho * even;
    const double M = 0.5 * om * (fi - fo) - om * wi * n.rho * odd;
    if constexpr (S == ForceScheme::guo) {
      const double s = (1.0 - 0.5 * op) * sym, a = (1.0 - 0.5 * om) * anti;
      fi = fi - P - M + (s + a);
      fo = fo - P + M + (s - a);
    } else {
      fi = fi - P - M + anti;
      fo = fo - P + M - anti;
    }
  }
}

}  // namespace detail

// Collides the nine populations of one node in place. Returns the density; u2
// receives |u|^2 (lattice units).
template <Collision C, ForceScheme S>
SF_ALWAYS_INLINE double collide(double& f0, double& f1, double& f2, double& f3, double& f4,
                                double& f5, double& f6, double& f7, double& f8,
                                const CollisionParams& p, double& u2) {
  const double rho = f0 + f1 + f2 + f3 + f4 + f5 + f6 + f7 + f8;
  const double jx = f1 + f2 + f8 - f4 - f5 - f6;
  const double jy = f2 + f3 + f4 - f6 - f7 - f8;
  double ux, uy;
  velocityFromMoments<S>(rho, jx, jy, p, ux, uy);
  u2 = ux * ux + uy * uy;
  const detail::NodeMoments n{rho, ux, uy, 1.0 - 1.5 * u2, ux * p.fx + uy * p.fy};
  // The rest population: no odd part; only Guo's symmetric source reaches it.
  const double op = p.omegaPlus;
  const double rest = (1.0 - op) * f0 + op * d2q9::w[0] * rho * n.even;
  if constexpr (S == ForceScheme::guo)
    f0 = rest - (1.0 - 0.5 * op) * 3.0 * d2q9::w[0] * n.uF;
  else
    f0 = rest;
  detail::relaxPair<C, S, 1>(f1, f5, n, p);
  detail::relaxPair<C, S, 2>(f2, f6, n, p);
  detail::relaxPair<C, S, 3>(f3, f7, n, p);
  detail::relaxPair<C, S, 4>(f4, f8, n, p);
  return rho;
}

template <Collision C, ForceScheme S>
SF_ALWAYS_INLINE double collide(double (&f)[d2q9::Q], const CollisionParams& p, double& u2) {
  return collide<C, S>(f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8], p, u2);
}

// The same chosen at run time, for work off the hot path.
inline double collide(Collision c, ForceScheme s, double (&f)[d2q9::Q], const CollisionParams& p,
                      double& u2) {
  const bool guo = s == ForceScheme::guo;
  if (c == Collision::bgk)
    return guo ? collide<Collision::bgk, ForceScheme::guo>(f, p, u2)
               : collide<Collision::bgk, ForceScheme::nodal>(f, p, u2);
  return guo ? collide<Collision::trt, ForceScheme::guo>(f, p, u2)
             : collide<Collision::trt, ForceScheme::nodal>(f, p, u2);
}

}  // namespace sf::lb
