#pragma once
// Scenes for the DEM kernel tests: discs, walls, and stepping through an
// impact.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "sandflow/dem/assembly.hpp"

namespace sf::dem::test {

inline int addDisc(Assembly& a, Vec2 x, double r, Vec2 v = Vec2::Zero(), int material = 1) {
  ElementDef d;
  d.shape = std::make_unique<Disc>(r);
  d.material = material;
  d.x = x;
  d.v = v;
  return a.add(std::move(d));
}

// A held wall from p to q.
inline int addWall(Assembly& a, Vec2 p, Vec2 q, int material = 1, double thickness = 1e-3) {
  ElementDef d;
  d.shape = std::make_unique<Wall>((q - p).norm(), thickness);
  d.material = material;
  d.x = 0.5 * (p + q);
  d.angle = std::atan2((q - p).y(), (q - p).x());
  d.hold = holdX | holdY | holdRotation;
  return a.add(std::move(d));
}

// Steps until the contacts that began have all ended (fails after 100,000).
inline void runUntilApart(Assembly& a, double dt) {
  bool touched = false;
  for (int s = 0; s < 100000; ++s) {
    a.step(dt, Vec2::Zero());
    if (a.touchingCount() > 0)
      touched = true;
    else if (touched)
      return;
  }
  ADD_FAILURE() << "the impacts did not end";
}

}  // namespace sf::dem::test
