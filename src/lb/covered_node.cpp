// The Noble-Torczynski pass over covered cells (see CoveredNode in node.hpp):
// TRT and Guo forcing cell by cell, BGK with nodal forcing in vector lanes.
// Cells are processed in fixed blocks whose reductions are combined in block
// order, so the result does not depend on the thread count.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "sandflow/core/kernel_isa.hpp"
#include "sandflow/core/parallel.hpp"
#include "sandflow/lb/collision.hpp"
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

// The operator on one cell's pulled populations f: writes `out`, returns the
// momentum it gave the fluid; rho and u2 (|u|^2 of the step's watch) besides.
template <Collision C, ForceScheme S>
SF_ALWAYS_INLINE Vec2 coverCell(const CoveredCell& cell, bool equilibriumInterior,
                                const CollisionParams& p, const PassConstants& pass,
                                const double (&f)[Q], double (&out)[Q], double& rho, double& u2) {
  using namespace d2q9;
  const double tau = pass.tau;
  const double* source = pass.source;
  double jx = 0, jy = 0;
  rho = 0;
  for (int i = 0; i < Q; ++i) rho += f[i], jx += ex[i] * f[i], jy += ey[i] * f[i];
  double solid[Q];
  equilibria(rho, cell.ux, cell.uy, solid);
  // Momentum given to the fluid: sum_i e_i Omega^s_i = rho u_s - j exactly.
  const Vec2 given(rho * cell.ux - jx, rho * cell.uy - jy);
  if (cell.interior && equilibriumInterior) {
    for (int i = 0; i < Q; ++i) out[i] = solid[i] + source[i];
    u2 = (jx * jx + jy * jy) / (rho * rho);
    return given;
  }
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
  return b * given;
}

// Where a pass reads a cell's inputs and puts its outputs: inputs from src in
// the step's layout (in[i] + node), outputs to dst in the other (out[i] +
// node), or with a buffer to buffer[i * pitch + k - first].
struct Ends {
  const double* src;
  double* dst;
  std::ptrdiff_t in[Q], out[Q];
  double* buffer;
  std::ptrdiff_t first, pitch;
  Ends(const StepContext& ctx, double* buf, std::ptrdiff_t first, std::ptrdiff_t last)
      : src(ctx.src), dst(ctx.dst), buffer(buf), first(first), pitch((last - first + 7) / 8 * 8) {
    const Slots slots = ctx.slots();
    for (int i = 0; i < Q; ++i) {
      in[i] = slots.input(ctx.from, i, 0);
      out[i] = slots.post(flipped(ctx.from), i, 0);
    }
  }
  double& output(int i, std::ptrdiff_t k, std::ptrdiff_t node) const {
    return buffer ? buffer[i * pitch + k - first] : dst[out[i] + node];
  }
};

template <Collision C, ForceScheme S>
SF_KERNEL_CLONES StepStats runBlock(const StepContext& ctx, const CoveredNode& node,
                                    std::ptrdiff_t first, std::ptrdiff_t last, double* buffer) {
  const PassConstants pass(ctx.params);
  const Ends ends(ctx, buffer, first, last);
  StepStats stats;
  for (std::ptrdiff_t k = first; k < last; ++k) {
    const CoveredCell& cell = node.cells[k];
    double f[Q], out[Q], rho, u2;
    for (int i = 0; i < Q; ++i) f[i] = ends.src[ends.in[i] + cell.node];
    node.exchange[k] =
        coverCell<C, S>(cell, node.equilibriumInterior, ctx.params, pass, f, out, rho, u2);
    for (int i = 0; i < Q; ++i) ends.output(i, k, cell.node) = out[i];
    stats.merge({rho, u2});
  }
  return stats;
}

// BGK with nodal forcing (the default) eight cells at a time, each step of the
// operator one operation on eight-lane vectors (GCC's vector extension: one
// AVX-512 register, two AVX ones, four SSE ones). The three cases are each
// computed and one is selected per lane: interior, f^eq(rho, u_s) + S; fully
// covered (B = 1), f_-i + f^eq_i(rho, u_s) - f^eq_-i(rho, u) + S; partial,
// BGK's collide(f) - f = -omega (f - f^eq) + S blended with Omega^s, without
// colliding again. A batch of eight interior cells skips the fluid's
// equilibrium, and its ratios. Every lane rounds as the scalar operator does
// (no FMA contraction), so the populations do not change; the mass (which the
// step's watch tests for NaN) sums lane by lane. Whole vectors in registers,
// not lane arrays in memory: a vector read back over eight scalar stores (or
// two half-width ones) cannot be forwarded and stalls.
constexpr int kLanes = 8;
using Lanes = double __attribute__((vector_size(kLanes * sizeof(double))));
using LaneMask = std::int64_t __attribute__((vector_size(kLanes * sizeof(double))));

// (By reference: a vector passed by value would change the ABI with the
// instruction set, which GCC warns of.)
SF_ALWAYS_INLINE void loadLanes(Lanes& v, const double* from) {
  std::memcpy(&v, from, sizeof v);
}
SF_ALWAYS_INLINE void storeLanes(double* to, const Lanes& v) {
  std::memcpy(to, &v, sizeof v);
}

// equilibria() of collision.hpp, operation for operation, on lanes.
SF_ALWAYS_INLINE void laneEquilibria(const Lanes& rho, const Lanes& ux, const Lanes& uy,
                                     Lanes (&feq)[d2q9::Q]) {
  const Lanes even = 1.0 - 1.5 * (ux * ux + uy * uy);
  feq[0] = d2q9::w[0] * rho * even;
  for (int i = 1; i <= 4; ++i) {
    const Lanes eu = double(d2q9::ex[i]) * ux + double(d2q9::ey[i]) * uy;
    const Lanes wr = d2q9::w[i] * rho, e = even + 4.5 * eu * eu, o = 3.0 * eu;
    feq[i] = wr * (e + o);
    feq[i + 4] = wr * (e - o);
  }
}

SF_KERNEL_CLONES StepStats runBgkNodalLanes(const StepContext& ctx, const CoveredNode& node,
                                            std::ptrdiff_t first, std::ptrdiff_t last,
                                            double* buffer) {
  using namespace d2q9;
  const CollisionParams& p = ctx.params;
  const PassConstants pass(p);
  const double tau = pass.tau;
  const double* source = pass.source;
  const Ends ends(ctx, buffer, first, last);
  StepStats stats;
  Lanes mass = {}, maxU2 = {};  // lane by lane, combined at the end (fixed order)
  for (std::ptrdiff_t k0 = first; k0 < last; k0 += kLanes) {
    // A short last batch repeats its last cell in the spare lanes (same
    // inputs, same outputs: written twice to the same node).
    const int used = int(std::min<std::ptrdiff_t>(kLanes, last - k0));
    const CoveredCell* c[kLanes];
    std::ptrdiff_t at[kLanes];
    int innerCount = 0;
    for (int l = 0; l < kLanes; ++l) {
      c[l] = &node.cells[k0 + std::min(l, used - 1)];
      at[l] = c[l]->node;
      innerCount += c[l]->interior;
    }
    const bool interiorRule = node.equilibriumInterior;
    const Lanes sx = {c[0]->ux, c[1]->ux, c[2]->ux, c[3]->ux,
                      c[4]->ux, c[5]->ux, c[6]->ux, c[7]->ux};
    const Lanes sy = {c[0]->uy, c[1]->uy, c[2]->uy, c[3]->uy,
                      c[4]->uy, c[5]->uy, c[6]->uy, c[7]->uy};
    const LaneMask inner = {-std::int64_t(c[0]->interior && interiorRule),
                            -std::int64_t(c[1]->interior && interiorRule),
                            -std::int64_t(c[2]->interior && interiorRule),
                            -std::int64_t(c[3]->interior && interiorRule),
                            -std::int64_t(c[4]->interior && interiorRule),
                            -std::int64_t(c[5]->interior && interiorRule),
                            -std::int64_t(c[6]->interior && interiorRule),
                            -std::int64_t(c[7]->interior && interiorRule)};
    // Eight consecutive nodes (a row of a solid, mostly) load and store as
    // vectors; any others gather and scatter, which cost several times more.
    // (In a list whose nodes ascend, as the coupler's do, the first and the
    // last tell.)
    bool consecutive = used == kLanes && at[kLanes - 1] - at[0] == kLanes - 1;
    if (consecutive && !node.ascending)
      for (int l = 1; l < kLanes; ++l) consecutive = consecutive && at[l] == at[l - 1] + 1;
    Lanes f[Q];
    if (consecutive) {
      for (int i = 0; i < Q; ++i) loadLanes(f[i], ends.src + at[0] + ends.in[i]);
    } else {
      for (int i = 0; i < Q; ++i) {
        const double* from = ends.src + ends.in[i];
        f[i] = Lanes{from[at[0]], from[at[1]], from[at[2]], from[at[3]],
                     from[at[4]], from[at[5]], from[at[6]], from[at[7]]};
      }
    }
    Lanes rho = {}, jx = {}, jy = {};
    for (int i = 0; i < Q; ++i) rho += f[i], jx += double(ex[i]) * f[i], jy += double(ey[i]) * f[i];
    Lanes solid[Q], out[Q];
    laneEquilibria(rho, sx, sy, solid);
    Lanes b, u2;
    if (interiorRule && innerCount == kLanes) {
      // Eight interior cells (a solid's inside, mostly): no fluid equilibrium.
      for (int i = 0; i < Q; ++i) out[i] = solid[i] + source[i];
      u2 = (jx * jx + jy * jy) / (rho * rho);
      b = Lanes{} + 1.0;  // not needed: interior cells give all of rho u_s - j
    } else {
      const Lanes eps = {c[0]->eps, c[1]->eps, c[2]->eps, c[3]->eps,
                         c[4]->eps, c[5]->eps, c[6]->eps, c[7]->eps};
      b = eps * (tau - 0.5) / ((1.0 - eps) + (tau - 0.5));
      const Lanes ux = jx / rho, uy = jy / rho;
      Lanes fluid[Q];
      laneEquilibria(rho, ux, uy, fluid);
      const Lanes relax = (1.0 - b) * p.omegaPlus;
      const LaneMask full = b == 1.0;
      for (int i = 0; i < Q; ++i) {
        const int o = opposite[i];
        // Fully covered (B = 1): f + Omega^s + S; partial: BGK's relaxation
        // towards the fluid's equilibrium blended with Omega^s (runBlock).
        const Lanes omega = f[o] - f[i] + solid[i] - fluid[o];
        const Lanes partial = f[i] - relax * (f[i] - fluid[i]) + b * omega + source[i];
        const Lanes covered = f[o] + (solid[i] - fluid[o]) + source[i];
        const Lanes mixed = full ? covered : partial;
        out[i] = inner ? solid[i] + source[i] : mixed;
      }
      u2 = inner ? (jx * jx + jy * jy) / (rho * rho) : ux * ux + uy * uy;
    }
    if (buffer) {  // whole batches: the buffer is rounded up to eight cells
      for (int i = 0; i < Q; ++i) storeLanes(&ends.output(i, k0, 0), out[i]);
    } else if (consecutive) {
      for (int i = 0; i < Q; ++i) storeLanes(ends.dst + at[0] + ends.out[i], out[i]);
    } else {
      for (int i = 0; i < Q; ++i)
        for (int l = 0; l < kLanes; ++l) ends.dst[ends.out[i] + at[l]] = out[i][l];
    }
    const Lanes gx = rho * sx - jx, gy = rho * sy - jy;
    const Lanes ex2 = inner ? gx : b * gx, ey2 = inner ? gy : b * gy;
    for (int l = 0; l < used; ++l) node.exchange[k0 + l] = Vec2(ex2[l], ey2[l]);
    const LaneMask counted = LaneMask{0, 1, 2, 3, 4, 5, 6, 7} < used;
    mass += counted ? rho : Lanes{};
    maxU2 = counted && u2 > maxU2 ? u2 : maxU2;
  }
  for (int l = 0; l < kLanes; ++l) {
    stats.mass += mass[l];
    stats.maxU2 = maxU2[l] > stats.maxU2 ? maxU2[l] : stats.maxU2;
  }
  return stats;
}

}  // namespace

StepStats CoveredNode::run(const StepContext& ctx, std::ptrdiff_t first, std::ptrdiff_t last,
                           double* buffer) const {
  const bool guo = ctx.forceScheme == ForceScheme::guo;
  if (ctx.collision == Collision::bgk)
    return guo ? runBlock<Collision::bgk, ForceScheme::guo>(ctx, *this, first, last, buffer)
               : runBgkNodalLanes(ctx, *this, first, last, buffer);
  return guo ? runBlock<Collision::trt, ForceScheme::guo>(ctx, *this, first, last, buffer)
             : runBlock<Collision::trt, ForceScheme::nodal>(ctx, *this, first, last, buffer);
}

void CoveredNode::scatter(const StepContext& ctx, std::ptrdiff_t first, std::ptrdiff_t last,
                          const double* buffer) const {
  const Ends ends(ctx, nullptr, first, last);
  for (int i = 0; i < Q; ++i) {
    const double* from = buffer + i * ends.pitch - first;
    for (std::ptrdiff_t k = first; k < last; ++k) ends.dst[ends.out[i] + cells[k].node] = from[k];
  }
}

void CoveredNode::collideCell(const StepContext& ctx, const CoveredCell& cell,
                              double (&f)[Q]) const {
  const PassConstants pass(ctx.params);
  double out[Q], rho, u2;
  const bool guo = ctx.forceScheme == ForceScheme::guo, e = equilibriumInterior;
  if (ctx.collision == Collision::bgk)
    guo ? coverCell<Collision::bgk, ForceScheme::guo>(cell, e, ctx.params, pass, f, out, rho, u2)
        : coverCell<Collision::bgk, ForceScheme::nodal>(cell, e, ctx.params, pass, f, out, rho, u2);
  else
    guo ? coverCell<Collision::trt, ForceScheme::guo>(cell, e, ctx.params, pass, f, out, rho, u2)
        : coverCell<Collision::trt, ForceScheme::nodal>(cell, e, ctx.params, pass, f, out, rho, u2);
  for (int i = 0; i < Q; ++i) f[i] = out[i];
}

std::size_t CoveredNode::passBufferSize() const {
  return std::size_t((std::ptrdiff_t(cells.size()) + kBlock - 1) / kBlock) * bufferSize(kBlock);
}

StepStats CoveredNode::streamCollide(const StepContext& ctx, double* buffer) const {
  exchange.resize(cells.size());
  const std::ptrdiff_t n = std::ptrdiff_t(cells.size());
  const std::ptrdiff_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<StepStats> partial(blocks);
  // Blocks taken as threads come free (the sweep's reason, fluid_node.cpp).
#pragma omp parallel for schedule(dynamic, 4) \
    num_threads(ctx.threads) if (n >= parallel::kLatticeNodes)
  for (std::ptrdiff_t b = 0; b < blocks; ++b)
    partial[b] = run(ctx, b * kBlock, std::min(n, (b + 1) * kBlock),
                     buffer ? buffer + b * bufferSize(kBlock) : nullptr);
  StepStats total;
  for (const StepStats& s : partial) total.merge(s);
  return total;
}

void CoveredNode::scatterAll(const StepContext& ctx, const double* buffer) const {
  const std::ptrdiff_t n = std::ptrdiff_t(cells.size());
  const std::ptrdiff_t blocks = (n + kBlock - 1) / kBlock;
#pragma omp parallel for schedule(static) num_threads(ctx.threads) if (n >= parallel::kLatticeNodes)
  for (std::ptrdiff_t b = 0; b < blocks; ++b)
    scatter(ctx, b * kBlock, std::min(n, (b + 1) * kBlock), buffer + b * bufferSize(kBlock));
}

}  // namespace sf::lb
