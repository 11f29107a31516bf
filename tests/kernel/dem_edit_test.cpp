// Assembly::configure: an element changed by hand, all of the edit or none.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "sandflow/core/error.hpp"
#include "sandflow/dem/assembly.hpp"

namespace sf::dem {
namespace {

struct Scene {
  Assembly a;
  int disc = 0, wall = 0;
  Scene() {
    a.materials().add(Material{"grain"});
    ElementDef d;
    d.shape = std::make_unique<Disc>(0.1);
    d.x = Vec2(0, 0);
    disc = a.add(std::move(d));
    ElementDef w;
    w.shape = std::make_unique<Wall>(2.0, 1e-3);
    w.x = Vec2(0, -1);
    wall = a.add(std::move(w));
  }
  // Every column a user can read, of one element.
  std::string state(int id) const {
    const Bodies& b = a.bodies();
    const int s = a.slot(id);
    std::ostringstream o;
    o << b.x[s].transpose() << ' ' << b.angle[s] << ' ' << b.v[s].transpose() << ' ' << b.w[s]
      << ' ' << b.mass[s] << ' ' << int(b.hold[s]) << ' ' << b.appliedForce[s].transpose() << ' '
      << b.stress[s] << ' ' << b.shape[s]->area();
    return o.str();
  }
};

TEST(DemEdit, ARefusedPartChangesNothing) {
  Scene s;
  const std::string disc = s.state(s.disc), wall = s.state(s.wall);
  ElementEdit e;
  e.velocity = Eigen::Vector3d(1, 2, 3);
  e.force = Eigen::Vector3d(4, 5, 6);
  e.radius = 0.2;  // a wall has no radius
  EXPECT_THROW(s.a.configure(s.wall, e), Error);
  e.radius.reset();
  e.stress = 1.0;  // a disc has no servo
  EXPECT_THROW(s.a.configure(s.disc, e), Error);
  e.stress.reset();
  e.from = Vec2(0, 0), e.to = Vec2(0, 0);  // a wall of no length
  EXPECT_THROW(s.a.configure(s.wall, e), Error);
  e.to = Vec2(1, 0), e.center = Vec2(0, 0);  // ends and centre both
  EXPECT_THROW(s.a.configure(s.wall, e), Error);
  EXPECT_EQ(s.state(s.disc), disc);
  EXPECT_EQ(s.state(s.wall), wall);
}

TEST(DemEdit, AnAcceptedEditIsAppliedWholeAndTheMassFollows) {
  Scene s;
  ElementEdit e;
  e.radius = 0.2;
  e.velocity = Eigen::Vector3d(1, 2, 3);
  e.center = Vec2(0.5, 0.5);
  s.a.configure(s.disc, e);
  const Bodies& b = s.a.bodies();
  const int d = s.a.slot(s.disc);
  EXPECT_EQ(b.x[d], Vec2(0.5, 0.5));
  EXPECT_EQ(b.v[d], Vec2(1, 2));
  EXPECT_EQ(b.w[d], 3);
  EXPECT_NEAR(b.mass[d], b.shape[d]->area() * s.a.materials()[b.material[d]].density, 1e-15);
  EXPECT_NEAR(b.shape[d]->area(), std::acos(-1.0) * 0.04, 1e-15);
  ElementEdit w;
  w.from = Vec2(0, 0), w.to = Vec2(0, 3);
  w.stress = 2.0;
  s.a.configure(s.wall, w);
  const int k = s.a.slot(s.wall);
  EXPECT_NEAR(b.x[k].y(), 1.5, 1e-15);
  EXPECT_NEAR(b.angle[k], std::acos(-1.0) / 2, 1e-15);
  EXPECT_EQ(b.stress[k], 2.0);
  EXPECT_EQ(b.hold[k], holdX | holdY | holdRotation);  // a servo plate is held
}

}  // namespace
}  // namespace sf::dem
