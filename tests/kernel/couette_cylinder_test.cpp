// Cylindrical Couette flow (thesis case B, §5.1), shortened for CI (the full
// study is tests/validation/validate_couette.cpp): steady velocity and torque
// converge under refinement; the translating system agrees with the stationary
// one; the interior treatment changes no result.
#include <gtest/gtest.h>

#include <cstdio>

#include "../validation/couette_case.hpp"

namespace sf {
namespace {

using validation::CouetteResult;
using validation::CouetteSetup;
using validation::runCouette;

CouetteResult couette(int cells, const Vec2& translate = Vec2::Zero()) {
  CouetteSetup s;
  s.cells = cells;
  s.translate = translate;
  return runCouette(s);
}

double slope(double e0, double e1) {
  return std::log(e0 / e1) / std::log(2.0);
}

TEST(CylindricalCouette, StationaryConvergesAtAboutSecondOrder) {
  const CouetteResult a = couette(20), b = couette(40), c = couette(80);
  std::printf("velocity L2: %.3e %.3e %.3e (slopes %.2f %.2f)\n", a.velocityError, b.velocityError,
              c.velocityError, slope(a.velocityError, b.velocityError),
              slope(b.velocityError, c.velocityError));
  std::printf("torque: %.3e %.3e %.3e (slopes %.2f %.2f)\n", a.torqueError, b.torqueError,
              c.torqueError, slope(a.torqueError, b.torqueError),
              slope(b.torqueError, c.torqueError));
  const double overall = slope(a.velocityError, c.velocityError) / 2;
  EXPECT_GE(overall, 1.6);
  EXPECT_LE(overall, 2.3);
  EXPECT_LT(c.velocityError, 0.006);
  EXPECT_LT(c.torqueError, 0.03);
  EXPECT_GE(slope(a.torqueError, c.torqueError) / 2, 1.5);
  EXPECT_LT(c.netForce, 1e-8);  // the stationary system feels no net force (symmetry)
}

TEST(CylindricalCouette, TranslatingSystemAgreesWithTheStationaryOne) {
  const CouetteResult s = couette(40), t = couette(40, Vec2(0.03, 0.015));
  std::printf("translating: velocity %.3e (stationary %.3e), torque %.3e (%.3e), net force %.3e\n",
              t.velocityError, s.velocityError, t.torqueError, s.torqueError, t.netForce);
  EXPECT_LT(t.velocityError, 1.2 * s.velocityError);
  EXPECT_LT(std::abs(t.torqueError - s.torqueError), 0.01);
  EXPECT_LT(t.netForce, 0.01);
}

TEST(CylindricalCouette, InteriorTreatmentChangesNoResult) {
  // A turning inner cylinder inside a resting outer one.
  CouetteSetup s;
  s.cells = 40;
  s.omega1 = 0.3;
  s.omega2 = 0;
  const CouetteResult eq = runCouette(s);
  s.coupling.equilibriumInterior = false;
  const CouetteResult nt = runCouette(s);
  std::printf("interior equilibrium: %.4e / %.4e, collide: %.4e / %.4e\n", eq.velocityError,
              eq.torqueError, nt.velocityError, nt.torqueError);
  EXPECT_LT(std::abs(eq.velocityError - nt.velocityError), 0.05 * eq.velocityError);
  EXPECT_LT(std::abs(eq.torque - nt.torque), 0.01 * std::abs(eq.exactTorque));
}

// Table 5.1 of the thesis: the Stokes layer diffusing in from the impulsively
// started outer wall, errors (x1e-2) 8.84 and 3.80 at t = 10 and 20 steps with
// dt, 1.58 and 0.61 with dt/2: super-quadratic in time.
TEST(CylindricalCouette, TransientStokesLayerMatchesTable51) {
  const validation::TransientErrors full = validation::transientErrors(false);
  const validation::TransientErrors half = validation::transientErrors(true);
  std::printf("transient: dt %.3e %.3e, dt/2 %.3e %.3e (thesis 8.84e-2 3.80e-2 1.58e-2 0.61e-2)\n",
              full.at10, full.at20, half.at10, half.at20);
  EXPECT_NEAR(full.at10, 8.84e-2, 0.1 * 8.84e-2);
  EXPECT_NEAR(full.at20, 3.80e-2, 0.15 * 3.80e-2);
  EXPECT_NEAR(half.at10, 1.58e-2, 0.15 * 1.58e-2);
  EXPECT_LT(half.at20, 1.5 * 0.61e-2);
  EXPECT_GT(full.at10 / half.at10, 4.0);  // halving dt more than quarters the error
  EXPECT_GT(full.at20 / half.at20, 4.0);
}

}  // namespace
}  // namespace sf
