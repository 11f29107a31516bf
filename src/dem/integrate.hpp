#pragma once
// The integrators (physics.md §4) as two stages around the force evaluation:
// preForce moves what a scheme moves before the forces (Verlet's first kick
// and drift) and readies the half-step velocities of new elements; postForce
// advances with the new forces. Both run over raw arrays: the loops keep
// their pointers in registers and run in chunks on any number of threads
// (each slot on its own, so the result does not depend on the count).
#include <cstdint>

#include "sandflow/dem/assembly.hpp"

namespace sf::dem::detail {

struct Motion {
  Vec2 *x, *v, *vHalf;
  double *angle, *w, *wHalf;
  const Vec2* force;
  const double *torque, *mass, *inertia;
  const std::uint8_t* hold;
  std::uint8_t* started;  // half-step velocity set (see preForce, postForce)
  // The step's accelerations f / m and torque / I, held degrees of freedom
  // included (accelerate() writes them; the fused postForce reads them).
  Vec2* acc;
  double* alpha;
};

// What the speed checks read besides the motion (Assembly::checkSpeeds).
struct SpeedInputs {
  const double *reach, *extent;
  const char* touching;  // in contact this step
  char* suspect;         // out: 1 where the exact check must look
};

// Whether the scheme kicks with forces before it computes new ones: an
// element without a previous step (new, or set by hand) then needs its force
// at its present state first (Assembly::startForces), and is started.
inline bool kicksBeforeForces(Integrator scheme) {
  return scheme == Integrator::verlet;
}

// Verlet: kick by half a step with the last forces, then drift. Central and
// Euler: elements not started take v(t) as the half-step velocity the
// velocity-dependent forces (damping) see.
void preForce(Integrator scheme, const Motion& m, int n, double dt, int threads);
// Central: elements not started get v(-dt/2) from v(0) and the new force,
// so that central difference is second order from the first step; then
// kick and drift. Euler: kick and drift. Verlet: the second half kick.
void postForce(Integrator scheme, const Motion& m, int n, double dt, int threads);
// The step's accelerations of every slot, in one vector pass, and a sieve
// for the speed checks: a slot is marked suspect unless a bound that is
// never below what the exact check computes (the triangle inequality, no
// cancellation) passes with a margin, so that the exact check, run on the
// suspects alone, refuses exactly what it refused on every slot. Returns
// whether any slot is suspect.
bool accelerate(const Motion& m, const SpeedInputs& in, int n, double dt, int threads);
// postForce with the accelerations accelerate() left (the same bits: the
// same divisions, done once for the checks and the kicks).
void postForceFused(Integrator scheme, const Motion& m, int n, double dt, int threads);
// Central difference keeps v(t - dt/2): a step of `to` after steps of `from`
// needs v(t - to/2) = v(t) - (v(t) - v(t - from/2)) to/from instead, or the
// change of step would kick every element by a (from - to)/2.
void changeStep(Integrator scheme, const Motion& m, int n, double from, double to);

}  // namespace sf::dem::detail
