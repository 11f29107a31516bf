#include "integrate.hpp"

#include <omp.h>
#include <algorithm>
#include <cstring>

#include "sandflow/core/parallel.hpp"

namespace sf::dem::detail {
namespace {

// The acceleration, zero along held degrees of freedom.
struct Accel {
  double x, y, alpha;
};
[[gnu::always_inline]] inline Accel accel(const Motion& m, int s) {
  const std::uint8_t h = m.hold[s];
  return {h & holdX ? 0.0 : m.force[s].x() / m.mass[s],
          h & holdY ? 0.0 : m.force[s].y() / m.mass[s],
          h & holdRotation ? 0.0 : m.torque[s] / m.inertia[s]};
}

bool anyUnstarted(const Motion& m, int n) {
  return std::memchr(m.started, 0, std::size_t(n)) != nullptr;
}

// Verlet's first half kick and drift, with the forces of the last step.
void kickDriftRange(const Motion& in, int begin, int end, double dt) {
  Vec2* __restrict x = in.x, * __restrict v = in.v, * __restrict vHalf = in.vHalf;
  double* __restrict angle = in.angle, * __restrict w = in.w, * __restrict wHalf = in.wHalf;
  for (int s = begin; s < end; ++s) {
    const Accel a = accel(in, s);
    vHalf[s] = v[s] + 0.5 * dt * Vec2(a.x, a.y);
    wHalf[s] = w[s] + 0.5 * dt * a.alpha;
    x[s] += dt * vHalf[s];
    angle[s] += dt * wHalf[s];
  }
}

template <Integrator scheme>
void advanceRange(const Motion& in, int begin, int end, double dt) {
  Vec2* __restrict x = in.x, * __restrict v = in.v, * __restrict vHalf = in.vHalf;
  double* __restrict angle = in.angle, * __restrict w = in.w, * __restrict wHalf = in.wHalf;
  for (int s = begin; s < end; ++s) {
    const Accel a = accel(in, s);
    if constexpr (scheme == Integrator::central) {
      const Vec2 vh = vHalf[s] + dt * Vec2(a.x, a.y);
      const double wh = wHalf[s] + dt * a.alpha;
      vHalf[s] = vh, wHalf[s] = wh;
      x[s] += dt * vh;
      angle[s] += dt * wh;
      v[s] = vh + 0.5 * dt * Vec2(a.x, a.y);  // velocity at the same time as the position
      w[s] = wh + 0.5 * dt * a.alpha;
    } else if constexpr (scheme == Integrator::euler) {  // the thesis's first-order scheme
      const Vec2 vn = v[s] + dt * Vec2(a.x, a.y);
      const double wn = w[s] + dt * a.alpha;
      v[s] = vn, w[s] = wn;
      x[s] += dt * vn;
      angle[s] += dt * wn;
    } else {  // verlet: second half kick; the drift was done before the forces
      v[s] = vHalf[s] + 0.5 * dt * Vec2(a.x, a.y);
      w[s] = wHalf[s] + 0.5 * dt * a.alpha;
    }
  }
}

// Runs range(m, begin, end, dt) over [0, n) in chunks, one per thread. Below
// a few thousand slots a parallel region costs more than it saves.
template <class Range>
void overSlots(Range range, const Motion& m, int n, double dt, int threads) {
  const int t = parallel::team(n, parallel::kIntegrateSlots, threads);
  if (t == 1) return range(m, 0, n, dt);
#pragma omp parallel num_threads(t)
  {
    const int count = omp_get_num_threads(), me = omp_get_thread_num();
    range(m, int(std::int64_t(n) * me / count), int(std::int64_t(n) * (me + 1) / count), dt);
  }
}

void startCentral(const Motion& m, int n, double dt) {
  for (int s = 0; s < n; ++s)
    if (!m.started[s]) {
      const Accel a = accel(m, s);
      m.vHalf[s] = m.v[s] - 0.5 * dt * Vec2(a.x, a.y);
      m.wHalf[s] = m.w[s] - 0.5 * dt * a.alpha;
      m.started[s] = 1;
    }
}

}  // namespace

void changeStep(Integrator scheme, const Motion& m, int n, double from, double to) {
  if (scheme != Integrator::central) return;  // the others keep v(t)
  const double r = to / from;
  for (int s = 0; s < n; ++s)
    if (m.started[s]) {
      m.vHalf[s] = m.v[s] - (m.v[s] - m.vHalf[s]) * r;
      m.wHalf[s] = m.w[s] - (m.w[s] - m.wHalf[s]) * r;
    }
}

void preForce(Integrator scheme, const Motion& m, int n, double dt, int threads) {
  if (scheme == Integrator::verlet) return overSlots(kickDriftRange, m, n, dt, threads);
  // Velocity-dependent forces (damping) use the last half-step velocity: the
  // extrapolated v(t) = v(t - dt/2) + a(t - dt) dt/2 feeds back the previous
  // acceleration and sustains limit cycles of the contact-rotation modes at
  // dt_crit/10 (a settling bed never came to rest).
  if (anyUnstarted(m, n))
    for (int s = 0; s < n; ++s)
      if (!m.started[s]) m.vHalf[s] = m.v[s], m.wHalf[s] = m.w[s];
}

void postForce(Integrator scheme, const Motion& m, int n, double dt, int threads) {
  switch (scheme) {
    case Integrator::central:
      if (anyUnstarted(m, n)) startCentral(m, n, dt);
      return overSlots(advanceRange<Integrator::central>, m, n, dt, threads);
    case Integrator::euler:
      return overSlots(advanceRange<Integrator::euler>, m, n, dt, threads);
    case Integrator::verlet:
      return overSlots(advanceRange<Integrator::verlet>, m, n, dt, threads);
  }
}

}  // namespace sf::dem::detail
