// A live change of the timestep, tau, the collision or the forcing
// (Lattice::reconfigure): the populations are in lattice units, so they are
// converted to keep the physical flow (docs/lattice.md, "Live changes").
//
// Per node holding fluid, with s = dt'/dt:
//   velocity   u_lat' = s u_lat                (the physical velocity stays)
//   density    rho' - rho0 = s^2 (rho - rho0)  (the pressure's excess over
//              c_s^2 rho0 stays: c_s^2 goes as 1/dt^2)
//   non-equilibrium, from the Chapman-Enskog expansion in lattice units, where
//              grad u_lat = dt grad u and (tau+ - 1/2) = 3 nu dt / h^2:
//              even part f1+ = -tau+ w rho/c_s^2 Q:grad u_lat, so tau+ dt;
//              odd part  f2- ~ tau- (tau+ - 1/2) grad^2 u_lat, so tau- dt^2
//              (a uniform force's odd share lies in the equilibrium, below).
// A node's stored state is post-collision, and at tau = 1 it holds no trace of N,
// the pre-collision non-equilibrium part. So each node's pre-collision state
// is rebuilt, converted and collided again with the new parameters (by its own
// operator: the fluid's, or a covered cell's Noble-Torczynski one):
//   - its density and first moment from the stored post-collision moments,
//     undoing what the collision gave (F, and a covered cell's exchange);
//   - N from the populations the node pulls for its next collision, less the
//     equilibrium of their own raw moments. N has no mass and no momentum, so
//     the node then reports exactly the converted density and velocity.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "sandflow/core/error.hpp"

#include "sandflow/lb/lattice.hpp"

namespace sf::lb {
namespace {

using d2q9::Q;

struct Scales {
  double rho0, density, velocity, even, odd;
};

Scales scalesBetween(const ResolvedLattice& from, const ResolvedLattice& to) {
  const double s = to.dt / from.dt;
  return {from.def.density, s * s, s, to.tau * s / from.tau,
          to.tauMinus() * s * s / from.tauMinus()};
}

// The non-equilibrium part of the pulled populations f, in place.
void nonEquilibrium(double (&f)[Q]) {
  double rho = 0, jx = 0, jy = 0;
  for (int i = 0; i < Q; ++i) rho += f[i], jx += d2q9::ex[i] * f[i], jy += d2q9::ey[i] * f[i];
  double feq[Q];
  equilibria(rho, jx / rho, jy / rho, feq);
  for (int i = 0; i < Q; ++i) f[i] -= feq[i];
}

// Guo's velocity carries half the force: u = (j + F/2) / rho.
double halfForce(const StepContext& ctx) {
  return ctx.forceScheme == ForceScheme::guo ? 0.5 : 0.0;
}

// The pre-collision populations under `to` of a node whose pre-collision
// density and raw first moment under `from` were rho, j, with non-equilibrium
// part n: written into n.
void convertNode(const StepContext& from, const StepContext& to, const Scales& k, double rho,
                 Vec2 j, double (&n)[Q]) {
  const Vec2 F(from.params.fx, from.params.fy), F2(to.params.fx, to.params.fy);
  const Vec2 u = (j + halfForce(from) * F) / rho * k.velocity;
  const double rho2 = k.rho0 + (rho - k.rho0) * k.density;
  const Vec2 j2 = rho2 * u - halfForce(to) * F2;
  double feq[Q];
  equilibria(rho2, j2.x() / rho2, j2.y() / rho2, feq);
  n[0] = feq[0] + k.even * n[0];
  for (int i = 1; i <= 4; ++i) {
    const int o = d2q9::opposite[i];
    const double even = 0.5 * (n[i] + n[o]), odd = 0.5 * (n[i] - n[o]);
    n[i] = feq[i] + k.even * even + k.odd * odd;
    n[o] = feq[o] + k.even * even - k.odd * odd;
  }
}

}  // namespace

void Lattice::convertPopulations(const ResolvedLattice& next, double machLimit) {
  // The old state, read throughout from a copy (a node's new outputs sit
  // where its neighbours' old ones are read); the new written into f_, in
  // the same layout (walls' slots are filled after).
  const std::vector<double> old(f_, f_ + populationSlots());
  StepContext from = context();
  from.src = old.data();
  const StepContext to = contextFor(next);
  const Scales k = scalesBetween(p_, next);
  const Vec2 F(from.params.fx, from.params.fy);
  const double tau = p_.tau;
  const Slots s = slots();
  std::vector<CoveredCell> cells = covered_.cells;
  for (CoveredCell& c : cells) c.ux *= k.velocity, c.uy *= k.velocity;
  // The first node whose converted state is not finite (a scene blowing up
  // already: a solid at an absurd speed), to refuse the change with.
  std::int64_t bad = std::numeric_limits<std::int64_t>::max();
  const auto write = [&](std::int64_t x, const double(&f)[Q]) {
    bool finite = true;
    for (int i = 0; i < Q; ++i) f_[s.post(layout_, i, x)] = f[i], finite &= std::isfinite(f[i]);
    return finite ? std::numeric_limits<std::int64_t>::max() : x;
  };
  const auto pulled = [&](std::int64_t x, double(&n)[Q]) {
    for (int d = 0; d < Q; ++d) n[d] = old[s.input(layout_, d, x)];
  };
  // Fluid nodes and Zou-He edges: the collision added F to the first moment.
  const auto convertFluid = [&](std::int64_t x, double(&n)[Q]) {
    nonEquilibrium(n);
    double rho, jx, jy;
    moments(old.data(), layout_, x, rho, jx, jy);
    convertNode(from, to, k, rho, Vec2(jx, jy) - F, n);
    double u2;
    collide(to.collision, to.forceScheme, n, to.params, u2);
    return write(x, n);
  };
#pragma omp parallel for schedule(static) num_threads(threads_.get()) reduction(min : bad)
  for (int j = 0; j < p_.ny; ++j)
    for (int i = 0; i < p_.nx; ++i) {
      const std::int64_t x = index(i, j);
      if (kind_[x] != NodeKind::fluid) continue;
      double n[Q];
      pulled(x, n);
      bad = std::min(bad, convertFluid(x, n));
    }
  for (const auto& kind : kinds_)
    if (const auto* edge = dynamic_cast<const ZouHeNode*>(kind.get()))
      for (std::size_t m = 0; m < edge->nodes.size(); ++m) {
        double n[Q];
        edge->pulled(from, m, n);
        bad = std::min(bad, convertFluid(edge->nodes[m], n));
      }
  // Covered cells, over the fluid's: their collision gave the first moment
  // (1 - B) j + B rho u_s + F.
  for (std::size_t m = 0; m < cells.size(); ++m) {
    const CoveredCell& c = covered_.cells[m];
    double n[Q];
    pulled(c.node, n);
    nonEquilibrium(n);
    double rho, jx, jy;
    moments(old.data(), layout_, c.node, rho, jx, jy);
    const double b = c.eps * (tau - 0.5) / ((1.0 - c.eps) + (tau - 0.5));
    const Vec2 us(c.ux, c.uy);
    const Vec2 j = b < 1 ? Vec2((Vec2(jx, jy) - F - b * rho * us) / (1 - b)) : Vec2(rho * us);
    convertNode(from, to, k, rho, j, n);
    covered_.collideCell(to, cells[m], n);
    bad = std::min(bad, write(c.node, n));
  }
  const auto nodeName = [&](std::int64_t x) {
    return "node (" + std::to_string(int(x % rowStride_) - 1) + ", " +
           std::to_string(int(x / rowStride_) - 1) + ")";
  };
  if (bad != std::numeric_limits<std::int64_t>::max()) {
    std::copy(old.begin(), old.end(), f_);
    throw Error("UNSTABLE NAN", "the flow at the new step would not be finite at " + nodeName(bad) +
                                    ": the scene is unstable there already");
  }
  // The same physical flow can be too fast for the new step's lattice speed
  // (a timestep many times larger): refused, as the next step would.
  const double back = to.forceScheme == ForceScheme::guo ? 0.5 : 1.0;
  double worst = 0;
  std::int64_t at = -1;
  for (int j = 0; j < p_.ny; ++j)
    for (int i = 0; i < p_.nx; ++i) {
      const std::int64_t x = index(i, j);
      if (!holdsFluid(x)) continue;
      double rho, jx, jy;
      moments(f_, layout_, x, rho, jx, jy);
      const double ux = (jx - back * to.params.fx) / rho, uy = (jy - back * to.params.fy) / rho;
      const double u2 = !(rho > 0) ? INFINITY : ux * ux + uy * uy;
      if (u2 > worst) worst = u2, at = x;
    }
  if (!(worst <= machLimit * machLimit)) {
    std::copy(old.begin(), old.end(), f_);
    throw Error("UNSTABLE MACH", "at the new timestep " + formatNumber(next.dt) + " the flow at " +
                                     nodeName(at) + " would move at Mach " +
                                     formatNumber(std::sqrt(worst)) + ", beyond " +
                                     formatNumber(machLimit) + ": take a smaller timestep");
  }
  covered_.cells.swap(cells);
  canUndo_ = false;
  lastMach_ *= k.velocity;
}

}  // namespace sf::lb
