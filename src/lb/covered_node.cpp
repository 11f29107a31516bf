// The Noble-Torczynski pass over covered cells (see CoveredNode in node.hpp):
// TRT and Guo forcing cell by cell, BGK with nodal forcing in vector lanes.
// Cells are processed in fixed blocks whose reductions are combined in block
// order, so the result does not depend on the thread count.
#include <algorithm>
#include <vector>

#include "sandflow/lb/collision.hpp"
#include "sandflow/lb/kernel_isa.hpp"
#include "sandflow/lb/node.hpp"

namespace sf::lb {
namespace {

using d2q9::Q;

constexpr std::ptrdiff_t kBlock = 256;

// What every cell of a pass shares: tau and the body forcing's term
// S_i = 3 w_i e_i.F of every direction.
struct PassConstants {
  double tau;
  double source[Q];
  explicit PassConstants(const CollisionParams& p) : tau(1.0 / p.omegaPlus) {
    for (int i = 0; i < Q; ++i)
      source[i] = 3.0 * d2q9::w[i] * (d2q9::ex[i] * p.fx + d2q9::ey[i] * p.fy);
  }
};

template <Collision C, ForceScheme S>
SF_KERNEL_CLONES StepStats runBlock(const StepContext& ctx, const CoveredNode& node,
                                    std::ptrdiff_t first, std::ptrdiff_t last) {
  using namespace d2q9;
  const CollisionParams& p = ctx.params;
  const PassConstants pass(p);
  const double tau = pass.tau;
  const double* source = pass.source;
  StepStats stats;
  for (std::ptrdiff_t k = first; k < last; ++k) {
    const CoveredCell& cell = node.cells[k];
    double f[Q];
    for (int i = 0; i < Q; ++i)
      f[i] = ctx.src[i * ctx.stride + cell.node - (ex[i] + ey[i] * ctx.rowStride)];
    double rho = 0, jx = 0, jy = 0;
    for (int i = 0; i < Q; ++i) rho += f[i], jx += ex[i] * f[i], jy += ey[i] * f[i];
    double solid[Q], out[Q];
    equilibria(rho, cell.ux, cell.uy, solid);
    // Momentum given to the fluid: sum_i e_i Omega^s_i = rho u_s - j exactly.
    const Vec2 given(rho * cell.ux - jx, rho * cell.uy - jy);
    Vec2 gave;
    double u2;
    if (cell.interior && node.equilibriumInterior) {
      for (int i = 0; i < Q; ++i) out[i] = solid[i] + source[i];
      gave = given;
      u2 = (jx * jx + jy * jy) / (rho * rho);
    } else {
      double fluid[Q];
      const double ux = jx / rho, uy = jy / rho;
      u2 = ux * ux + uy * uy;
      equilibria(rho, ux, uy, fluid);
      const double b = cell.eps * (tau - 0.5) / ((1.0 - cell.eps) + (tau - 0.5));
      if (b == 1.0) {  // fully covered (eps = 1): f + Omega^s + S, no fluid collision
        for (int i = 0; i < Q; ++i)
          out[i] = f[opposite[i]] + (solid[i] - fluid[opposite[i]]) + source[i];
      } else {
        double fc[Q];
        for (int i = 0; i < Q; ++i) fc[i] = f[i];
        collide<C, S>(fc, p, u2);
        for (int i = 0; i < Q; ++i) {
          const double omega = f[opposite[i]] - f[i] + solid[i] - fluid[opposite[i]];
          out[i] = f[i] + (1.0 - b) * (fc[i] - f[i]) + b * (omega + source[i]);
        }
      }
      gave = b * given;
    }
    for (int i = 0; i < Q; ++i) ctx.dst[i * ctx.stride + cell.node] = out[i];
    node.exchange[k] = gave;
    stats.merge({rho, u2});
  }
  return stats;
}

// BGK with nodal forcing (the default) eight cells at a time. The cells'
// populations are gathered into lanes and each step of the operator runs as
// one loop over the lanes, which vectorizes. The three cases are each computed
// and one is selected per lane: interior, f^eq(rho, u_s) + S; fully covered
// (B = 1), f_-i + f^eq_i(rho, u_s) - f^eq_-i(rho, u) + S; partial, BGK's
// collide(f) - f = -omega (f - f^eq) + S blended with Omega^s, without
// colliding again. A batch of eight interior cells skips the fluid's
// equilibrium, and its ratios. Every lane rounds as the scalar operator does
// (no FMA contraction), so the populations do not change; the mass (which the
// step's watch tests for NaN) sums lane by lane.
constexpr int kLanes = 8;

// equilibria() of collision.hpp, operation for operation, for eight lanes.
SF_ALWAYS_INLINE void laneEquilibria(const double* rho, const double* ux, const double* uy,
                                     double (&feq)[d2q9::Q][kLanes]) {
  alignas(64) double even[kLanes];
#pragma omp simd
  for (int l = 0; l < kLanes; ++l) {
    even[l] = 1.0 - 1.5 * (ux[l] * ux[l] + uy[l] * uy[l]);
    feq[0][l] = d2q9::w[0] * rho[l] * even[l];
  }
  for (int i = 1; i <= 4; ++i)
#pragma omp simd
    for (int l = 0; l < kLanes; ++l) {
      const double eu = d2q9::ex[i] * ux[l] + d2q9::ey[i] * uy[l];
      const double wr = d2q9::w[i] * rho[l], e = even[l] + 4.5 * eu * eu, o = 3.0 * eu;
      feq[i][l] = wr * (e + o);
      feq[i + 4][l] = wr * (e - o);
    }
}

SF_KERNEL_CLONES StepStats runBgkNodalLanes(const StepContext& ctx, const CoveredNode& node,
                                            std::ptrdiff_t first, std::ptrdiff_t last) {
  using namespace d2q9;
  const CollisionParams& p = ctx.params;
  const PassConstants pass(p);
  const double tau = pass.tau;
  const double* source = pass.source;
  std::ptrdiff_t pull[Q];
  for (int i = 0; i < Q; ++i) pull[i] = i * ctx.stride - (ex[i] + ey[i] * ctx.rowStride);
  StepStats stats;
  alignas(64) double mass[kLanes] = {};  // lane by lane, summed at the end (fixed order)
  for (std::ptrdiff_t k0 = first; k0 < last; k0 += kLanes) {
    // A short last batch repeats its last cell in the spare lanes (same
    // inputs, same outputs: written twice to the same node).
    const int used = int(std::min<std::ptrdiff_t>(kLanes, last - k0));
    alignas(64) double f[Q][kLanes], solid[Q][kLanes], fluid[Q][kLanes], out[Q][kLanes];
    alignas(64) double rho[kLanes], jx[kLanes], jy[kLanes], ux[kLanes], uy[kLanes];
    alignas(64) double sx[kLanes], sy[kLanes], eps[kLanes], b[kLanes], inner[kLanes], u2[kLanes];
    std::ptrdiff_t at[kLanes];
#pragma omp simd
    for (int l = 0; l < kLanes; ++l) {
      const CoveredCell& c = node.cells[k0 + std::min(l, used - 1)];
      at[l] = c.node;
      sx[l] = c.ux, sy[l] = c.uy;
      inner[l] = c.interior && node.equilibriumInterior ? 1.0 : 0.0;
      eps[l] = c.eps;
    }
    // Eight consecutive nodes (a row of a solid, mostly) load and store as
    // vectors; any others gather and scatter, which cost several times more.
    const bool consecutive = used == kLanes && at[kLanes - 1] - at[0] == kLanes - 1;
    if (consecutive) {
      for (int i = 0; i < Q; ++i) {
        const double* from = ctx.src + at[0] + pull[i];
#pragma omp simd
        for (int l = 0; l < kLanes; ++l) f[i][l] = from[l];
      }
    } else {
      for (int i = 0; i < Q; ++i)
#pragma omp simd
        for (int l = 0; l < kLanes; ++l) f[i][l] = ctx.src[at[l] + pull[i]];
    }
#pragma omp simd
    for (int l = 0; l < kLanes; ++l) rho[l] = 0, jx[l] = 0, jy[l] = 0;
    for (int i = 0; i < Q; ++i)
#pragma omp simd
      for (int l = 0; l < kLanes; ++l)
        rho[l] += f[i][l], jx[l] += ex[i] * f[i][l], jy[l] += ey[i] * f[i][l];
    laneEquilibria(rho, sx, sy, solid);
    double innerLanes = 0;
    for (int l = 0; l < kLanes; ++l) innerLanes += inner[l];
    if (innerLanes == kLanes) {
      // Eight interior cells (a solid's inside, mostly): no fluid equilibrium.
      for (int i = 0; i < Q; ++i)
#pragma omp simd
        for (int l = 0; l < kLanes; ++l) out[i][l] = solid[i][l] + source[i];
#pragma omp simd
      for (int l = 0; l < kLanes; ++l) {
        u2[l] = (jx[l] * jx[l] + jy[l] * jy[l]) / (rho[l] * rho[l]);
        b[l] = 1.0;  // not needed: interior cells give all of rho u_s - j
      }
    } else {
#pragma omp simd
      for (int l = 0; l < kLanes; ++l) b[l] = eps[l] * (tau - 0.5) / ((1.0 - eps[l]) + (tau - 0.5));
#pragma omp simd
      for (int l = 0; l < kLanes; ++l) ux[l] = jx[l] / rho[l], uy[l] = jy[l] / rho[l];
      laneEquilibria(rho, ux, uy, fluid);
      for (int i = 0; i < Q; ++i) {
        const int o = opposite[i];
#pragma omp simd
        for (int l = 0; l < kLanes; ++l) {
          // Fully covered (B = 1): f + Omega^s + S; partial: BGK's relaxation
          // towards the fluid's equilibrium blended with Omega^s (runBlock).
          const double omega = f[o][l] - f[i][l] + solid[i][l] - fluid[o][l];
          const double relax = (1.0 - b[l]) * p.omegaPlus;
          const double partial =
              f[i][l] - relax * (f[i][l] - fluid[i][l]) + b[l] * omega + source[i];
          const double covered = f[o][l] + (solid[i][l] - fluid[o][l]) + source[i];
          const double mixed = b[l] == 1.0 ? covered : partial;
          out[i][l] = inner[l] != 0 ? solid[i][l] + source[i] : mixed;
        }
      }
#pragma omp simd
      for (int l = 0; l < kLanes; ++l)
        u2[l] = inner[l] != 0 ? (jx[l] * jx[l] + jy[l] * jy[l]) / (rho[l] * rho[l])
                              : ux[l] * ux[l] + uy[l] * uy[l];
    }
    if (consecutive) {
      for (int i = 0; i < Q; ++i) {
        double* to = ctx.dst + i * ctx.stride + at[0];
#pragma omp simd
        for (int l = 0; l < kLanes; ++l) to[l] = out[i][l];
      }
    } else {
      for (int i = 0; i < Q; ++i)
#pragma omp simd
        for (int l = 0; l < kLanes; ++l) ctx.dst[i * ctx.stride + at[l]] = out[i][l];
    }
    for (int l = 0; l < used; ++l) {
      const Vec2 given(rho[l] * sx[l] - jx[l], rho[l] * sy[l] - jy[l]);
      node.exchange[k0 + l] = inner[l] != 0 ? given : b[l] * given;
      mass[l] += rho[l];
      stats.maxU2 = u2[l] > stats.maxU2 ? u2[l] : stats.maxU2;
    }
  }
  for (int l = 0; l < kLanes; ++l) stats.mass += mass[l];
  return stats;
}

}  // namespace

StepStats CoveredNode::run(const StepContext& ctx, std::ptrdiff_t first,
                           std::ptrdiff_t last) const {
  const bool guo = ctx.forceScheme == ForceScheme::guo;
  if (ctx.collision == Collision::bgk)
    return guo ? runBlock<Collision::bgk, ForceScheme::guo>(ctx, *this, first, last)
               : runBgkNodalLanes(ctx, *this, first, last);
  return guo ? runBlock<Collision::trt, ForceScheme::guo>(ctx, *this, first, last)
             : runBlock<Collision::trt, ForceScheme::nodal>(ctx, *this, first, last);
}

StepStats CoveredNode::streamCollide(const StepContext& ctx) const {
  exchange.resize(cells.size());
  const std::ptrdiff_t n = std::ptrdiff_t(cells.size());
  const std::ptrdiff_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<StepStats> partial(blocks);
#pragma omp parallel for schedule(static) num_threads(ctx.threads) if (n >= kParallelNodes)
  for (std::ptrdiff_t b = 0; b < blocks; ++b)
    partial[b] = run(ctx, b * kBlock, std::min(n, (b + 1) * kBlock));
  StepStats total;
  for (const StepStats& s : partial) total.merge(s);
  return total;
}

}  // namespace sf::lb
