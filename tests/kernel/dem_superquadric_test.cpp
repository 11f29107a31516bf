// Superquadrics: exact mass properties, and contacts that converge as the
// outline is sampled more finely.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "sandflow/core/error.hpp"
#include "sandflow/dem/narrow_phase.hpp"
#include "sandflow/dem/shape_checks.hpp"
#include "sandflow/dem/superquadric.hpp"

namespace sf::dem {
namespace {

TEST(DemSuperquadric, EllipseMassPropertiesAreExact) {
  const Superquadric s(2, 1, 2, 2, 64);
  EXPECT_NEAR(s.area(), std::numbers::pi * 2, 1e-12);
  EXPECT_NEAR(s.inertiaPerMass(), (4.0 + 1.0) / 4, 1e-12);
}

TEST(DemSuperquadric, MassPropertiesMatchQuadrature) {
  const double a = 3, b = 2, m = 4, n = 3;
  const Superquadric s(a, b, m, n, 64);
  // Midpoint rule on a fine grid, counting cells whose centre is inside.
  const int cells = 2000;
  double area = 0, polar = 0;
  const double hx = 2 * a / cells, hy = 2 * b / cells;
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j) {
      const Vec2 p(-a + (i + 0.5) * hx, -b + (j + 0.5) * hy);
      if (s.implicit(p) < 0) area += hx * hy, polar += hx * hy * p.squaredNorm();
    }
  EXPECT_NEAR(s.area() / area, 1.0, 2e-4);
  EXPECT_NEAR(s.inertiaPerMass() / (polar / area), 1.0, 2e-4);
}

// "CODE: message" of the refusal of a superquadric, or "accepted".
std::string refusal(double a, double b, double m, double n, int samples = 16) {
  try {
    Superquadric(a, b, m, n, samples);
  } catch (const Error& e) {
    return e.code() + ": " + e.what();
  }
  return "accepted";
}

TEST(DemSuperquadric, RefusesSemiAxesThatAreNotFiniteAndPositive) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
  const std::string message = "VALUE AXES: superquadric semi-axes must be finite and > 0, got ";
  EXPECT_EQ(refusal(0, 1, 2, 2), message + "{0 1}");
  EXPECT_EQ(refusal(1, -1, 2, 2), message + "{1 -1}");
  EXPECT_EQ(refusal(nan, 1, 2, 2), message + "{nan 1}");
  EXPECT_EQ(refusal(1, inf, 2, 2), message + "{1 inf}");
}

TEST(DemSuperquadric, RefusesAxesMoreUnequalThanTheLimit) {
  EXPECT_EQ(refusal(1, 1e-7, 2, 2),
            "VALUE AXES: superquadric semi-axes {1 1e-07} differ by a factor of 1e+07: at most "
            "1e+06 is allowed");
  EXPECT_EQ(refusal(1e-300, 1e300, 2, 2),
            "VALUE AXES: superquadric semi-axes {1e-300 1e+300} differ by a factor of inf: at "
            "most 1e+06 is allowed");
  EXPECT_EQ(refusal(kMaxAxisRatio, 1, 2, 2), "accepted");
  EXPECT_EQ(refusal(1, kMaxAxisRatio, 1, 1), "accepted");
}

TEST(DemSuperquadric, RefusesExponentsOutOfRange) {
  const std::string message =
      "VALUE EXPONENTS: superquadric exponents must be 1 to 100 (1 a lozenge, 2 an ellipse, 100 "
      "nearly a box; below 1 it is not convex), got ";
  EXPECT_EQ(refusal(1, 1, 0.5, 2), message + "{0.5 2}");
  EXPECT_EQ(refusal(1, 1, 2, 100.5), message + "{2 100.5}");
  EXPECT_EQ(refusal(1, 1, std::nan(""), 2), message + "{nan 2}");
  EXPECT_EQ(refusal(1, 1, 2, std::numeric_limits<double>::infinity()), message + "{2 inf}");
}

TEST(DemSuperquadric, RefusesTooFewOrTooManySamples) {
  EXPECT_EQ(refusal(1, 1, 2, 2, 7), "VALUE SIDES: superquadric samples must be 8 to 10000, got 7");
  EXPECT_EQ(refusal(1, 1, 2, 2, 10001),
            "VALUE SIDES: superquadric samples must be 8 to 10000, got 10001");
}

// At the ends of every range the mass properties stay exact and the outline
// finite: the limits are where the shape still works, not beyond.
TEST(DemSuperquadric, ShapesAtTheLimitsHaveExactMassAndAFiniteOutline) {
  const Superquadric box(1, 1, kMaxExponent, kMaxExponent, 64);
  // Area of |x|^m + |y|^m <= 1: 4 Gamma(1 + 1/m)^2 / Gamma(1 + 2/m).
  const double g = std::tgamma(1 + 1 / kMaxExponent);
  EXPECT_NEAR(box.area(), 4 * g * g / std::tgamma(1 + 2 / kMaxExponent), 1e-12);
  EXPECT_GT(box.area(), 3.9);  // nearly the 2 x 2 square
  const Superquadric needle(kMaxAxisRatio, 1, 2, 2, 64);
  EXPECT_NEAR(needle.area() / (std::numbers::pi * kMaxAxisRatio), 1.0, 1e-12);
  EXPECT_NEAR(needle.inertiaPerMass() / ((kMaxAxisRatio * kMaxAxisRatio + 1) / 4), 1.0, 1e-12);
  for (const Superquadric* s : {&box, &needle})
    for (const Vec2& p : s->world(Vec2::Zero(), 0)) EXPECT_TRUE(p.allFinite());
}

// A circular superquadric (a = b, m = n = 2) pressed against a disc from an
// oblique direction: the normal must approach the line of centres and the
// overlap the exact one as the samples grow.
TEST(DemSuperquadric, ContactConvergesWithSampleCount) {
  const Disc disc(0.5);
  const double theta = 0.3, gap = -0.05;  // overlap 0.05 along the direction theta
  const Vec2 dir(std::cos(theta), std::sin(theta));
  double previousNormal = 1, previousOverlap = 1;
  for (int samples : {16, 64, 256, 1024}) {
    const Superquadric s(1, 1, 2, 2, samples);
    Manifold m;
    ASSERT_TRUE(collide(s, {{0, 0}, 0.1}, disc, {(1.5 + gap) * dir, 0}, m)) << samples;
    const double normalError = (m.normal - dir).norm();
    const double overlapError = std::abs(m.overlap - 0.05);
    EXPECT_LE(normalError, previousNormal) << samples;
    EXPECT_LE(overlapError, previousOverlap + 1e-12) << samples;
    previousNormal = normalError, previousOverlap = overlapError;
  }
  EXPECT_LT(previousNormal, 1e-2);
  EXPECT_LT(previousOverlap, 1e-3);
}

TEST(DemSuperquadric, RestsOnAWallAtItsHalfHeight) {
  const Superquadric s(1.5, 1, 4, 4, 128);
  const Wall floor(10, 0.1);
  Manifold m;
  ASSERT_TRUE(collide(floor, {{0, 0}, 0}, s, {{0, 0.98}, 0}, m));
  EXPECT_NEAR(m.overlap, 0.02, 1e-12);
  EXPECT_NEAR(m.normal.y(), 1, 1e-12);
  EXPECT_FALSE(collide(floor, {{0, 0}, 0}, s, {{0, 1.01}, 0}, m));
}

}  // namespace
}  // namespace sf::dem
