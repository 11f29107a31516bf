// Zou-He velocity and pressure sides: an inlet/outlet channel between no-slip
// walls develops the Poiseuille profile.
#include <gtest/gtest.h>

#include <cmath>

#include "lattice_helpers.hpp"

namespace sf {
namespace {

lb::LatticeDef openChannel(int nx, int ny) {
  lb::LatticeDef def = test::channelDef(nx, ny, 1.5);
  def.collision = lb::Collision::trt;  // walls exactly halfway: isolates the open sides
  return def;
}

TEST(ZouHe, PressureDrivenChannelIsPoiseuille) {
  const int nx = 16, ny = 32;
  lb::LatticeDef def = openChannel(nx, ny);
  const lb::ResolvedLattice probe = lb::resolve(def);
  const double cs2 = std::pow(probe.soundSpeed(), 2);
  const double rho0 = 1.0, drho = 2e-4;  // small: the fluid is weakly compressible
  def.sides[lb::left] = lb::SideDef{lb::SideKind::pressure, Vec2::Zero(), cs2 * (rho0 + drho / 2)};
  def.sides[lb::right] = lb::SideDef{lb::SideKind::pressure, Vec2::Zero(), cs2 * (rho0 - drho / 2)};
  lb::Lattice lattice(lb::resolve(def));
  test::runToSteady(lattice, 1e-11, 100000);
  // Pressure nodes sit on the first and last node columns, (nx - 1) h apart.
  const double gradient = cs2 * drho / (nx - 1);
  const double nu = *def.viscosity, H = ny;
  const double err = test::profileError(
      lattice, nx / 2, [&](double y) { return gradient / (2 * rho0 * nu) * y * (H - y); });
  EXPECT_LE(err, 1e-3);
  EXPECT_NEAR(lattice.density(0, ny / 2), rho0 + drho / 2, 1e-14);
}

TEST(ZouHe, UniformInletDevelopsPoiseuilleWithTheSameFlux) {
  const int nx = 96, ny = 32;
  lb::LatticeDef def = openChannel(nx, ny);
  const lb::ResolvedLattice probe = lb::resolve(def);
  const double U = 0.02 * probe.latticeSpeed();
  const double cs2 = std::pow(probe.soundSpeed(), 2);
  def.sides[lb::left] = lb::SideDef{lb::SideKind::velocity, Vec2(U, 0)};
  def.sides[lb::right] = lb::SideDef{lb::SideKind::pressure, Vec2::Zero(), cs2 * 1.0};
  lb::Lattice lattice(lb::resolve(def));
  // The inlet density settles slowly (time constant ~1.7e4 steps); a change
  // below 1e-6 per 200 steps leaves ~1e-4 of the flux to go, inside the tolerances.
  test::runToSteady(lattice, 1e-6, 100000);
  // Mass flux per unit depth is U H at the inlet; a parabola with that flux
  // peaks at 1.5 U. Compare far from both ends, with the local density.
  const int i = 2 * ny;
  double flux = 0;
  for (int j = 0; j < ny; ++j) flux += lattice.density(i, j) * lattice.velocity(i, j).x();
  double inflow = 0;
  for (int j = 0; j < ny; ++j) inflow += lattice.density(0, j) * U;
  EXPECT_NEAR(flux / inflow, 1.0, 1e-4);
  const double H = ny, mean = flux / (ny * lattice.density(i, ny / 2));
  const double err =
      test::profileError(lattice, i, [&](double y) { return 6 * mean * y * (H - y) / (H * H); });
  EXPECT_LE(err, 1e-3);
}

}  // namespace
}  // namespace sf
