#pragma once
// Node kinds (design.md "polymorphism per node kind, not per node"). A `Node`
// subclass owns a batch -- a list of spans, nodes or links -- and acts on the
// whole batch per virtual call, so the inner loops are plain code.
//
// A step has two phases over population arrays indexed [direction * stride + node]
// on the padded (nx+2) x (ny+2) grid, holding post-collision populations:
//   1. streamCollide: kinds whose nodes hold fluid pull f_i(x - e_i) from `src`,
//      collide, and write `dst` (the bulk fluid, Zou-He edges);
//   2. fill (after the swap): kinds that bound the fluid write the slots their
//      fluid neighbours will pull from next step (bounce-back, slip, periodic).
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
};

struct StepContext {
  const double* src = nullptr;
  double* dst = nullptr;
  std::ptrdiff_t stride = 0;  // nodes in the padded grid
  std::ptrdiff_t rowStride = 0;
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
  virtual void fill(double* /*f*/, int /*threads*/) const {}
};

struct CoveredCell;
class CoveredNode;

// Bulk fluid: contiguous spans of a row, fused pull-stream and collide, no branches.
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
  // Every fluid node, covered ones too: the covered pass then writes those
  // again, while their rows are in cache (streamCollideWith).
  StepStats streamCollide(const StepContext& ctx) const override;
  // Notes where the covered cells fall among the spans, for the sweep; cells
  // out of node order get no sweep (their pass runs after the bulk).
  // `ascending`: whether their nodes ascend strictly (CoveredNode::ascending).
  void planSweep(const std::vector<CoveredCell>& cells, bool ascending);
  // True when the cells last planned for can run in the bulk's sweep.
  bool sweepsWith(const CoveredNode& covered) const;
  // The bulk and the covered cells block by block: each block's spans whole,
  // then its covered cells over them, while the rows they pull from are in
  // cache. The mass is the spans' (which include the covered nodes). Adds the
  // thread-seconds spent in covered cells to `coveredSeconds`.
  StepStats streamCollideWith(const StepContext& ctx, const CoveredNode& covered,
                              double& coveredSeconds) const;

 private:
  std::vector<Block> blocks_;  // of spans, for covered cells in node order
  std::size_t blockCells_ = 0;
};

// Slot copies f[dst] = f[src] + add, evaluated after the swap. One form serves
// periodic images, (moving) bounce-back and specular reflection.
struct Link {
  std::int64_t dst;    // direction * stride + node, a slot a fluid node pulls from
  std::int64_t src;    // the post-collision slot it takes its value from
  double add;          // moving-wall momentum term, lattice units
  std::int32_t owner;  // obstacle id, or -1 - side for the domain's sides
  std::int32_t node;   // the fluid node that pulls (for forces)
};

class LinkNode : public Node {
 public:
  std::vector<Link> links;
  std::size_t count() const override { return links.size(); }
  void fill(double* f, int threads) const override;
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
// then computes them again, over that, from the pulled populations with the
// partially-saturated operator
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
  StepStats streamCollide(const StepContext& ctx) const override;
  // Cells [first, last) alone; `exchange` must hold every cell already.
  StepStats run(const StepContext& ctx, std::ptrdiff_t first, std::ptrdiff_t last) const;
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
  std::vector<std::int64_t> nodes;
  const char* name() const override { return pressure ? "pressure" : "velocity"; }
  std::size_t count() const override { return nodes.size(); }
  StepStats streamCollide(const StepContext& ctx) const override;
  // The populations `node` pulls from ctx.src, the ones from outside rebuilt:
  // what its next collision will see.
  void pulled(const StepContext& ctx, std::int64_t node, double (&f)[d2q9::Q]) const;
};

}  // namespace sf::lb
