#pragma once
// Small helpers shared by the lattice tests: build a lattice from a definition,
// run to a steady state, compare a profile with an exact one.
#include <cmath>
#include <functional>

#include "sandflow/lb/lattice.hpp"

namespace sf::test {

inline lb::LatticeDef channelDef(int nx, int ny, double tau, double viscosity = 0.1) {
  lb::LatticeDef def;
  def.size = Vec2(nx, ny);
  def.cells = nx;
  def.viscosity = viscosity;
  def.tau = tau;
  return def;  // periodic in x, no-slip bottom and top
}

// Steps until the largest change of a velocity component over `check` steps,
// relative to the largest |component|, drops below `tolerance`. Returns the
// steps taken.
inline long runToSteady(lb::Lattice& lattice, double tolerance, long maxSteps, int check = 200) {
  auto snapshot = [&] {
    std::vector<double> u;
    for (int j = 0; j < lattice.ny(); ++j)
      for (int i = 0; i < lattice.nx(); ++i) {
        const Vec2 v = lattice.velocity(i, j);
        u.push_back(v.x());
        u.push_back(v.y());
      }
    return u;
  };
  std::vector<double> before = snapshot();
  long steps = 0;
  while (steps < maxSteps) {
    for (int k = 0; k < check; ++k) lattice.step();
    steps += check;
    const std::vector<double> after = snapshot();
    double change = 0, scale = 0;
    for (std::size_t k = 0; k < after.size(); ++k) {
      change = std::max(change, std::abs(after[k] - before[k]));
      scale = std::max(scale, std::abs(after[k]));
    }
    before = after;
    if (scale > 0 && change <= tolerance * scale) break;
  }
  return steps;
}

// Largest |u_x(i, j) - exact(y)| over column i, relative to the largest |exact|.
inline double profileError(const lb::Lattice& lattice, int i,
                           const std::function<double(double)>& exact) {
  double err = 0, scale = 0;
  for (int j = 0; j < lattice.ny(); ++j) {
    const double y = lattice.position(i, j).y();
    if (lattice.kind(i, j) != lb::NodeKind::fluid) continue;
    err = std::max(err, std::abs(lattice.velocity(i, j).x() - exact(y)));
    scale = std::max(scale, std::abs(exact(y)));
  }
  return err / scale;
}

}  // namespace sf::test
