// Issue 37's sides: a velocity side's parabolic profile and ramp, and the
// outflow side, whose reflection of a vortex that leaves through it is held
// well below a Zou-He pressure side's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "lattice_helpers.hpp"

namespace sf {
namespace {

// Lattice units (h = dt = 1): viscosity (2 tau - 1) / 6.
lb::LatticeDef unitLattice(int nx, int ny, double tau) {
  return test::channelDef(nx, ny, tau, (2 * tau - 1) / 6);
}

TEST(OpenSides, ParabolicInletPeaksMidwayAndVanishesAtTheEnds) {
  const int nx = 24, ny = 20;
  lb::LatticeDef def = unitLattice(nx, ny, 0.8);
  const double U = 0.05;
  def.sides[lb::left] = lb::SideDef{lb::SideKind::velocity, Vec2(U, 0.01)};
  def.sides[lb::left].profile = lb::SideProfile::parabolic;
  def.sides[lb::right] = lb::SideDef{lb::SideKind::outflow};
  lb::Lattice lattice(lb::resolve(def));
  for (int k = 0; k < 3; ++k) lattice.step();
  for (int j = 0; j < ny; ++j) {
    const double s = j + 0.5, shape = 4 * s * (ny - s) / (ny * ny);
    EXPECT_NEAR(lattice.velocity(0, j).x(), U * shape, 1e-14) << j;
    EXPECT_NEAR(lattice.velocity(0, j).y(), 0.01 * shape, 1e-14) << j;
  }
}

TEST(OpenSides, RampRaisesTheVelocitySmoothlyOverItsTime) {
  const int nx = 16, ny = 8;
  lb::LatticeDef def = unitLattice(nx, ny, 0.8);
  const double U = 0.04, T = 40;
  def.sides[lb::bottom] = lb::SideDef{lb::SideKind::velocity, Vec2(0, U)};
  def.sides[lb::bottom].ramp = T;
  def.sides[lb::top] = lb::SideDef{lb::SideKind::outflow};
  lb::Lattice lattice(lb::resolve(def));
  for (int n = 1; n <= 60; ++n) {
    lattice.step();
    const double expected = n >= T ? U : U * 0.5 * (1 - std::cos(std::numbers::pi * n / T));
    ASSERT_NEAR(lattice.velocity(5, 0).y(), expected, 1e-15) << "step " << n;
  }
}

// Kinetic energy of the flow's departure from the uniform stream (U, 0).
double perturbationEnergy(const lb::Lattice& l, double U) {
  double e = 0;
  for (int j = 0; j < l.ny(); ++j)
    for (int i = 0; i < l.nx(); ++i) {
      const Vec2 u = l.velocity(i, j) - Vec2(U, 0);
      e += 0.5 * l.density(i, j) * u.squaredNorm();
    }
  return e;
}

struct Reflection {
  double initial, left;  // perturbation energy at the start, largest after the vortex left
};

// A vortex carried by a uniform stream (periodic in y) out of the
// right side; the energy of what stays behind once it has gone.
Reflection vortexLeaving(const lb::SideDef& right, int threads = 1) {
  const int nx = 160, ny = 80;
  const double U = 0.05, rc = 6, uMax = 0.02, x0 = 110, y0 = 40;
  lb::LatticeDef def = unitLattice(nx, ny, 0.56);
  def.sides[lb::bottom] = def.sides[lb::top] = lb::SideDef{lb::SideKind::periodic};
  def.sides[lb::left] = lb::SideDef{lb::SideKind::velocity, Vec2(U, 0)};
  def.sides[lb::right] = right;
  lb::Lattice lattice(lb::resolve(def));
  lattice.setThreads(threads);
  // A shielded (Taylor) vortex, u_theta = uMax (r / rc) exp((1 - r^2/rc^2) / 2),
  // no net circulation, so nothing of it reaches far; its pressure from
  // dp/dr = rho u_theta^2 / r: p = p0 - rho uMax^2 e / 2 exp(-r^2/rc^2).
  lattice.initialize([&](const Vec2& x, double& rho, Vec2& u) {
    const Vec2 d = x - Vec2(x0, y0);
    const double g = std::exp(-d.squaredNorm() / (rc * rc));
    const double k = uMax / rc * std::exp(0.5) * std::sqrt(g);  // u_theta / r
    u = Vec2(U - k * d.y(), k * d.x());
    rho = 1.0 - 3.0 * uMax * uMax * std::exp(1.0) / 2 * g;  // p = rho / 3
  });
  Reflection out{perturbationEnergy(lattice, U), 0.0};
  // The centre leaves after (nx - x0) / U = 1000 steps, its core ~4 rc later.
  for (int n = 1; n <= 4000; ++n) {
    lattice.step();
    if (n >= 2000 && n % 50 == 0) out.left = std::max(out.left, perturbationEnergy(lattice, U));
  }
  return out;
}

TEST(OpenSides, OutflowLetsAVortexLeaveWithLittleReflection) {
  const Reflection outflow = vortexLeaving(lb::SideDef{lb::SideKind::outflow});
  const Reflection pressure =
      vortexLeaving(lb::SideDef{lb::SideKind::pressure, Vec2::Zero(), 1.0 / 3.0});
  std::printf("perturbation energy left after the vortex: outflow %.3e, pressure %.3e of %.3e\n",
              outflow.left, pressure.left, outflow.initial);
  EXPECT_LT(outflow.left, 0.2 * pressure.left);
  EXPECT_LT(outflow.left, 1e-5 * outflow.initial);
}

TEST(OpenSides, OutflowStepIsTheSameOnAnyThreadCount) {
  const lb::SideDef outflow{lb::SideKind::outflow};
  EXPECT_EQ(vortexLeaving(outflow, 1).left, vortexLeaving(outflow, 2).left);
}

}  // namespace
}  // namespace sf
