// Polygons: mass properties, clipping against exact areas, and contacts.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include "sandflow/core/error.hpp"
#include "sandflow/dem/assembly.hpp"
#include "sandflow/dem/polygon.hpp"
#include "sandflow/dem/shape_checks.hpp"

namespace sf::dem {
namespace {

std::vector<Vec2> square(Vec2 c, double half, double angle = 0) {
  std::vector<Vec2> v;
  for (int k = 0; k < 4; ++k) {
    const double t = angle + std::numbers::pi / 4 + k * std::numbers::pi / 2;
    v.push_back(c + half * std::sqrt(2.0) * Vec2(std::cos(t), std::sin(t)));
  }
  return v;
}

TEST(DemPolygon, MassPropertiesOfARectangle) {
  Vec2 c;
  const Polygon p = Polygon::fromVertices({{1, 1}, {1, 3}, {5, 3}, {5, 1}}, c);  // clockwise
  EXPECT_NEAR(c.x(), 3, 1e-14);
  EXPECT_NEAR(c.y(), 2, 1e-14);
  EXPECT_NEAR(p.area(), 8, 1e-13);
  EXPECT_NEAR(p.inertiaPerMass(), (16.0 + 4.0) / 12, 1e-13);  // (a^2 + b^2)/12
  EXPECT_GT(geometry::signedArea(p.vertices()), 0);           // reordered counter-clockwise
}

TEST(DemPolygon, ManySidedPolygonApproachesTheEllipse) {
  std::vector<Vec2> v;
  const int n = 400;
  const double a = 2, b = 1;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * k / n;
    v.emplace_back(a * std::cos(t), b * std::sin(t));
  }
  Vec2 c;
  const Polygon p = Polygon::fromVertices(v, c);
  const double exactArea = std::numbers::pi * a * b;
  EXPECT_NEAR(p.area() / exactArea, 1.0, 1e-3);
  EXPECT_NEAR(p.inertiaPerMass() / ((a * a + b * b) / 4), 1.0, 1e-3);
}

// "CODE: message" of the refusal of an outline, or "accepted".
std::string refusal(const std::vector<Vec2>& v) {
  try {
    Vec2 c;
    Polygon::fromVertices(v, c);
  } catch (const Error& e) {
    return e.code() + ": " + e.what();
  }
  return "accepted";
}

// The corners of a regular polygon of `n` sides, visited `step` corners apart
// (step 2 of 5: the pentagram), `rounds` times over.
std::vector<Vec2> star(int n, int step, int rounds = 1) {
  std::vector<Vec2> v;
  for (int k = 0; k < n * rounds; ++k) {
    const double t = 2 * std::numbers::pi * (k * step % n) / n;
    v.emplace_back(std::cos(t), std::sin(t));
  }
  return v;
}

TEST(DemPolygon, RefusesTooFewOrNonFiniteVertices) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(refusal({{0, 0}, {1, 0}}),
            "VALUE VERTICES: a polygon needs at least 3 vertices, got 2");
  EXPECT_EQ(refusal({{0, 0}, {1, 0}, {std::nan(""), 1}}),
            "VALUE VERTICES: polygon vertex 3 is not finite: {nan 1}");
  EXPECT_EQ(refusal({{0, 0}, {inf, 0}, {0, 1}}),
            "VALUE VERTICES: polygon vertex 2 is not finite: {inf 0}");
  EXPECT_EQ(refusal({{-1e308, 0}, {1e308, 0}, {0, 1}}),
            "VALUE VERTICES: polygon is too large: its vertices span more than a double holds");
}

TEST(DemPolygon, RefusesRepeatedAndCollinearVertices) {
  EXPECT_EQ(refusal({{1, 1}, {1, 1}, {1, 1}}),
            "VALUE VERTICES: polygon vertices are all one point: it has no area");
  EXPECT_EQ(refusal({{0, 0}, {1, 0}, {1, 1}, {1, 1}}),
            "VALUE VERTICES: polygon vertices 3 and 4 are the same point: give each corner once");
  EXPECT_EQ(refusal({{0, 0}, {1, 0}, {1, 1}, {0, 0}}),
            "VALUE VERTICES: polygon vertices 4 and 1 are the same point: give each corner once");
  EXPECT_EQ(refusal({{0, 0}, {1, 0}, {2, 0}}),
            "VALUE VERTICES: polygon vertices are all on one line: it has no area");
  // Thinner than 1e-10 of its size is a line too.
  EXPECT_EQ(refusal({{0, 0}, {1, 0}, {1, 1e-11}, {0, 1e-11}}),
            "VALUE VERTICES: polygon vertices are all on one line: it has no area");
  EXPECT_EQ(refusal({{0, 0}, {1, 0}, {2, 0}, {2, 1}}),
            "VALUE VERTICES: polygon vertex 2 lies on the straight line from vertex 1 to vertex "
            "3: leave it out");
  EXPECT_EQ(refusal({{0, 0}, {2, 0}, {1, 0}, {1, 1}}),
            "VALUE VERTICES: polygon outline doubles back on itself at vertex 2 "
            "(self-intersecting)");
}

TEST(DemPolygon, RefusesAConcaveOutlineNamingTheVertexInTheGivenOrder) {
  EXPECT_EQ(refusal({{0, 0}, {2, 0}, {1, 0.2}, {2, 2}, {0, 2}}),
            "VALUE VERTICES: polygon is not convex at vertex 3");
  EXPECT_EQ(refusal({{0, 2}, {2, 2}, {1, 0.2}, {2, 0}, {0, 0}}),  // clockwise
            "VALUE VERTICES: polygon is not convex at vertex 3");
}

TEST(DemPolygon, RefusesAnOutlineThatCrossesItself) {
  EXPECT_EQ(refusal({{0, 0}, {1, 1}, {1, 0}, {0, 1}}),  // a bow tie
            "VALUE VERTICES: polygon outline crosses itself (self-intersecting): edges 1-2 and "
            "3-4 meet");
  // A vertex on an edge that is not its own: the outline touches itself.
  EXPECT_EQ(refusal({{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}),
            "VALUE VERTICES: polygon outline crosses itself (self-intersecting): edges 1-2 and "
            "3-4 meet");
}

// Issue 24: outlines whose turns all go one way but that wind round more than
// once were taken for convex polygons, with the area of each round added up.
TEST(DemPolygon, RefusesAnOutlineThatWindsMoreThanOnce) {
  const std::string twice =
      "VALUE VERTICES: polygon outline winds 2 times around (self-intersecting): a convex "
      "outline goes round once";
  EXPECT_EQ(refusal(star(5, 2)), twice);     // the pentagram, its points in star order
  EXPECT_EQ(refusal(star(4, 1, 2)), twice);  // a square traced twice
  std::vector<Vec2> clockwise = star(4, 1, 2);
  std::reverse(clockwise.begin(), clockwise.end());
  EXPECT_EQ(refusal(clockwise), twice);
  EXPECT_EQ(refusal(star(7, 3)),
            "VALUE VERTICES: polygon outline winds 3 times around (self-intersecting): a convex "
            "outline goes round once");
}

TEST(DemPolygon, AcceptsConvexOutlinesOfAnySizeAnywhere) {
  EXPECT_EQ(refusal(star(5, 1)), "accepted");
  EXPECT_EQ(refusal(square({1e3, -1e3}, 1e-3, 0.3)), "accepted");
  EXPECT_EQ(refusal(square({0, 0}, 1e-50)), "accepted");
  EXPECT_EQ(refusal(square({0, 0}, 1e50)), "accepted");
  // A needle 1e-9 wide: sharp, but its corners still turn.
  EXPECT_EQ(refusal({{0, 0}, {1, 0}, {0, 1e-9}}), "accepted");
  // An ellipse of 10000 sides at the largest axis ratio: its flattest
  // vertices turn by 6e-10, above the 1e-10 of a straight line.
  std::vector<Vec2> v;
  for (int k = 0; k < 10000; ++k) {
    const double t = 2 * std::numbers::pi * k / 10000;
    v.emplace_back(kMaxAxisRatio * std::cos(t), std::sin(t));
  }
  EXPECT_EQ(refusal(v), "accepted");
}

// The overlap of two axis-aligned rectangles is known exactly; rotate both by
// the same angle and shift them: clipping must keep the area to round-off.
TEST(DemPolygon, ClippedAreaMatchesExactOverlapTo1e12) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 1000; ++k) {
    const Vec2 c1(u(rng), u(rng)), c2 = c1 + Vec2(u(rng), u(rng));
    const double w1 = 0.5 + 0.4 * u(rng), h1 = 0.5 + 0.4 * u(rng);
    const double w2 = 0.5 + 0.4 * u(rng), h2 = 0.5 + 0.4 * u(rng);
    const double ox =
        std::max(0.0, std::min(c1.x() + w1, c2.x() + w2) - std::max(c1.x() - w1, c2.x() - w2));
    const double oy =
        std::max(0.0, std::min(c1.y() + h1, c2.y() + h2) - std::max(c1.y() - h1, c2.y() - h2));
    const double angle = 3 * u(rng);
    auto rect = [&](Vec2 c, double w, double h) {
      std::vector<Vec2> v = {{c.x() - w, c.y() - h},
                             {c.x() + w, c.y() - h},
                             {c.x() + w, c.y() + h},
                             {c.x() - w, c.y() + h}};
      for (Vec2& p : v) p = Eigen::Rotation2Dd(angle) * p;
      return v;
    };
    const std::vector<Vec2> region = geometry::clip(rect(c1, w1, h1), rect(c2, w2, h2));
    const double area = region.size() >= 3 ? geometry::signedArea(region) : 0.0;
    EXPECT_NEAR(area, ox * oy, 1e-12) << k;
  }
}

// The law: the normal is perpendicular to the chord joining the two points
// where the outlines cross, the depth is overlap area / chord length.
TEST(DemPolygon, SquaresFaceToFaceFollowTheChordLaw) {
  Vec2 c;
  const Polygon a = Polygon::fromVertices(square({0, 0}, 1), c);
  const Polygon b = Polygon::fromVertices(square({0, 0}, 1), c);
  Manifold m;
  ASSERT_TRUE(collide(a, {{0, 0}, 0}, b, {{1.9, 0}, 0}, m));  // aligned: the face normal
  EXPECT_NEAR(m.normal.x(), 1, 1e-12);
  EXPECT_NEAR(m.normal.y(), 0, 1e-12);
  EXPECT_NEAR(m.overlap, 0.1, 1e-12);
  EXPECT_NEAR(m.point.x(), 0.95, 1e-12);
  EXPECT_NEAR(m.point.y(), 0.0, 1e-12);
  // Offset by 0.3: the outlines cross at (1, -0.7) and (0.9, 1).
  ASSERT_TRUE(collide(a, {{0, 0}, 0}, b, {{1.9, 0.3}, 0}, m));
  const Vec2 chord = Vec2(0.9, 1) - Vec2(1, -0.7);
  const Vec2 normal = Vec2(chord.y(), -chord.x()).normalized();
  EXPECT_NEAR(m.normal.x(), normal.x(), 1e-12);
  EXPECT_NEAR(m.normal.y(), normal.y(), 1e-12);
  EXPECT_NEAR(m.overlap, 0.1 * 1.7 / chord.norm(), 1e-12);
  EXPECT_NEAR(m.point.x(), 0.95, 1e-12);
  EXPECT_NEAR(m.point.y(), 0.15, 1e-12);
  EXPECT_FALSE(collide(a, {{0, 0}, 0}, b, {{2.01, 0}, 0}, m));
}

TEST(DemPolygon, DiscAgainstPolygonEdgeAndCorner) {
  Vec2 c;
  const Polygon a = Polygon::fromVertices(square({0, 0}, 1), c);
  const Disc d(0.5);
  Manifold m;
  ASSERT_TRUE(collide(a, {{0, 0}, 0}, d, {{1.4, 0}, 0}, m));
  EXPECT_NEAR(m.overlap, 0.1, 1e-12);
  EXPECT_NEAR(m.normal.x(), 1, 1e-12);
  ASSERT_TRUE(collide(d, {{1.3, 1.3}, 0}, a, {{0, 0}, 0}, m));  // corner, reversed roles
  EXPECT_NEAR(m.overlap, 0.5 - 0.3 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(m.normal.x(), -std::sqrt(0.5), 1e-12);            // from the disc to the polygon
  ASSERT_TRUE(collide(a, {{0, 0}, 0}, d, {{0.9, 0.2}, 0}, m));  // centre inside
  EXPECT_NEAR(m.overlap, 0.6, 1e-12);
}

TEST(DemPolygon, SquareRestsOnAWallWithItsWeight) {
  Assembly asm_;
  Material mat{"rock"};
  mat.kn = mat.ks = 1e6;
  mat.restitution = 0.2;
  mat.friction = 0.5;
  const int rock = asm_.materials().add(mat);
  ElementDef floor;
  floor.shape = std::make_unique<Wall>(1.0, 0.01);
  floor.material = rock;
  floor.hold = holdX | holdY | holdRotation;
  const int w = asm_.add(std::move(floor));
  ElementDef box;
  Vec2 c;
  box.shape = std::make_unique<Polygon>(Polygon::fromVertices(square({0, 0.0101}, 0.01, 0.0), c));
  box.x = c;
  box.angle = 0.3;  // lands on a corner, then settles on a face
  box.material = rock;
  const int s = asm_.add(std::move(box));
  const double dt = asm_.criticalTimestep() / 10;
  for (int k = 0; k < 100000; ++k) asm_.step(dt, Vec2(0, -9.81));
  const Bodies& b = asm_.bodies();
  const int slot = asm_.slot(s);
  const double weight = b.mass[slot] * 9.81;
  EXPECT_NEAR(-asm_.contactForce(asm_.slot(w)).y() / weight, 1.0, 1e-6);
  EXPECT_LT(b.v[slot].norm(), 1e-6);
  const double turn = std::remainder(b.angle[slot], std::numbers::pi / 2);
  EXPECT_NEAR(turn, 0.0, 1e-3);  // flat on a face
  EXPECT_NEAR(b.x[slot].y(), 0.01, 2e-4);
}

}  // namespace
}  // namespace sf::dem
