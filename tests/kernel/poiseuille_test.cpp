// Plane Poiseuille flow driven by a body force between no-slip walls at y = 0
// and y = H (halfway bounce-back): u(y) = F / (2 rho nu) y (H - y).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "lattice_helpers.hpp"

namespace sf {
namespace {

using lb::Collision;
using lb::ForceScheme;

double poiseuilleError(int ny, Collision c, ForceScheme s, double tau, bool slipTop = false) {
  lb::LatticeDef def = test::channelDef(4, ny, tau);
  def.collision = c;
  def.forceScheme = s;
  const double nu = *def.viscosity, rho = def.density;
  // Peak velocity ~ 0.02 of the lattice speed whatever the resolution.
  const double dt = (2 * tau - 1) / 6 / nu;  // h = 1
  const double umax = 0.02 / dt;
  const double H = ny;
  const double F = 8 * rho * nu * umax / (H * H);
  def.forcing = Vec2(F, 0);
  if (slipTop) def.sides[lb::top] = lb::SideDef{lb::SideKind::slip};
  lb::Lattice lattice(lb::resolve(def));
  test::runToSteady(lattice, 1e-15, 400000);
  if (slipTop)  // symmetry plane at y = H: half of a channel of width 2H
    return test::profileError(lattice, 1,
                              [&](double y) { return F / (2 * rho * nu) * y * (2 * H - y); });
  return test::profileError(lattice, 1, [&](double y) { return F / (2 * rho * nu) * y * (H - y); });
}

TEST(Poiseuille, TrtMagicWithGuoForcingIsExact) {
  for (double tau : {0.6, 1.0, 2.0})
    EXPECT_LE(poiseuilleError(16, Collision::trt, ForceScheme::guo, tau), 1e-10) << "tau " << tau;
}

TEST(Poiseuille, SlipTopIsASymmetryPlane) {
  EXPECT_LE(poiseuilleError(16, Collision::trt, ForceScheme::guo, 1.0, true), 1e-10);
}

TEST(Poiseuille, BgkAtTauOneConvergesSecondOrder) {
  double previous = 0;
  for (int ny : {8, 16, 32, 64}) {
    const double e = poiseuilleError(ny, Collision::bgk, ForceScheme::nodal, 1.0);
    std::printf("BGK nodal tau=1 ny=%d: relative error %.3e", ny, e);
    if (previous > 0) {
      const double order = std::log2(previous / e);
      std::printf("  order %.3f", order);
      EXPECT_NEAR(order, 2.0, 0.1) << "ny " << ny;
    }
    std::printf("\n");
    EXPECT_GT(e, 1e-8) << "BGK at tau = 1 is not exact: the wall is off halfway";
    previous = e;
  }
}

TEST(Poiseuille, GuoForcingAlsoSecondOrderWithBgk) {
  const double coarse = poiseuilleError(16, Collision::bgk, ForceScheme::guo, 1.0);
  const double fine = poiseuilleError(32, Collision::bgk, ForceScheme::guo, 1.0);
  EXPECT_NEAR(std::log2(coarse / fine), 2.0, 0.1);
}

}  // namespace
}  // namespace sf
