// The DEM benchmark bed of shared/reference/dem-bed.md: N discs, radii uniform
// in [0.5, 1] mm, settled under gravity in a box open at the top, then timed.
// Prints particle-steps per second of the timed phase, contacts per disc, the
// kinetic energy at its end and the time per step by stage.
//
//   sandflow_dem_bed N ?settle? ?timed? ?threads?
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>

#include "sandflow/dem/assembly.hpp"

using namespace sf;
using namespace sf::dem;

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 10000;
  const long settle = argc > 2 ? std::atol(argv[2]) : 100000;
  const long timed = argc > 3 ? std::atol(argv[3]) : 2000;
  const int threads = argc > 4 ? std::atoi(argv[4]) : 1;

  Assembly a;
  a.threads = threads;
  Material m{"glass"};
  m.density = 2650;
  m.kn = m.ks = 1e5;
  m.restitution = 0.5;
  m.friction = 0.5;
  const int mat = a.materials().add(m);

  const double pitch = 2.05e-3;
  const int cols = (n + 127) / 128;
  const int rows = (n + cols - 1) / cols;
  const double W = (cols + 0.25) * pitch, H = 1.05e-3 + rows * pitch + 0.01;
  auto wall = [&](Vec2 p, Vec2 q) {
    ElementDef d;
    d.shape = std::make_unique<Wall>((q - p).norm(), 1e-3);
    d.material = mat;
    d.x = 0.5 * (p + q);
    d.angle = std::atan2((q - p).y(), (q - p).x());
    d.hold = holdX | holdY | holdRotation;
    a.add(std::move(d));
  };
  wall({0, 0}, {W, 0});
  wall({0, 0}, {0, H});
  wall({W, 0}, {W, H});
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> radius(0.5e-3, 1.0e-3), jitter(-0.02e-3, 0.02e-3);
  for (int i = 0; i < n; ++i) {
    const int row = i / cols;
    ElementDef d;
    d.shape = std::make_unique<Disc>(radius(rng));
    d.material = mat;
    d.x = Vec2((i % cols + 0.5 + 0.25 * (row % 2)) * pitch + jitter(rng), 1.05e-3 + row * pitch);
    a.add(std::move(d));
  }
  const double mMin = 2650 * std::numbers::pi * 0.25e-6;
  const double dt = 2 * std::sqrt(mMin / 1e5) / 20;
  const Vec2 g(0, -9.81);
  using Clock = std::chrono::steady_clock;
  const auto s0 = Clock::now();
  for (long s = 0; s < settle; ++s) a.step(dt, g);
  const double settleSeconds = std::chrono::duration<double>(Clock::now() - s0).count();
  const StepTimes before = a.times();
  double contacts = 0;
  const auto t0 = Clock::now();
  for (long s = 0; s < timed; ++s) {
    a.step(dt, g);
    contacts += double(a.touchingCount());
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  const StepTimes& after = a.times();
  const double per = 1e6 / double(timed);
  std::printf(
      "N=%d threads=%d dt=%.3g settle_s=%.1f timed_s=%.3f psps=%.4g contacts_per_disc=%.3f "
      "kinetic=%.3g sort_us=%.1f narrow_us=%.1f integrate_us=%.1f builds=%lld\n",
      n, threads, dt, settleSeconds, seconds, n * double(timed) / seconds, contacts / timed / n,
      a.kineticEnergy(), (after.sort - before.sort) * per, (after.narrow - before.narrow) * per,
      (after.integrate - before.integrate) * per, a.broadPhaseBuilds());
  return 0;
}
