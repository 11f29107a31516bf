// A bed settled under gravity: it comes to rest and the walls carry its weight.
#include <gtest/gtest.h>

#include <random>

#include "dem_helpers.hpp"
#include "sandflow/dem/assembly.hpp"

namespace sf::dem {
namespace {

TEST(DemBed, SettlesAndTheWallsCarryTheWeight) {
  Assembly a;
  Material m{"sand"};
  m.kn = m.ks = 1e5;
  m.restitution = 0.3;
  m.friction = 0.5;
  const int sand = a.materials().add(m);
  auto wall = [&](Vec2 p, Vec2 q) { return test::addWall(a, p, q, sand); };
  const double W = 0.02;
  std::vector<int> walls = {wall({0, 0}, {W, 0}), wall({0, 0}, {0, 0.05}), wall({W, 0}, {W, 0.05})};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  double weight = 0;
  const Vec2 g(0, -9.81);
  for (int k = 0; k < 90; ++k) {
    ElementDef d;
    const double r = 0.6e-3 + 0.3e-3 * u(rng);
    d.shape = std::make_unique<Disc>(r);
    d.material = sand;
    d.x = Vec2((k % 9 + 0.5 + 0.25 * (k / 9 % 2)) * 2.05e-3 + 1e-4 * u(rng),
               1e-3 + (k / 9) * 2.05e-3);
    a.add(std::move(d));
  }
  for (int s = 0; s < a.bodies().size(); ++s)
    if (a.bodies().invMass[s] > 0) weight += a.bodies().mass[s] * g.norm();
  const double dt = a.criticalTimestep() / 10;
  double peak = 0, ke = 0;
  int steps = 0, quiet = 0;
  // At rest: the energy below 1e-8 of its peak for 100 steps. The first step
  // below may catch the bed rocking slowly, its walls' load still swinging
  // by 0.2% of the weight sideways.
  for (; steps < 400000; ++steps) {
    a.step(dt, g);
    ke = a.kineticEnergy();
    peak = std::max(peak, ke);
    quiet = ke < 1e-8 * peak ? quiet + 1 : 0;
    if (steps > 1000 && quiet >= 100) break;
  }
  EXPECT_LT(ke, 1e-8 * peak) << "after " << steps << " steps";
  Vec2 reaction = Vec2::Zero();
  for (int w : walls) reaction += a.contactForce(a.slot(w));
  EXPECT_NEAR(-reaction.y() / weight, 1.0, 1e-3);  // the grains push the walls down
  EXPECT_NEAR(reaction.x() / weight, 0.0, 1e-3);
}

}  // namespace
}  // namespace sf::dem
