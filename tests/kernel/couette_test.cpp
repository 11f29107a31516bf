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

namespace sf {
namespace {

// The Zou-He reconstruction is written for one side and rotated onto the others:
// a sliding velocity edge on each side in turn, the opposite side a resting
// no-slip wall, periodic along the edge, gives the same linear profile.
TEST(Couette, ZouHeVelocityOnEverySide) {
  for (int side : {lb::left, lb::right, lb::bottom, lb::top}) {
    const bool vertical = side == lb::left || side == lb::right;
    lb::LatticeDef def;
    def.size = vertical ? Vec2(16, 4) : Vec2(4, 16);
    def.cells = vertical ? 16 : 4;
    def.viscosity = 0.1;
    def.tau = 0.9;
    const double U = 0.04 * lb::resolve(def).latticeSpeed();
    for (auto& s : def.sides) s = lb::SideDef{lb::SideKind::periodic};
    def.sides[side] = lb::SideDef{lb::SideKind::velocity, vertical ? Vec2(0, U) : Vec2(U, 0)};
    def.sides[side ^ 1] = lb::SideDef{lb::SideKind::noslip};
    lb::Lattice lattice(lb::resolve(def));
    test::runToSteady(lattice, 1e-15, 200000, 100);
    // Distance from the resting wall to the velocity nodes is 16 - 1/2 spacings.
    double worst = 0;
    for (int k = 0; k < 16; ++k) {
      const int i = vertical ? k : 1, j = vertical ? 1 : k;
      const double fromWall = (side == lb::right || side == lb::top) ? k + 0.5 : 15.5 - k;
      const Vec2 u = lattice.velocity(i, j);
      const double along = vertical ? u.y() : u.x(), across = vertical ? u.x() : u.y();
      worst = std::max({worst, std::abs(along - U * fromWall / 15.5), std::abs(across)});
    }
    EXPECT_LE(worst / U, 1e-10) << "side " << lb::sideNames[side];
  }
}

}  // namespace
}  // namespace sf
