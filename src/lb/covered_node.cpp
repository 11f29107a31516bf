// The Noble-Torczynski pass over covered cells (see CoveredNode in node.hpp).
// Cells are processed in fixed blocks whose reductions are combined in block
// order, so the result does not depend on the thread count.
#include <algorithm>
#include <vector>

#include "sandflow/lb/kernel_isa.hpp"
#include "sandflow/lb/node.hpp"

namespace sf::lb {
namespace {

using d2q9::Q;

constexpr std::ptrdiff_t kBlock = 256;

template <Collision C, ForceScheme S>
SF_KERNEL_CLONES StepStats runBlock(const StepContext& ctx, const CoveredNode& node,
                                    std::ptrdiff_t first, std::ptrdiff_t last) {
  using namespace d2q9;
  const CollisionParams& p = ctx.params;
  const double tau = 1.0 / p.omegaPlus;
  double source[Q];
  for (int i = 0; i < Q; ++i) source[i] = 3.0 * w[i] * (ex[i] * p.fx + ey[i] * p.fy);
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
      } else if constexpr (C == Collision::bgk && S == ForceScheme::nodal) {
        // BGK with nodal forcing relaxes to the same equilibrium: collide(f) - f
        // = -(f - f^eq) / tau + S, without colliding again.
        const double relax = (1.0 - b) * p.omegaPlus;
        for (int i = 0; i < Q; ++i) {
          const double omega = f[opposite[i]] - f[i] + solid[i] - fluid[opposite[i]];
          out[i] = f[i] - relax * (f[i] - fluid[i]) + b * omega + source[i];
        }
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

}  // namespace

StepStats CoveredNode::run(const StepContext& ctx, std::ptrdiff_t first,
                           std::ptrdiff_t last) const {
  const bool guo = ctx.forceScheme == ForceScheme::guo;
  if (ctx.collision == Collision::bgk)
    return guo ? runBlock<Collision::bgk, ForceScheme::guo>(ctx, *this, first, last)
               : runBlock<Collision::bgk, ForceScheme::nodal>(ctx, *this, first, last);
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
