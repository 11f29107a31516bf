// The narrow phase is symmetric: collide(b, a) is collide(a, b) with the normal
// reversed (the same overlap and contact point), for every pair of shape types.
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <vector>

#include "sandflow/dem/narrow_phase.hpp"
#include "sandflow/dem/polygon.hpp"
#include "sandflow/dem/superquadric.hpp"

namespace sf::dem {
namespace {

// One shape of each type, none with a symmetry that would hide a swapped role:
// an irregular pentagon, an elongated superquadric, a long wall.
std::vector<std::unique_ptr<Shape>> oneOfEach() {
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.push_back(std::make_unique<Disc>(0.5));
  Vec2 centroid;
  shapes.push_back(std::make_unique<Polygon>(Polygon::fromVertices(
      {{-0.5, -0.4}, {0.6, -0.5}, {0.7, 0.2}, {0.1, 0.6}, {-0.6, 0.3}}, centroid)));
  shapes.push_back(std::make_unique<Superquadric>(0.7, 0.4, 4, 2, 64));
  shapes.push_back(std::make_unique<Wall>(4.0, 0.1));
  return shapes;
}

TEST(NarrowPhase, CollideIsSymmetricForEveryPairOfShapeTypes) {
  const auto shapes = oneOfEach();
  ASSERT_EQ(int(shapes.size()), kShapeTypes);
  // The second shape's pose relative to the first (at the origin, turned by
  // 0.3): near, overlapping by various depths in various directions, plus one
  // apart. Both centres within reach of the wall's segment.
  const Pose first{Vec2(0, 0), 0.3};
  const std::array seconds{Pose{Vec2(0.6, 0.2), 0.0},   Pose{Vec2(-0.4, 0.7), 1.1},
                           Pose{Vec2(0.2, -0.5), -0.7}, Pose{Vec2(-0.75, -0.3), 2.5},
                           Pose{Vec2(0.05, 0.45), 0.4}, Pose{Vec2(3.0, 3.0), 0.0}};
  for (const auto& a : shapes) {
    for (const auto& b : shapes) {
      const char* names = shapeTypeNames[int(a->type())];
      SCOPED_TRACE(std::string(names) + " / " + shapeTypeNames[int(b->type())]);
      EXPECT_EQ(canCollide(a->type(), b->type()), canCollide(b->type(), a->type()));
      int contacts = 0;
      for (const Pose& second : seconds) {
        Manifold ab, ba;
        const bool hitAB = collide(*a, first, *b, second, ab);
        const bool hitBA = collide(*b, second, *a, first, ba);
        ASSERT_EQ(hitAB, hitBA) << "at " << second.x.transpose();
        if (!hitAB) continue;
        ++contacts;
        // Round-off only: both orders compute the same geometry.
        EXPECT_NEAR(ab.normal.norm(), 1.0, 1e-12);
        EXPECT_LT((ab.normal + ba.normal).norm(), 1e-12) << "at " << second.x.transpose();
        EXPECT_NEAR(ab.overlap, ba.overlap, 1e-12) << "at " << second.x.transpose();
        EXPECT_GT(ab.overlap, 0.0);
        EXPECT_LT((ab.point - ba.point).norm(), 1e-12) << "at " << second.x.transpose();
      }
      // Pairs that can touch did touch in most poses (the test is not vacuous);
      // walls never touch walls.
      if (canCollide(a->type(), b->type()))
        EXPECT_GE(contacts, 3);
      else
        EXPECT_EQ(contacts, 0);
    }
  }
  EXPECT_FALSE(canCollide(ShapeType::wall, ShapeType::wall));
}

}  // namespace
}  // namespace sf::dem
