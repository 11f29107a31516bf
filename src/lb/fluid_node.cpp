// The bulk fluid loop: stream and collide over contiguous spans of a row, in
// place (the AA pattern, node.hpp). One pointer per direction into
// structure-of-arrays storage, no test on node kind, so the loop body vectorizes;
// per-span reductions are combined in span order: any thread count, same result.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "sandflow/core/kernel_isa.hpp"
#include "sandflow/core/parallel.hpp"
#include "sandflow/core/prefetch.hpp"
#include "sandflow/lb/node.hpp"

namespace sf::lb {
namespace {

using d2q9::Q;

// Nodes a thread takes at a time from the spans (a few rows): whole rows keep
// the hardware's prefetch streams long; far fewer grabs than spans.
constexpr std::ptrdiff_t kGrabNodes = 4096;

// One span of a row. In place (the AA pattern) the slot a node reads
// direction i from is the one it writes direction opp(i) to: one pointer per
// slot, p_i at the input of direction i, read and then written with f*_opp(i).
// Into another array: inputs r_i from src in its layout, outputs w_i to dst
// in the other.
template <Collision C, ForceScheme S, bool InPlace>
SF_KERNEL_CLONES StepStats runSpan(const StepContext& ctx, std::ptrdiff_t first, std::ptrdiff_t n) {
  const Slots slots = ctx.slots();
  const Layout to = flipped(ctx.from);
  const double* __restrict s[Q];
  double* __restrict d[Q];
  for (int i = 0; i < Q; ++i) {
    if constexpr (InPlace) {
      // The output of direction opp(i) goes where the input of direction i
      // came from; the loop reads it through the same pointer (opp below).
      d[d2q9::opposite[i]] = ctx.dst + slots.input(ctx.from, i, first);
      s[i] = nullptr;
    } else {
      s[i] = ctx.src + slots.input(ctx.from, i, first);
      d[i] = ctx.dst + slots.post(to, i, first);
    }
  }
  const double* __restrict s0 = s[0];
  const double* __restrict s1 = s[1];
  const double* __restrict s2 = s[2];
  const double* __restrict s3 = s[3];
  const double* __restrict s4 = s[4];
  const double* __restrict s5 = s[5];
  const double* __restrict s6 = s[6];
  const double* __restrict s7 = s[7];
  const double* __restrict s8 = s[8];
  double* __restrict d0 = d[0];
  double* __restrict d1 = d[1];
  double* __restrict d2 = d[2];
  double* __restrict d3 = d[3];
  double* __restrict d4 = d[4];
  double* __restrict d5 = d[5];
  double* __restrict d6 = d[6];
  double* __restrict d7 = d[7];
  double* __restrict d8 = d[8];
  const CollisionParams p = ctx.params;

  double mass = 0.0, maxU2 = 0.0;
#pragma omp simd reduction(+ : mass) reduction(max : maxU2)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    // In place, input i is read through the pointer that writes opp(i).
    double f0 = (InPlace ? d0 : s0)[k], f1 = (InPlace ? d5 : s1)[k], f2 = (InPlace ? d6 : s2)[k],
           f3 = (InPlace ? d7 : s3)[k], f4 = (InPlace ? d8 : s4)[k], f5 = (InPlace ? d1 : s5)[k],
           f6 = (InPlace ? d2 : s6)[k], f7 = (InPlace ? d3 : s7)[k], f8 = (InPlace ? d4 : s8)[k];
    double u2;
    mass += collide<C, S>(f0, f1, f2, f3, f4, f5, f6, f7, f8, p, u2);
    maxU2 = u2 > maxU2 ? u2 : maxU2;
    d0[k] = f0;
    d1[k] = f1;
    d2[k] = f2;
    d3[k] = f3;
    d4[k] = f4;
    d5[k] = f5;
    d6[k] = f6;
    d7[k] = f7;
    d8[k] = f8;
  }
  return {mass, maxU2};
}

template <Collision C, ForceScheme S, bool InPlace>
StepStats runSpans(const StepContext& ctx, const std::vector<FluidNode::Span>& spans) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(spans.size());
  std::vector<StepStats> partial(spans.size());
  // Small lattices stay on one thread: a parallel region costs more than it saves.
  std::ptrdiff_t nodes = 0;
  for (const FluidNode::Span& s : spans) nodes += s.length;
  // Spans handed out a few rows at a time as threads come free (see sweep).
  const int grab =
      int(std::max<std::ptrdiff_t>(1, kGrabNodes * n / std::max<std::ptrdiff_t>(1, nodes)));
#pragma omp parallel for schedule(dynamic, grab) \
    num_threads(ctx.threads) if (nodes >= parallel::kLatticeNodes)
  for (std::ptrdiff_t k = 0; k < n; ++k)
    partial[k] = runSpan<C, S, InPlace>(ctx, spans[k].first, spans[k].length);
  StepStats total;
  for (const StepStats& p : partial) total.merge(p);
  return total;
}

template <Collision C, ForceScheme S, bool InPlace>
StepStats sweep(const StepContext& ctx, const std::vector<FluidNode::Span>& spans,
                const std::vector<FluidNode::Block>& blocks, const CoveredNode& covered,
                double& coveredSeconds) {
  using Clock = std::chrono::steady_clock;
  const std::ptrdiff_t n = std::ptrdiff_t(blocks.size());
  // Per span, summed in span order as runSpans does: the mass does not depend
  // on how the spans are cut into blocks (nor on the thread count).
  std::vector<StepStats> partial(spans.size());
  std::vector<double> seconds(blocks.size(), 0.0), coveredU2(blocks.size(), 0.0);
  std::ptrdiff_t nodes = 0;
  for (const FluidNode::Span& s : spans) nodes += s.length;
  covered.exchange.resize(covered.cells.size());
  const bool parallel = nodes >= parallel::kLatticeNodes;
  // In place, a block's covered cells are computed before its spans
  // overwrite their inputs, into a buffer of the thread's.
  std::vector<std::vector<double>> buffers(InPlace ? std::size_t(std::max(1, ctx.threads)) : 0);
  // Blocks handed out one at a time as threads come free: the cores of a
  // shared machine do not keep the same speed, and with halves fixed in
  // advance one of two threads sat idle for 0.9 ms of a 6 ms sweep (AMD EPYC,
  // 1024^2 coupled scene; 0.75 ms of a 4.2 ms fluid-only step). Each block
  // is done whole by one thread, so the results do not change.
#pragma omp parallel for schedule(dynamic, 1) num_threads(ctx.threads) if (parallel)
  for (std::ptrdiff_t b = 0; b < n; ++b) {
    const std::int32_t span0 = b == 0 ? 0 : blocks[b - 1].spanEnd;
    const std::int32_t cell0 = b == 0 ? 0 : blocks[b - 1].cellEnd;
    const std::int32_t cell1 = blocks[b].cellEnd;
    // The block's covered cells and exchanges asked for now, to be in cache
    // when they are done: the sweep has evicted them since they were written,
    // and a block's few hundred give the hardware's prefetcher too short a
    // stream.
    const std::size_t cells = std::size_t(cell1 - cell0);
    prefetchForRead(covered.cells.data() + cell0, cells * sizeof(CoveredCell));
    prefetchForWrite(covered.exchange.data() + cell0, cells * sizeof(Vec2));
    double* buffer = nullptr;
    if (InPlace && cells > 0) {
      std::vector<double>& mine = buffers[std::size_t(omp_get_thread_num())];
      mine.resize(std::max(mine.size(), CoveredNode::bufferSize(cells)));
      buffer = mine.data();
      const auto t0 = Clock::now();
      coveredU2[b] = covered.run(ctx, cell0, cell1, buffer).maxU2;
      seconds[b] = std::chrono::duration<double>(Clock::now() - t0).count();
    }
    // The block's spans whole, then its covered cells over them: the mass is
    // the spans', which hold the covered nodes too.
    for (std::int32_t k = span0; k < blocks[b].spanEnd; ++k)
      partial[k] = runSpan<C, S, InPlace>(ctx, spans[k].first, spans[k].length);
    if (cells > 0) {
      const auto t0 = Clock::now();
      if (InPlace)
        covered.scatter(ctx, cell0, cell1, buffer);
      else
        coveredU2[b] = covered.run(ctx, cell0, cell1, nullptr).maxU2;
      seconds[b] += std::chrono::duration<double>(Clock::now() - t0).count();
    }
  }
  StepStats total;
  for (const StepStats& p : partial) total.merge(p);
  for (double u2 : coveredU2) total.maxU2 = std::max(total.maxU2, u2);
  double spent = 0;
  for (double t : seconds) spent += t;
  coveredSeconds += spent / (parallel ? std::max(1, ctx.threads) : 1);
  return total;
}

// The kernel for the step's collision, forcing and whether it is in place.
template <template <Collision, ForceScheme, bool> class Run, class... Args>
StepStats dispatch(const StepContext& ctx, Args&&... args) {
  const bool guo = ctx.forceScheme == ForceScheme::guo, bgk = ctx.collision == Collision::bgk;
  if (ctx.inPlace()) {
    if (bgk)
      return guo ? Run<Collision::bgk, ForceScheme::guo, true>::run(ctx, args...)
                 : Run<Collision::bgk, ForceScheme::nodal, true>::run(ctx, args...);
    return guo ? Run<Collision::trt, ForceScheme::guo, true>::run(ctx, args...)
               : Run<Collision::trt, ForceScheme::nodal, true>::run(ctx, args...);
  }
  if (bgk)
    return guo ? Run<Collision::bgk, ForceScheme::guo, false>::run(ctx, args...)
               : Run<Collision::bgk, ForceScheme::nodal, false>::run(ctx, args...);
  return guo ? Run<Collision::trt, ForceScheme::guo, false>::run(ctx, args...)
             : Run<Collision::trt, ForceScheme::nodal, false>::run(ctx, args...);
}

template <Collision C, ForceScheme S, bool InPlace>
struct SpansRun {
  static StepStats run(const StepContext& ctx, const std::vector<FluidNode::Span>& spans) {
    return runSpans<C, S, InPlace>(ctx, spans);
  }
};

template <Collision C, ForceScheme S, bool InPlace>
struct SweepRun {
  static StepStats run(const StepContext& ctx, const std::vector<FluidNode::Span>& spans,
                       const std::vector<FluidNode::Block>& blocks, const CoveredNode& covered,
                       double& coveredSeconds) {
    return sweep<C, S, InPlace>(ctx, spans, blocks, covered, coveredSeconds);
  }
};

}  // namespace

std::size_t FluidNode::count() const {
  std::size_t n = 0;
  for (const Span& s : spans) n += s.length;
  return n;
}

void FluidNode::planSweep(const std::vector<CoveredCell>& cells, bool ascending) {
  blocks_.clear();
  blockCells_ = 0;
  const std::size_t n = cells.size();
  if (n == 0 || !ascending || spans.empty()) return;
  // Blocks of about kSweepNodes nodes, cut where a span starts, and the cells
  // in each (those before the next block's first span). A block's sources and
  // destinations (4096 x 9 x 8 B each, 590 KB) stay in a 1 MB L2 for its
  // covered cells to re-read: with 8192 they spilled, and the covered cells
  // took 2.5 ms a step at one thread against 1.7 (AMD EPYC, 1024^2, 122k cells).
  constexpr std::ptrdiff_t kSweepNodes = 4096;
  std::ptrdiff_t nodes = 0;
  auto c = cells.begin();
  for (std::size_t k = 0; k < spans.size(); ++k) {
    nodes += spans[k].length;
    const bool last = k + 1 == spans.size();
    if (nodes < kSweepNodes && !last) continue;
    c = last ? cells.end()
             : std::lower_bound(c, cells.end(), spans[k + 1].first,
                                [](const CoveredCell& x, std::ptrdiff_t v) { return x.node < v; });
    blocks_.push_back({std::int32_t(k + 1), std::int32_t(c - cells.begin())});
    nodes = 0;
  }
  blockCells_ = n;
}

bool FluidNode::sweepsWith(const CoveredNode& covered) const {
  return !blocks_.empty() && blockCells_ == covered.cells.size();
}

StepStats FluidNode::streamCollideWith(const StepContext& ctx, const CoveredNode& covered,
                                       double& coveredSeconds) const {
  return dispatch<SweepRun>(ctx, spans, blocks_, covered, coveredSeconds);
}

StepStats FluidNode::streamCollide(const StepContext& ctx) const {
  return dispatch<SpansRun>(ctx, spans);
}

}  // namespace sf::lb
