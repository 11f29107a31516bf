// Bonds: a bonded pair pulled apart breaks at its strength, once.
#include <gtest/gtest.h>

#include <cmath>

#include "sandflow/core/error.hpp"
#include "sandflow/dem/assembly.hpp"

namespace sf::dem {
namespace {

struct Pair {
  Assembly a;
  int left, right;
  explicit Pair(double strength, double shearStrength = 1e9) {
    Material m{"cement"};
    m.kn = m.ks = 1e5;
    m.bondStiffness = 2e5;
    m.bondStrength = strength;
    m.restitution = 0.5;
    const int mat = a.materials().add(m);
    auto disc = [&](Vec2 x) {
      ElementDef d;
      d.shape = std::make_unique<Disc>(1e-3);
      d.material = mat;
      d.x = x;
      return a.add(std::move(d));
    };
    left = disc({-1e-3, 0});
    right = disc({1e-3, 0});
    a.bond(left, right, -1, -1, shearStrength);
  }
};

TEST(DemBond, PulledApartBreaksAtItsStrengthOnce) {
  const double strength = 2.0;  // N per unit thickness
  Pair p(strength);
  // Pull the right disc with a slowly growing force; hold the left one.
  Bodies& b = p.a.bodiesForTesting();
  b.hold[p.a.slot(p.left)] = holdX | holdY | holdRotation;
  p.a.updateMass(p.a.slot(p.left));
  const double dt = p.a.criticalTimestep() / 20;
  const double rate = 50.0;  // N/s: quasi-static against the bond's own period
  double t = 0, appliedAtBreak = -1;
  for (int s = 0; s < 400000 && p.a.breaks().empty(); ++s) {
    b.appliedForce[p.a.slot(p.right)] = Vec2(rate * t, 0);
    p.a.step(dt, Vec2::Zero());
    t += dt;
    if (!p.a.breaks().empty()) appliedAtBreak = rate * t;
  }
  ASSERT_EQ(p.a.breaks().size(), 1u);
  EXPECT_NEAR(appliedAtBreak / strength, 1.0, 0.01);
  EXPECT_TRUE(p.a.breaks()[0].tension);
  EXPECT_NEAR(p.a.breaks()[0].at.x(), 0.0, 2e-4);
  EXPECT_TRUE(p.a.bonds().empty());
  for (int s = 0; s < 1000; ++s) p.a.step(dt, Vec2::Zero());
  EXPECT_EQ(p.a.breaks().size(), 1u);  // recorded once
}

TEST(DemBond, ShearedBondBreaksInShear) {
  Pair p(1e9, 1.0);
  Bodies& b = p.a.bodiesForTesting();
  b.hold[p.a.slot(p.left)] = holdX | holdY | holdRotation;
  p.a.updateMass(p.a.slot(p.left));
  b.hold[p.a.slot(p.right)] = holdRotation;
  p.a.updateMass(p.a.slot(p.right));
  const double dt = p.a.criticalTimestep() / 20;
  double t = 0, appliedAtBreak = -1;
  for (int s = 0; s < 400000 && p.a.breaks().empty(); ++s) {
    b.appliedForce[p.a.slot(p.right)] = Vec2(0, 25.0 * t);
    p.a.step(dt, Vec2::Zero());
    t += dt;
    if (!p.a.breaks().empty()) appliedAtBreak = 25.0 * t;
  }
  ASSERT_EQ(p.a.breaks().size(), 1u);
  EXPECT_FALSE(p.a.breaks()[0].tension);
  EXPECT_NEAR(appliedAtBreak, 1.0, 0.02);
}

TEST(DemBond, RefusesSelfDuplicateAndDistantBonds) {
  Pair p(1.0);
  EXPECT_THROW(p.a.bond(p.left, p.left), Error);
  EXPECT_THROW(p.a.bond(p.left, p.right), Error);
  ElementDef far;
  far.shape = std::make_unique<Disc>(1e-3);
  far.x = Vec2(1, 1);
  const int id = p.a.add(std::move(far));
  EXPECT_NO_THROW(p.a.bond(p.left, id));  // bond() bonds at any distance when asked by id
  EXPECT_EQ(p.a.bondAll({}, 1e-4), 0);    // auto: only pairs within the gap (already bonded)
}

TEST(DemBond, DeletingAnElementRemovesItsBonds) {
  Pair p(1.0);
  p.a.remove(p.right);
  EXPECT_TRUE(p.a.bonds().empty());
}

}  // namespace
}  // namespace sf::dem
