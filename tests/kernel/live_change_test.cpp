// A change of tau or the timestep on a live lattice keeps the physical flow
// (Lattice::reconfigure, src/lb/lattice_convert.cpp). The flow: a decaying
// shear wave on a periodic square under a uniform body force,
//   u_x(y, t) = U exp(-nu k^2 t) sin(k y) + F t / rho0,  u_y = 0,
// exact for the incompressible equations (the force only shifts the frame).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <vector>

#include "sandflow/lb/lattice.hpp"

namespace sf {
namespace {

constexpr double kL = 1.0, kNu = 0.01, kU = 0.01, kForce = 2e-4, kRho = 1.0;
const double kK = 2 * std::numbers::pi / kL;

lb::LatticeDef waveDef(int cells, double tau, lb::Collision c, lb::ForceScheme s) {
  lb::LatticeDef def;
  def.size = Vec2(kL, kL);
  def.cells = cells;
  def.viscosity = kNu;
  def.tau = tau;
  def.collision = c;
  def.forceScheme = s;
  def.forcing = Vec2(kForce, 0);
  for (auto& side : def.sides) side = lb::SideDef{lb::SideKind::periodic};
  return def;
}

double exactU(double y, double t) {
  return kU * std::exp(-kNu * kK * kK * t) * std::sin(kK * y) + kForce * t / kRho;
}

void startWave(lb::Lattice& lattice) {
  lattice.initialize([](const Vec2& x, double& rho, Vec2& u) {
    rho = kRho;
    u = Vec2(exactU(x.y(), 0), 0);
  });
}

// Runs until time t (a whole number of steps at the lattice's timestep).
double runTo(lb::Lattice& lattice, double now, double t) {
  const long steps = std::lround((t - now) / lattice.params().dt);
  for (long s = 0; s < steps; ++s) lattice.step();
  return now + steps * lattice.params().dt;
}

// Relative L2 error of u_x against the exact wave, and the largest |u_y|.
double waveError(const lb::Lattice& lattice, double t) {
  double err2 = 0, ref2 = 0;
  for (int j = 0; j < lattice.ny(); ++j)
    for (int i = 0; i < lattice.nx(); ++i) {
      const Vec2 u = lattice.velocity(i, j);
      const double exact = exactU(lattice.position(i, j).y(), t);
      err2 += std::pow(u.x() - exact, 2) + u.y() * u.y();
      ref2 += exact * exact;
    }
  return std::sqrt(err2 / ref2);
}

// The non-equilibrium part of what node (i, j) pulls for its next collision.
void pulledNonEquilibrium(const lb::Lattice& lattice, int i, int j, double (&n)[9]) {
  double rho = 0, jx = 0, jy = 0;
  for (int d = 0; d < 9; ++d) {
    const int si = (i - lb::d2q9::ex[d] + lattice.nx()) % lattice.nx();
    const int sj = (j - lb::d2q9::ey[d] + lattice.ny()) % lattice.ny();
    n[d] = lattice.population(d, si, sj);
    rho += n[d], jx += lb::d2q9::ex[d] * n[d], jy += lb::d2q9::ey[d] * n[d];
  }
  for (int d = 0; d < 9; ++d) n[d] -= lb::equilibrium(d, rho, jx / rho, jy / rho);
}

// || N(a) - N(b) || / || N(b) || over the lattice.
double nonEquilibriumMismatch(const lb::Lattice& a, const lb::Lattice& b) {
  double diff2 = 0, ref2 = 0;
  for (int j = 0; j < a.ny(); ++j)
    for (int i = 0; i < a.nx(); ++i) {
      double na[9], nb[9];
      pulledNonEquilibrium(a, i, j, na);
      pulledNonEquilibrium(b, i, j, nb);
      for (int d = 0; d < 9; ++d) diff2 += std::pow(na[d] - nb[d], 2), ref2 += nb[d] * nb[d];
    }
  return std::sqrt(diff2 / ref2);
}

struct Scheme {
  lb::Collision collision;
  lb::ForceScheme force;
  const char* name;
};
constexpr Scheme kSchemes[] = {{lb::Collision::bgk, lb::ForceScheme::nodal, "BGK nodal"},
                               {lb::Collision::bgk, lb::ForceScheme::guo, "BGK Guo"},
                               {lb::Collision::trt, lb::ForceScheme::nodal, "TRT nodal"},
                               {lb::Collision::trt, lb::ForceScheme::guo, "TRT Guo"}};

// tau 1 (the default, whose stored state holds no non-equilibrium part) to
// 0.65: the timestep falls to 0.3 of itself; and back up, 0.65 to 1.
TEST(LiveChange, ShearWaveStaysOnItsDecayWhenTauChangesHalfway) {
  const int n = 32;
  const double T = 4.0;  // the wave decays to exp(-nu k^2 T) = 0.2
  for (const Scheme& s : kSchemes)
    for (const auto& [tau0, tau1] : {std::pair{1.0, 0.65}, std::pair{0.65, 1.0}}) {
      double worst = 0;  // the two unchanged runs' error: the discretisation's
      for (double tau : {tau0, tau1}) {
        lb::Lattice plain(lb::resolve(waveDef(n, tau, s.collision, s.force)));
        startWave(plain);
        worst = std::max(worst, waveError(plain, runTo(plain, 0, T)));
      }
      lb::Lattice changed(lb::resolve(waveDef(n, tau0, s.collision, s.force)));
      startWave(changed);
      double t = runTo(changed, 0, T / 2);
      const double before = waveError(changed, t);
      changed.reconfigure(lb::resolve(waveDef(n, tau1, s.collision, s.force)));
      const double across = waveError(changed, t);
      t = runTo(changed, t, T);
      const double after = waveError(changed, t);
      std::printf(
          "%s tau %.2f -> %.2f: error %.2e before, %.2e just after, %.2e at T (%.2e "
          "unchanged)\n",
          s.name, tau0, tau1, before, across, after, worst);
      // The reported field carries over to round-off ...
      EXPECT_NEAR(across, before, 1e-9) << s.name;
      // ... and the run stays within the discretisation error of either
      // timestep (a flow kept in lattice units is off by a factor 0.3 or 3).
      EXPECT_LT(after, 1.5 * worst) << s.name;
    }
}

// The non-equilibrium part after the change is that of a run made at the new
// timestep from the start: 0.4% (BGK) and 0.2% (TRT) off. Scaling the odd
// part as the even one (tau dt) leaves 1.8% and 3.9%.
TEST(LiveChange, NonEquilibriumMatchesARunAtTheNewStep) {
  const int n = 32;
  for (const Scheme& s : kSchemes) {
    lb::Lattice changed(lb::resolve(waveDef(n, 0.8, s.collision, s.force)));
    startWave(changed);
    const double t = runTo(changed, 0, 2.0);
    changed.reconfigure(lb::resolve(waveDef(n, 0.65, s.collision, s.force)));
    lb::Lattice reference(lb::resolve(waveDef(n, 0.65, s.collision, s.force)));
    startWave(reference);
    ASSERT_EQ(runTo(reference, 0, t), t);
    const double mismatch = nonEquilibriumMismatch(changed, reference);
    std::printf("%s: non-equilibrium part off by %.2e of a run at the new step\n", s.name,
                mismatch);
    EXPECT_LT(mismatch, 0.01) << s.name;
  }
}

// A change that changes nothing the step uses leaves every population as it was.
TEST(LiveChange, SameStepLeavesThePopulations) {
  lb::Lattice lattice(lb::resolve(waveDef(16, 0.8, lb::Collision::trt, lb::ForceScheme::guo)));
  startWave(lattice);
  runTo(lattice, 0, 0.5);
  const std::vector<double> before = lattice.populations();
  lattice.reconfigure(lb::resolve(lattice.params().def));
  EXPECT_EQ(lattice.populations(), before);
}

}  // namespace
}  // namespace sf
