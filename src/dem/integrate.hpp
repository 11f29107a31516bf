#pragma once
// The integrators' update of every slot's motion from its force and torque
// (physics.md §4), over raw arrays: the loop keeps its pointers in registers
// and runs in chunks on any number of threads (each slot on its own, so the
// result does not depend on the count).
#include <cstdint>

#include "sandflow/dem/assembly.hpp"

namespace sf::dem::detail {

struct Motion {
  Vec2 *x, *v, *vHalf;
  double *angle, *w, *wHalf;
  const Vec2* force;
  const double *torque, *mass, *inertia;
  const std::uint8_t* hold;
};

// Slots whose half-step velocity is not set yet (new, or set by hand): v(-dt/2)
// from v(0), so that central difference is second order from the first step.
void startCentral(const Motion& m, std::uint8_t* started, int n, double dt);
void advance(Integrator scheme, const Motion& m, int n, double dt, int threads);

}  // namespace sf::dem::detail
