#include <gtest/gtest.h>

#include "sandflow/lb/lattice.hpp"

TEST(Lattice, Builds) {
  sf::lb::LatticeDef def;
  def.size = sf::Vec2(1, 1);
  def.cells = 16;
  def.viscosity = 0.1;
  sf::lb::Lattice l(sf::lb::resolve(def));
  l.step();
  EXPECT_EQ(l.nx(), 16);
}
