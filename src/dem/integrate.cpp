#include "integrate.hpp"

#include <omp.h>
#include <algorithm>
#include <cstring>

#include "sandflow/core/kernel_isa.hpp"
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

// The kicks and drift with the accelerations of accelerate(): held degrees
// of freedom keep their velocity (a select, not a branch, so that the loop
// is one vector pass down the columns).
template <Integrator scheme>
SF_KERNEL_CLONES void advanceFusedRange(const Motion& in, int begin, int end, double dt) {
  double* __restrict x = in.x[0].data();  // Vec2 is two packed doubles
  double* __restrict v = in.v[0].data();
  double* __restrict vHalf = in.vHalf[0].data();
  double* __restrict angle = in.angle;
  double* __restrict w = in.w;
  double* __restrict wHalf = in.wHalf;
  const double* __restrict acc = in.acc[0].data();
  const double* __restrict alpha = in.alpha;
  const std::uint8_t* __restrict hold = in.hold;
  const double half = 0.5 * dt;
#pragma omp simd
  for (int s = begin; s < end; ++s) {
    const std::uint8_t h = hold[s];
    const double gx = acc[2 * s], gy = acc[2 * s + 1], ga = alpha[s];  // loaded either way
    const double ax = h & holdX ? 0.0 : gx, ay = h & holdY ? 0.0 : gy;
    const double al = h & holdRotation ? 0.0 : ga;
    if constexpr (scheme == Integrator::central) {
      const double vx = vHalf[2 * s] + dt * ax, vy = vHalf[2 * s + 1] + dt * ay;
      const double wh = wHalf[s] + dt * al;
      vHalf[2 * s] = vx, vHalf[2 * s + 1] = vy, wHalf[s] = wh;
      x[2 * s] += dt * vx, x[2 * s + 1] += dt * vy;
      angle[s] += dt * wh;
      v[2 * s] = vx + half * ax, v[2 * s + 1] = vy + half * ay;
      w[s] = wh + half * al;
    } else if constexpr (scheme == Integrator::euler) {
      const double vx = v[2 * s] + dt * ax, vy = v[2 * s + 1] + dt * ay;
      const double wn = w[s] + dt * al;
      v[2 * s] = vx, v[2 * s + 1] = vy, w[s] = wn;
      x[2 * s] += dt * vx, x[2 * s + 1] += dt * vy;
      angle[s] += dt * wn;
    } else {
      v[2 * s] = vHalf[2 * s] + half * ax, v[2 * s + 1] = vHalf[2 * s + 1] + half * ay;
      w[s] = wHalf[s] + half * al;
    }
  }
}

SF_KERNEL_CLONES bool sieveRange(const Motion& m, const SpeedInputs& in, int begin, int end,
                                 double dt) {
  const double* __restrict x = m.x[0].data();
  const double* __restrict v = m.v[0].data();
  const double* __restrict angle = m.angle;
  const double* __restrict w = m.w;
  const double* __restrict f = m.force[0].data();
  const double* __restrict torque = m.torque;
  const double* __restrict mass = m.mass;
  const double* __restrict inertia = m.inertia;
  double* __restrict acc = m.acc[0].data();
  double* __restrict alpha = m.alpha;
  const std::uint8_t* __restrict hold = m.hold;
  const double* __restrict reach = in.reach;
  const double* __restrict extent = in.extent;
  const char* __restrict touching = in.touching;
  char* __restrict suspect = in.suspect;
  int any = 0;
#pragma omp simd reduction(| : any)
  for (int s = begin; s < end; ++s) {
    const double ax = f[2 * s] / mass[s], ay = f[2 * s + 1] / mass[s];
    const double al = torque[s] / inertia[s];
    acc[2 * s] = ax, acc[2 * s + 1] = ay, alpha[s] = al;
    const double vx = v[2 * s], vy = v[2 * s + 1], ws = w[s];
    // In contact: |v + dt a| + |w + dt alpha| reach, bounded term by term.
    const double bound = (std::abs(vx) + std::abs(dt * ax) + std::abs(vy) + std::abs(dt * ay) +
                          (std::abs(ws) + std::abs(dt * al)) * reach[s]) *
                         dt;
    const bool slowEnough = bound <= 0.5 * extent[s] * (1 - 1e-9);
    // In free flight: where it goes is finite (held or not: a held degree
    // of freedom that stays put is finite too).
    const double vfx = vx + dt * ax, vfy = vy + dt * ay, wf = ws + dt * al;
    const double probe = (vfx - vfx) + (vfy - vfy) + (wf - wf) +
                         ((x[2 * s] + dt * vfx) - (x[2 * s] + dt * vfx)) +
                         ((x[2 * s + 1] + dt * vfy) - (x[2 * s + 1] + dt * vfy)) +
                         ((angle[s] + dt * wf) - (angle[s] + dt * wf));
    const bool finite = probe == 0;
    // Fully held: invMass and invInertia 0 (Assembly::updateMass), one byte to read.
    const bool fixed = (hold[s] & (holdX | holdY | holdRotation)) == (holdX | holdY | holdRotation);
    const bool ok = fixed || (touching[s] ? slowEnough : finite);
    suspect[s] = !ok;
    any |= !ok;
  }
  return any != 0;
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

bool accelerate(const Motion& m, const SpeedInputs& in, int n, double dt, int threads) {
  const int t = parallel::team(n, parallel::kIntegrateSlots, threads);
  if (t == 1) return sieveRange(m, in, 0, n, dt);
  int any = 0;
#pragma omp parallel num_threads(t) reduction(| : any)
  {
    const int count = omp_get_num_threads(), me = omp_get_thread_num();
    any |= sieveRange(m, in, int(std::int64_t(n) * me / count),
                      int(std::int64_t(n) * (me + 1) / count), dt);
  }
  return any != 0;
}

void postForceFused(Integrator scheme, const Motion& m, int n, double dt, int threads) {
  switch (scheme) {
    case Integrator::central:
      if (anyUnstarted(m, n)) startCentral(m, n, dt);
      return overSlots(advanceFusedRange<Integrator::central>, m, n, dt, threads);
    case Integrator::euler:
      return overSlots(advanceFusedRange<Integrator::euler>, m, n, dt, threads);
    case Integrator::verlet:
      return overSlots(advanceFusedRange<Integrator::verlet>, m, n, dt, threads);
  }
}

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
