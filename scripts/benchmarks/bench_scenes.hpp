#pragma once
// Scenes the benchmarks share, in lattice units (h = dt = 1).
#include <cmath>
#include <memory>
#include <numbers>
#include <random>

#include "sandflow/sim/manager.hpp"

namespace sf::bench {

// An n x n channel: periodic in x, no-slip bottom and top, tau 0.8, driven
// by a small body force.
inline lb::LatticeDef channel(int n) {
  lb::LatticeDef def;
  def.size = Vec2(n, n);
  def.cells = n;
  def.tau = 0.8;
  def.timestep = 1.0;
  def.forcing = Vec2(1e-7, 0);
  return def;
}

// Discs of radius 8 of `material` on a jittered grid with random velocities,
// covering `fraction` of an n x n lattice, clear of its walls; returns how
// many were made.
inline int scatterDiscs(sim::Manager& m, int n, double fraction, unsigned seed, int material) {
  const double r = 8.0, area = std::numbers::pi * r * r;
  const int count = int(fraction * n * n / area);
  const int perRow = int(std::ceil(std::sqrt(double(count))));
  const double pitch = double(n) / perRow;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  int made = 0;
  for (int k = 0; k < count; ++k) {
    dem::ElementDef d;
    d.shape = std::make_unique<dem::Disc>(r);
    d.material = material;
    d.x = Vec2((k % perRow + 0.5) * pitch + 0.1 * pitch * u(rng),
               (k / perRow + 0.5) * pitch + 0.1 * pitch * u(rng));
    if (d.x.y() < r + 2 || d.x.y() > n - r - 2) continue;
    d.v = 0.01 * Vec2(u(rng), u(rng));
    d.w = 0.001 * u(rng);
    m.assembly().add(std::move(d));
    ++made;
  }
  return made;
}

}  // namespace sf::bench
