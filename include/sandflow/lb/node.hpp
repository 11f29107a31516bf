#pragma once
// Node kinds (design.md "polymorphism per node kind, not per node"). A `Node`
// subclass owns a batch -- a list of spans, nodes or links -- and acts on the
// whole batch per virtual call, so the inner loops are plain code.
//
// The populations live in one array indexed [direction * stride + node] on the
// padded (nx+2) x (ny+2) grid, streamed in place by the AA pattern (Bailey et
// al. 2009; docs/lattice.md): each node reads its inputs from nine slots and
// writes its outputs to the same nine, so no cache line is read for
// ownership. The array's layout flips every step (Layout). A step has two
// phases:
//   1. streamCollide: kinds whose nodes hold fluid read their inputs in the
//      array's layout, collide, and write their outputs in the other (the
//      bulk fluid, Zou-He edges, covered cells);
//   2. fill: kinds that bound the fluid write the slots their fluid
//      neighbours will read next step (bounce-back, slip, periodic).
// With `src` != `dst` the same step reads one array and writes another (a
// lattice that keeps its last state, Lattice::keepPrevious).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sandflow/geometry/vec2.hpp"
#include "sandflow/lb/collision.hpp"

namespace sf::lb {

// What a node is, as stored per node and written to output (values are stable).
enum class NodeKind : std::uint8_t {
  fluid = 0,     // bulk fluid
  noslip = 1,    // bounce-back wall node (borders fluid)
  slip = 2,      // specular (free-slip) wall node
  solid = 3,     // interior of a fixed solid: no work
  velocity = 4,  // Zou-He velocity edge node (holds fluid)
  pressure = 5,  // Zou-He pressure edge node (holds fluid)
  open = 6,      // outside a velocity/pressure side: never read
  outflow = 7,   // outside an outflow side: written from the fluid inside (OutflowNode)
};

// The array's two layouts. Node x's post-collision population f*_i and the
// input f_i of its next collision (which came from x - e_i) sit at:
//   collided (after a local step, and as made):  f*_i in slot opp(i) at x;
//                                                 f_i in slot opp(i) at x - e_i;
//   streamed (after a neighbour step):            f*_i in slot i at x + e_i;
//                                                 f_i in slot i at x.
// A step from `collided` is a neighbour step (read at x - e_i, write at
// x + e_i), one from `streamed` a local step. Either way the slot a node reads
// for direction i is the one it writes direction opp(i) to.
enum class Layout : std::uint8_t { collided = 0, streamed = 1 };
inline constexpr Layout flipped(Layout l) {
  return l == Layout::collided ? Layout::streamed : Layout::collided;
}

// Slot offsets of the two layouts, for a grid of the given strides.
struct Slots {
  std::ptrdiff_t stride = 0, rowStride = 0;
  std::ptrdiff_t shift(int i) const { return d2q9::ex[i] + d2q9::ey[i] * rowStride; }
  // Where node x's post-collision f*_i is in layout l.
  std::ptrdiff_t post(Layout l, int i, std::ptrdiff_t x) const {
    return l == Layout::collided ? d2q9::opposite[i] * stride + x : i * stride + x + shift(i);
  }
  // Where the input f_i of node x's next collision is in layout l.
  std::ptrdiff_t input(Layout l, int i, std::ptrdiff_t x) const {
    return l == Layout::collided ? d2q9::opposite[i] * stride + x - shift(i) : i * stride + x;
  }
};

struct StepContext {
  const double* src = nullptr;  // in layout `from`
  double* dst = nullptr;        // written in flipped(from); == src in place
  Layout from = Layout::collided;
  std::ptrdiff_t stride = 0;  // nodes in the padded grid
  std::ptrdiff_t rowStride = 0;
  Slots slots() const { return {stride, rowStride}; }
  bool inPlace() const { return src == dst; }
  Collision collision = Collision::bgk;
  ForceScheme forceScheme = ForceScheme::nodal;
  CollisionParams params;
  int threads = 1;
};

// Reductions of one phase-1 pass, combined in a fixed order.
struct StepStats {
  double mass = 0.0;   // sum of densities (NaN if any population is NaN)
  double maxU2 = 0.0;  // largest |u|^2, lattice units
  void merge(const StepStats& o) {
    mass += o.mass;
    maxU2 = o.maxU2 > maxU2 ? o.maxU2 : maxU2;
  }
};

class Node {
 public:
  virtual ~Node() = default;
  virtual const char* name() const = 0;
  virtual std::size_t count() const = 0;  // nodes (or links) in the batch
  virtual StepStats streamCollide(const StepContext&) const { return {}; }
  // Writes the slots for a step from layout `layout`.
  virtual void fill(double* /*f*/, Layout /*layout*/, int /*threads*/) const {}
};

struct CoveredCell;
class CoveredNode;

// Bulk fluid: contiguous spans of a row, fused stream and collide, no branches.
class FluidNode final : public Node {
 public:
  struct Span {
    std::ptrdiff_t first;
    std::int32_t length;
  };
  struct Block {  // a stretch of rows: where its spans and covered cells end
    std::int32_t spanEnd, cellEnd;
  };
  std::vector<Span> spans;
  const char* name() const override { return "fluid"; }
  std::size_t count() const override;
  // Every fluid node, covered ones too: the covered cells' outputs, computed
  // from their inputs before, replace the bulk's (streamCollideWith, or the
  // lattice's own order without a sweep).
  StepStats streamCollide(const StepContext& ctx) const override;
  // Notes where the covered cells fall among the spans, for the sweep; cells
  // out of node order get no sweep (their pass runs after the bulk).
  // `ascending`: whether their nodes ascend strictly (CoveredNode::ascending).
  void planSweep(const std::vector<CoveredCell>& cells, bool ascending);
  // True when the cells last planned for can run in the bulk's sweep.
  bool sweepsWith(const CoveredNode& covered) const;
  // The bulk and the covered cells block by block: each block's covered
  // cells, then its spans whole, then the cells' outputs over the spans', while
  // the rows are in cache. The mass is the spans' (which include the covered
  // nodes). Adds the thread-seconds spent in covered cells to `coveredSeconds`.
  StepStats streamCollideWith(const StepContext& ctx, const CoveredNode& covered,
                              double& coveredSeconds) const;

 private:
  std::vector<Block> blocks_;  // of spans, for covered cells in node order
  std::size_t blockCells_ = 0;
};

// What a fluid node's input from a non-fluid neighbour is: the post-collision
// population of a fluid node (itself, its periodic image's or a neighbour's
// across a slip wall) plus a moving wall's term. One form serves periodic
// images, (moving) bounce-back and specular reflection.
struct Link {
  std::int32_t node;   // the fluid node whose input it is (for forces)
  std::int8_t in;      // the input's direction i (it comes from node - e_i)
  std::int8_t out;     // the direction j of the post-collision f*_j it copies ...
  std::int32_t from;   // ... of this fluid node
  double add;          // moving-wall momentum term, lattice units
  std::int32_t owner;  // obstacle id, or -1 - side for the domain's sides
};

// A link resolved for one layout: f[dst] = f[src] + add.
struct SlotCopy {
  std::int64_t dst, src;
  double add;
};

class LinkNode : public Node {
 public:
  std::vector<Link> links;
  std::size_t count() const override { return links.size(); }
  // Resolves the links for both layouts (after they change).
  void resolve(const Slots& slots);
  void fill(double* f, Layout layout, int threads) const override;

 private:
  std::vector<SlotCopy> copies_[2];  // per Layout
};

class PeriodicNode final : public LinkNode {
 public:
  const char* name() const override { return "periodic"; }
};
class BounceBackNode final : public LinkNode {
 public:
  const char* name() const override { return "noslip"; }
};
class SlipNode final : public LinkNode {
 public:
  const char* name() const override { return "slip"; }
};

// Cells covered by moving solids (physics.md §2, Noble & Torczynski): a short
// list rebuilt every step. The bulk computes them as plain fluid; this pass
// computes them again from their inputs (before the bulk overwrites those in
// place) with the partially-saturated operator, whose outputs replace the bulk's:
//   f' = f + (1 - B) (collide(f) - f) + B (Omega^s + S),
//   Omega^s_i = f_-i - f_i + f_i^eq(rho, u_s) - f_-i^eq(rho, u),  S_i = 3 w_i e_i.F,
// and records the momentum B sum_i Omega^s_i e_i it gave the fluid. Interior
// cells (eps = 1 with every neighbour eps = 1) hold no physical fluid: with
// `equilibriumInterior` they are set to f^eq(rho, u_s) + S, which exchanges the
// same momentum, rho u_s - j, without carrying a non-equilibrium part.
// 32 bytes: the list is written, read by the covered pass and swapped each step.
struct CoveredCell {
  std::int32_t node;  // padded index of a bulk-fluid node (a lattice has under 2^31)
  bool interior;
  double eps;     // solid ratio, (0, 1]
  double ux, uy;  // solid velocity, lattice units
};
static_assert(sizeof(CoveredCell) == 32);

class CoveredNode final : public Node {
 public:
  std::vector<CoveredCell> cells;
  bool equilibriumInterior = true;
  bool ascending = false;  // the cells' nodes ascend strictly (the coupler's list does)
  // Per cell, the momentum the last step gave the fluid (lattice units).
  mutable std::vector<Vec2> exchange;
  const char* name() const override { return "covered"; }
  std::size_t count() const override { return cells.size(); }
  // All cells, in a pass of their own, outputs straight to dst (into another
  // array than src); or, in place, into `buffer` (passBufferSize() doubles)
  // before the bulk overwrites their inputs, for scatterAll to write over the
  // bulk's after it.
  StepStats streamCollide(const StepContext& ctx) const override {
    return streamCollide(ctx, nullptr);
  }
  StepStats streamCollide(const StepContext& ctx, double* buffer) const;
  std::size_t passBufferSize() const;
  void scatterAll(const StepContext& ctx, const double* buffer) const;
  // Cells [first, last) alone; `exchange` must hold every cell already. With
  // a buffer (9 x (last - first), rounded up to 8 cells) the outputs go
  // there, by direction, for `scatter` to write over the bulk's; else to dst.
  StepStats run(const StepContext& ctx, std::ptrdiff_t first, std::ptrdiff_t last,
                double* buffer) const;
  void scatter(const StepContext& ctx, std::ptrdiff_t first, std::ptrdiff_t last,
               const double* buffer) const;
  static std::size_t bufferSize(std::ptrdiff_t cells) {
    return 9 * std::size_t((cells + 7) / 8 * 8);
  }
  // The operator on one cell's pre-collision populations, in place (the
  // scalar form of the step's).
  void collideCell(const StepContext& ctx, const CoveredCell& cell, double (&f)[d2q9::Q]) const;
};

// Interior of fixed solids: removed from the work; kept to be counted.
class FixedSolidNode final : public Node {
 public:
  std::size_t nodes = 0;
  const char* name() const override { return "solid"; }
  std::size_t count() const override { return nodes; }
};

// Zou & He (1997) velocity or pressure boundary on one side: the edge nodes pull
// what they can, rebuild the populations that would come from outside, collide.
class ZouHeNode final : public Node {
 public:
  int side = 0;  // sf::lb::Side
  bool pressure = false;
  double density = 1.0;          // pressure sides
  Vec2 velocity = Vec2::Zero();  // velocity sides, lattice units
  // Per node (lattice units) when the velocity varies along the side or in
  // time; empty: `velocity` at every node.
  std::vector<Vec2> velocities;
  std::vector<std::int64_t> nodes;
  const char* name() const override { return pressure ? "pressure" : "velocity"; }
  std::size_t count() const override { return nodes.size(); }
  StepStats streamCollide(const StepContext& ctx) const override;
  // The populations nodes[m] pulls from ctx.src, the ones from outside
  // rebuilt: what its next collision will see.
  void pulled(const StepContext& ctx, std::size_t m, double (&f)[d2q9::Q]) const;
};

// An outflow side (docs/lattice.md): the populations that would come in from
// outside are the post-collision ones of the edge node beside the node
// outside, along the side (zero-gradient extrapolation, as if the node outside
// held its inner neighbour's state). Links of the periodic form (out = in,
// `from` that edge node), written with the other fills after each step: the
// edge nodes stay plain fluid nodes and the step keeps no state of its own.
class OutflowNode final : public LinkNode {
 public:
  const char* name() const override { return "outflow"; }
};

}  // namespace sf::lb
