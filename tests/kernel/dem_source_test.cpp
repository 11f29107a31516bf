// Sources: a ring of sources keeps producing clones every t_b = 2 sqrt(r/a_s).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sandflow/dem/assembly.hpp"

namespace sf::dem {
namespace {

TEST(DemSource, RingProducesClonesEveryBirthInterval) {
  Assembly a;
  Material m{"grain"};
  m.kn = m.ks = 1e5;
  m.restitution = 0.5;
  m.friction = 0.5;
  const int mat = a.materials().add(m);
  const double r = 1e-3, as = 2.0, R = 0.01;
  const int n = 8;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * k / n;
    ElementDef d;
    d.shape = std::make_unique<Disc>(r);
    d.material = mat;
    d.x = R * Vec2(std::cos(t), std::sin(t));
    const int id = a.add(std::move(d));
    a.makeSource(id, as * Vec2(std::cos(t), std::sin(t)), 0.0, -1);
  }
  const double tb = 2 * std::sqrt(r / as);
  const double dt = a.criticalTimestep() / 10;
  const double T = 10 * tb;
  const long steps = std::lround(T / dt);
  for (long s = 0; s < steps; ++s) a.step(dt, Vec2::Zero());
  for (const Source& src : a.sources()) {
    // One at t = 0, then one each time the previous clone has cleared the source.
    EXPECT_NEAR(src.made, 1 + T / tb, 1.0) << "source " << src.id;
    ASSERT_GE(src.clones.size(), 3u);
  }
  // The clones of one source move outward, one behind the other.
  const Source& first = a.sources()[0];
  const Bodies& b = a.bodies();
  EXPECT_GT(b.x[a.slot(first.clones[0])].norm(), b.x[a.slot(first.clones[1])].norm());
  EXPECT_EQ(a.touchingCount(), 0u);  // the sources touch nothing, the clones separate
}

TEST(DemSource, LimitAndIntervalAreHonoured) {
  Assembly a;
  ElementDef d;
  d.shape = std::make_unique<Disc>(1e-3);
  const int id = a.add(std::move(d));
  a.makeSource(id, Vec2(0, -10), 0.05, 3);
  const double dt = a.criticalTimestep() / 10;
  for (double t = 0; t < 1.0; t += dt) a.step(dt, Vec2::Zero());
  EXPECT_EQ(a.sources()[0].made, 3);
  EXPECT_EQ(a.bodies().size(), 4);
}

}  // namespace
}  // namespace sf::dem
