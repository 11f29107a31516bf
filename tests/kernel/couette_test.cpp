// Plane Couette flow: a linear profile between a resting no-slip wall at y = 0
// and a moving top. Both ways of moving the top reproduce it to round-off.
#include <gtest/gtest.h>

#include "lattice_helpers.hpp"

namespace sf {
namespace {

TEST(Couette, ZouHeVelocityTopIsExact) {
  // The Zou-He edge imposes U on the top row of nodes, at y = H - h/2.
  for (double tau : {0.7, 1.0, 1.6}) {
    lb::LatticeDef def = test::channelDef(4, 16, tau);
    const double dt = (2 * tau - 1) / 6 / *def.viscosity;
    const double U = 0.05 / dt;  // Mach 0.05
    def.sides[lb::top] = lb::SideDef{lb::SideKind::velocity, Vec2(U, 0)};
    lb::Lattice lattice(lb::resolve(def));
    test::runToSteady(lattice, 1e-15, 200000);
    const double top = 16 - 0.5;
    EXPECT_LE(test::profileError(lattice, 1, [&](double y) { return U * y / top; }), 1e-10)
        << "tau " << tau;
    EXPECT_NEAR(lattice.velocity(2, 15).x(), U, 1e-12 * U);
  }
}

TEST(Couette, MovingBounceBackWallIsExact) {
  lb::LatticeDef def = test::channelDef(4, 16, 0.8);
  const double dt = (2 * 0.8 - 1) / 6 / *def.viscosity;
  const double U = 0.05 / dt;
  def.sides[lb::top] = lb::SideDef{lb::SideKind::noslip, Vec2(U, 0)};
  lb::Lattice lattice(lb::resolve(def));
  test::runToSteady(lattice, 1e-15, 200000);
  EXPECT_LE(test::profileError(lattice, 1, [&](double y) { return U * y / 16; }), 1e-10);
}

}  // namespace
}  // namespace sf
