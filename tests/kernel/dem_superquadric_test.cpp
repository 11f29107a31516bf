// Superquadrics: exact mass properties, and contacts that converge as the
// outline is sampled more finely.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sandflow/core/error.hpp"
#include "sandflow/dem/narrow_phase.hpp"
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

TEST(DemSuperquadric, RefusesBadParameters) {
  EXPECT_THROW(Superquadric(0, 1, 2, 2, 16), Error);
  EXPECT_THROW(Superquadric(1, 1, 0.5, 2, 16), Error);
  EXPECT_THROW(Superquadric(1, 1, 2, 2, 4), Error);
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
