// Taylor-Green vortex on a periodic square: u = u0 exp(-2 nu k^2 t) (-cos kx sin ky,
// sin kx cos ky). Diffusive scaling (tau fixed, dt ~ h^2) gives second order.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "sandflow/lb/lattice.hpp"

namespace sf {
namespace {

double taylorGreenError(int n, lb::Collision collision) {
  const double L = 1.0, nu = 0.01, u0 = 0.01, rho0 = 1.0, tau = 0.8;
  const double k = 2 * std::numbers::pi / L;
  lb::LatticeDef def;
  def.size = Vec2(L, L);
  def.cells = n;
  def.viscosity = nu;
  def.tau = tau;
  def.collision = collision;
  for (auto& side : def.sides) side = lb::SideDef{lb::SideKind::periodic};
  lb::Lattice lattice(lb::resolve(def));
  const double cs2 = std::pow(lattice.params().soundSpeed(), 2);
  lattice.initialize([&](const Vec2& x, double& rho, Vec2& u) {
    u = u0 *
        Vec2(-std::cos(k * x.x()) * std::sin(k * x.y()), std::sin(k * x.x()) * std::cos(k * x.y()));
    const double p = -rho0 * u0 * u0 / 4 * (std::cos(2 * k * x.x()) + std::cos(2 * k * x.y()));
    rho = rho0 + p / cs2;
  });
  const double T = 0.625;  // a whole number of steps at every resolution used
  const long steps = std::lround(T / lattice.params().dt);
  for (long s = 0; s < steps; ++s) lattice.step();
  const double decay = std::exp(-2 * nu * k * k * T);
  double err2 = 0, ref2 = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec2 x = lattice.position(i, j);
      const Vec2 exact = u0 * decay *
                         Vec2(-std::cos(k * x.x()) * std::sin(k * x.y()),
                              std::sin(k * x.x()) * std::cos(k * x.y()));
      err2 += (lattice.velocity(i, j) - exact).squaredNorm();
      ref2 += exact.squaredNorm();
    }
  return std::sqrt(err2 / ref2);
}

TEST(TaylorGreen, ConvergesSecondOrderUnderDiffusiveScaling) {
  for (lb::Collision c : {lb::Collision::bgk, lb::Collision::trt}) {
    double previous = 0;
    for (int n : {16, 32, 64}) {
      const double e = taylorGreenError(n, c);
      std::printf("%s N=%d: L2 error %.3e", c == lb::Collision::bgk ? "BGK" : "TRT", n, e);
      if (previous > 0) {
        const double slope = std::log2(previous / e);
        std::printf("  slope %.3f", slope);
        EXPECT_GE(slope, 1.8);
        EXPECT_LE(slope, 2.2);
      }
      std::printf("\n");
      previous = e;
    }
  }
}

}  // namespace
}  // namespace sf
