#include "element_sums.hpp"

namespace sf::dem::detail {

double sumElements(const SumInputs& in, int begin, int end) {
  const Vec2 *applied = in.applied, *own = in.acceleration, *fluid = in.fluid,
             *buoyancy = in.buoyancy;
  const double *mass = in.mass, *appliedTorque = in.appliedTorque, *fluidTorque = in.fluidTorque;
  const std::uint32_t* __restrict start = in.start;
  const std::uint32_t* __restrict entry = in.entry;
  const double* __restrict fx = in.fx;
  const double* __restrict fy = in.fy;
  const double* __restrict ta = in.ta;
  const double* __restrict tb = in.tb;
  const std::int32_t* __restrict touches = in.touches;
  Vec2* __restrict force = in.force;
  double* __restrict torque = in.torque;
  char* __restrict touching = in.touching;
  const Vec2 g = in.gravity;
  double probe = 0;
  for (int s = begin; s < end; ++s) {
    // The same operations, in the same order, as the serial pass down the
    // list (force[a] -= f, force[b] += f): x + (-y) is x - y, bit for bit.
    Vec2 f = applied[s] + mass[s] * (g + own[s]) + fluid[s] + buoyancy[s];
    double fxs = f.x(), fys = f.y(), t = appliedTorque[s] + fluidTorque[s];
    std::int32_t touch = 0;
    for (std::uint32_t e = start[s], last = start[s + 1]; e < last; ++e) {
      const std::uint32_t q = entry[e];
      const std::uint32_t k = q >> 1;
      const bool onB = q & 1;
      const double sign = onB ? 1.0 : -1.0;
      fxs += sign * fx[k];
      fys += sign * fy[k];
      t += onB ? tb[k] : -ta[k];
      touch |= touches[k];
    }
    force[s] = Vec2(fxs, fys), torque[s] = t, touching[s] = char(touch);
    // x - x is 0 for finite x and NaN otherwise.
    probe += (fxs - fxs) + (fys - fys) + (t - t);
  }
  return probe;
}

}  // namespace sf::dem::detail
