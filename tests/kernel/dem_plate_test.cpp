// A plate holding a prescribed stress on a specimen (servo).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sandflow/dem/assembly.hpp"

namespace sf::dem {
namespace {

TEST(DemPlate, HoldsItsStressOnASpecimen) {
  Assembly a;
  Material m{"sand"};
  m.kn = m.ks = 1e6;
  m.restitution = 0.2;
  m.friction = 0.3;
  const int sand = a.materials().add(m);
  m.name = "steel";
  m.friction = 0;  // frictionless walls: the floor carries the whole plate load
  const int steel = a.materials().add(m);
  auto wall = [&](Vec2 p, Vec2 q) {
    ElementDef d;
    d.shape = std::make_unique<Wall>((q - p).norm(), 1e-3);
    d.material = steel;
    d.x = 0.5 * (p + q);
    d.angle = std::atan2((q - p).y(), (q - p).x());
    d.hold = holdX | holdY | holdRotation;
    return a.add(std::move(d));
  };
  const double W = 0.02, H = 0.03;
  const int floor = wall({0, 0}, {W, 0});
  wall({0, 0}, {0, 2 * H});
  wall({W, 0}, {W, 2 * H});
  const int plate = wall({W, H}, {0, H});  // left normal points down, into the specimen
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 60; ++k) {
    ElementDef d;
    d.shape = std::make_unique<Disc>(0.8e-3 + 0.3e-3 * u(rng));
    d.material = sand;
    d.x = Vec2((k % 8 + 0.6) * 2.3e-3, (k / 8 + 0.6) * 2.3e-3);
    a.add(std::move(d));
  }
  const double stress = 2e3;  // N/m^2: load 40 N/m on the 2 cm plate
  a.setPlateStress(plate, stress);
  const double dt = a.criticalTimestep() / 10;
  for (int s = 0; s < 60000; ++s) a.step(dt, Vec2::Zero());
  const double load = a.contactForce(a.slot(plate)).y();  // grains push the plate up
  EXPECT_NEAR(load / (stress * W), 1.0, 1e-3);
  EXPECT_NEAR(-a.contactForce(a.slot(floor)).y() / (stress * W), 1.0, 1e-3);
  EXPECT_LT(a.bodies().x[a.slot(plate)].y(), H);  // it moved down onto the grains
}

}  // namespace
}  // namespace sf::dem
