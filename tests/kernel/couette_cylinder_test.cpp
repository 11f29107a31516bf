// Cylindrical Couette flow (thesis case B, §5.1): an inner cylinder at rest
// inside a rotating outer one, both circular walls of the lattice treated with
// the Noble-Torczynski operator and the exact solid ratio. Steady velocity and
// torque converge under refinement; the translating system (both walls moving
// across the periodic lattice) agrees with the stationary one.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "coupled_helpers.hpp"

namespace sf {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double r1 = 0.1, r2 = 0.3, omega2 = 0.1, nu = 4.166e-2;

struct CouetteResult {
  double velocityError;  // relative L2 over the fluid nodes between the walls
  double torqueError;    // relative, on the inner cylinder
  double netForce;       // |force| on the inner cylinder / (torque / r1)
};

double exactSpeed(double r) {
  const double A = omega2 * r2 * r2 / (r2 * r2 - r1 * r1);
  const double B = -omega2 * r1 * r1 * r2 * r2 / (r2 * r2 - r1 * r1);
  return A * r + B / r;
}

double exactTorque() {
  return 4 * pi * 1.0 * nu * omega2 * r1 * r1 * r2 * r2 / (r2 * r2 - r1 * r1);
}

// Steady state after `time` (the slowest mode decays on (r2 - r1)^2 / (pi^2 nu)
// ~ 0.1, so t = 2.5 leaves ~1e-10 of the start-up).
CouetteResult couette(int cells, double time, const Vec2& translate = Vec2::Zero()) {
  sim::Manager m;
  m.createLattice(test::periodicSquare(1.0, cells, nu));
  lb::Lattice& l = m.lattice();
  const Vec2 centre(0.5, 0.5);
  const int inner = l.addCircle({-1, centre, r1, false, translate, 0.0});
  l.addCircle({-1, centre, r2, true, translate, omega2});
  const long steps = std::lround(time / l.params().dt);
  for (long k = 0; k < steps; ++k) m.step();

  const Vec2 c = l.circles()[0].centre;  // where the walls are now
  double err = 0, norm = 0;
  for (int j = 0; j < l.ny(); ++j)
    for (int i = 0; i < l.nx(); ++i) {
      if (l.solidRatio(i, j) > 0) continue;
      Vec2 d = l.position(i, j) - c;
      d -= Vec2(std::round(d.x()), std::round(d.y()));  // nearest periodic image
      const double r = d.norm();
      if (r <= r1 || r >= r2) continue;
      const Vec2 exact = translate + exactSpeed(r) * Vec2(-d.y(), d.x()) / r;
      err += (l.velocity(i, j) - exact).squaredNorm();
      norm += exact.squaredNorm() - translate.squaredNorm();
    }
  const lb::ObstacleInfo in = l.obstacleInfo(inner);
  return {std::sqrt(err / norm), std::abs(in.torque - exactTorque()) / exactTorque(),
          in.force.norm() * r1 / exactTorque()};
}

double slope(double e0, double e1) {
  return std::log(e0 / e1) / std::log(2.0);
}

TEST(CylindricalCouette, StationaryConvergesAtAboutSecondOrder) {
  const CouetteResult a = couette(20, 2.5), b = couette(40, 2.5), c = couette(80, 2.5);
  const double s1 = slope(a.velocityError, b.velocityError),
               s2 = slope(b.velocityError, c.velocityError);
  RecordProperty("velocity_errors", std::to_string(a.velocityError) + " " +
                                        std::to_string(b.velocityError) + " " +
                                        std::to_string(c.velocityError));
  std::printf("velocity L2: %.3e %.3e %.3e (slopes %.2f %.2f)\n", a.velocityError, b.velocityError,
              c.velocityError, s1, s2);
  std::printf("torque: %.3e %.3e %.3e (slopes %.2f %.2f)\n", a.torqueError, b.torqueError,
              c.torqueError, slope(a.torqueError, b.torqueError),
              slope(b.torqueError, c.torqueError));
  EXPECT_GE(slope(a.velocityError, c.velocityError) / 2, 1.6);
  EXPECT_LE(slope(a.velocityError, c.velocityError) / 2, 2.3);
  EXPECT_LT(c.velocityError, 0.01);
  EXPECT_LT(c.torqueError, 0.03);
  EXPECT_LT(c.torqueError, a.torqueError);
  // The stationary system feels no net force (symmetry).
  EXPECT_LT(c.netForce, 1e-8);
}

TEST(CylindricalCouette, TranslatingSystemAgreesWithTheStationaryOne) {
  const Vec2 v(0.03, 0.03 * 0.5);
  const CouetteResult s = couette(40, 2.5), t = couette(40, 2.5, v);
  std::printf("translating: velocity %.3e (stationary %.3e), torque %.3e (%.3e), net force %.3e\n",
              t.velocityError, s.velocityError, t.torqueError, s.torqueError, t.netForce);
  EXPECT_LT(t.velocityError, 1.5 * s.velocityError);
  EXPECT_LT(std::abs(t.torqueError - s.torqueError), 0.05);
  EXPECT_LT(t.netForce, 0.05);  // oscillates about zero, small
}

}  // namespace
}  // namespace sf
