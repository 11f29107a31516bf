// Classifies every node and builds the batches of each node kind: the fluid
// spans, the Zou-He edges and the links that walls and periodic edges fill.
// Rebuilt when walls or obstacles change, never per step.
#include <algorithm>
#include <cmath>

#include "sandflow/core/error.hpp"
#include "sandflow/lb/lattice.hpp"

namespace sf::lb {
namespace {

using d2q9::ex;
using d2q9::ey;

bool isWall(NodeKind k) {
  return k == NodeKind::noslip || k == NodeKind::slip;
}
bool holdsFluidKind(NodeKind k) {
  return k == NodeKind::fluid || k == NodeKind::velocity || k == NodeKind::pressure;
}

// What a (possibly halo) grid position is, after periodic wrapping.
struct Where {
  NodeKind kind;
  std::int64_t node;  // padded index of the interior node it wraps to; -1 outside
  int owner;          // obstacle id or -1 - side
};

class Classifier {
 public:
  Classifier(const ResolvedLattice& p, const std::vector<NodeKind>& kind,
             const std::vector<int>& owner)
      : p_(p), kind_(kind), owner_(owner) {}

  Where at(int px, int py) const {
    int outside[2] = {-1, -1};  // side index per axis, or -1 inside
    if (px < 0 || px >= p_.nx) {
      if (periodic(left))
        px = (px + p_.nx) % p_.nx;
      else
        outside[0] = px < 0 ? left : right;
    }
    if (py < 0 || py >= p_.ny) {
      if (periodic(bottom))
        py = (py + p_.ny) % p_.ny;
      else
        outside[1] = py < 0 ? bottom : top;
    }
    if (outside[0] < 0 && outside[1] < 0) {
      const std::int64_t node = std::int64_t(py + 1) * (p_.nx + 2) + (px + 1);
      return {kind_[node], node, owner_[node]};
    }
    // A corner takes the kind of its horizontal (bottom/top) side when that is a wall.
    int side = outside[1] >= 0 ? outside[1] : outside[0];
    if (outside[0] >= 0 && outside[1] >= 0 && !wallSide(outside[1])) side = outside[0];
    return {sideKind(side), -1, -1 - side};
  }

  NodeKind sideKind(int side) const {
    switch (p_.def.sides[side].kind) {
      case SideKind::noslip:
        return NodeKind::noslip;
      case SideKind::slip:
        return NodeKind::slip;
      case SideKind::outflow:
        return NodeKind::outflow;
      default:
        return NodeKind::open;
    }
  }

 private:
  bool periodic(int side) const { return p_.def.sides[side].kind == SideKind::periodic; }
  bool wallSide(int side) const { return isWall(sideKind(side)); }
  const ResolvedLattice& p_;
  const std::vector<NodeKind>& kind_;
  const std::vector<int>& owner_;
};

}  // namespace

void Lattice::rebuildTopology() {
  ++topology_;
  canUndo_ = false;
  covered_.cells.clear();  // the coupling covers the new topology before the next step
  covered_.exchange.clear();
  const int nx = p_.nx, ny = p_.ny;
  const std::vector<NodeKind> previous = kind_;
  std::vector<NodeKind> kind(stride_, NodeKind::open);
  std::vector<int> owner(stride_, -1);

  // 1. Interior: fluid, Zou-He edges, then obstacles on top.
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) kind[index(i, j)] = NodeKind::fluid;
  for (int s = 0; s < 4; ++s) {
    const SideKind k = p_.def.sides[s].kind;
    if (k != SideKind::velocity && k != SideKind::pressure) continue;
    const NodeKind nk = k == SideKind::velocity ? NodeKind::velocity : NodeKind::pressure;
    if (s == left || s == right)
      for (int j = 0; j < ny; ++j) kind[index(s == left ? 0 : nx - 1, j)] = nk;
    else
      for (int i = 0; i < nx; ++i) kind[index(i, s == bottom ? 0 : ny - 1)] = nk;
  }
  for (const RectObstacle& r : obstacles_)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const Vec2 x = position(i, j);
        if (x.x() >= r.lo.x() && x.x() <= r.hi.x() && x.y() >= r.lo.y() && x.y() <= r.hi.y()) {
          kind[index(i, j)] = r.slip ? NodeKind::slip : NodeKind::noslip;
          owner[index(i, j)] = r.id;
        }
      }

  // 2. Solid nodes that no fluid node touches do no work.
  Classifier where(p_, kind, owner);
  std::vector<std::int64_t> interior;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (!isWall(kind[index(i, j)])) continue;
      bool bordersFluid = false;
      for (int d = 1; d < 9 && !bordersFluid; ++d)
        bordersFluid = holdsFluidKind(where.at(i + ex[d], j + ey[d]).kind);
      if (!bordersFluid) interior.push_back(index(i, j));
    }
  for (std::int64_t n : interior) kind[n] = NodeKind::solid;
  for (int j = -1; j <= ny; ++j)
    for (int i = -1; i <= nx; ++i)
      if (i < 0 || j < 0 || i >= nx || j >= ny) kind[index(i, j)] = where.at(i, j).kind;

  // 3. Batches.
  auto fluid = std::make_unique<FluidNode>();
  auto periodic = std::make_unique<PeriodicNode>();
  auto bounce = std::make_unique<BounceBackNode>();
  auto slip = std::make_unique<SlipNode>();
  auto solid = std::make_unique<FixedSolidNode>();
  auto outflow = std::make_unique<OutflowNode>();
  std::vector<std::unique_ptr<ZouHeNode>> zouHe(4);

  for (int j = 0; j < ny; ++j) {
    int i = 0;
    while (i < nx) {
      if (kind[index(i, j)] != NodeKind::fluid) {
        ++i;
        continue;
      }
      const int start = i;
      while (i < nx && kind[index(i, j)] == NodeKind::fluid) ++i;
      fluid->spans.push_back({index(start, j), std::int32_t(i - start)});
    }
  }
  solid->nodes = std::count(kind.begin(), kind.end(), NodeKind::solid);
  for (int s = 0; s < 4; ++s) {
    const SideDef& side = p_.def.sides[s];
    if (side.kind != SideKind::velocity && side.kind != SideKind::pressure) continue;
    auto z = std::make_unique<ZouHeNode>();
    z->side = s;
    z->pressure = side.kind == SideKind::pressure;
    z->density = side.pressure / (p_.soundSpeed() * p_.soundSpeed());
    z->velocity = side.velocity * (p_.dt / p_.h);
    zouHe[s] = std::move(z);
  }

  const double rho0 = p_.def.density;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::int64_t x = index(i, j);
      const NodeKind k = kind[x];
      if (!holdsFluidKind(k)) continue;
      if (k != NodeKind::fluid) {
        const int s = (k == NodeKind::velocity || k == NodeKind::pressure)
                          ? (i == 0 && zouHe[left]         ? left
                             : i == nx - 1 && zouHe[right] ? right
                             : j == 0 && zouHe[bottom]     ? bottom
                                                           : top)
                          : 0;
        zouHe[s]->nodes.push_back(x);
      }
      const std::int32_t node = std::int32_t(x);
      for (int d = 1; d < 9; ++d) {
        const std::int8_t in = std::int8_t(d);
        const int si = i - ex[d], sj = j - ey[d];
        const Where w = where.at(si, sj);
        if (holdsFluidKind(w.kind)) {
          if (w.node != index(si, sj))
            periodic->links.push_back({node, in, in, std::int32_t(w.node), 0.0, -1});
          continue;
        }
        if (w.kind == NodeKind::open && k != NodeKind::fluid) continue;  // Zou-He rebuilds it
        if (w.kind == NodeKind::outflow) {
          // The node outside holds the state of the edge node beside it.
          const Where beside = where.at(std::clamp(si, 0, nx - 1), std::clamp(sj, 0, ny - 1));
          if (holdsFluidKind(beside.kind)) {
            outflow->links.push_back({node, in, in, std::int32_t(beside.node), 0.0, w.owner});
            continue;
          }
        }
        const int back = d2q9::opposite[d];
        if (w.kind == NodeKind::slip && d % 2 == 0) {
          // Specular reflection off an axis-aligned wall: find which neighbour
          // along the diagonal's components is fluid and which is wall.
          const Where a = where.at(i - ex[d], j), b = where.at(i, j - ey[d]);
          if (holdsFluidKind(a.kind) && isWall(b.kind)) {
            slip->links.push_back({node, in, std::int8_t(d2q9::direction(ex[d], -ey[d])),
                                   std::int32_t(a.node), 0.0, w.owner});
            continue;
          }
          if (holdsFluidKind(b.kind) && isWall(a.kind)) {
            slip->links.push_back({node, in, std::int8_t(d2q9::direction(-ex[d], ey[d])),
                                   std::int32_t(b.node), 0.0, w.owner});
            continue;
          }
        }
        // Bounce-back (also the fallback at corners and for axis links of slip walls).
        double add = 0.0;
        if (w.owner < 0) {  // a side of the domain: it may move
          const Vec2 u = p_.def.sides[-1 - w.owner].velocity * (p_.dt / p_.h);
          add = 6.0 * d2q9::w[d] * rho0 * (ex[d] * u.x() + ey[d] * u.y());
        }
        LinkNode& target = w.kind == NodeKind::slip ? static_cast<LinkNode&>(*slip) : *bounce;
        target.links.push_back({node, in, std::int8_t(back), node, add, w.owner});
      }
    }

  const Slots slots{stride_, rowStride_};
  for (LinkNode* l : {static_cast<LinkNode*>(periodic.get()), static_cast<LinkNode*>(bounce.get()),
                      static_cast<LinkNode*>(slip.get()), static_cast<LinkNode*>(outflow.get())})
    l->resolve(slots);
  kinds_.clear();
  kinds_.push_back(std::move(fluid));
  for (auto& z : zouHe)
    if (z) kinds_.push_back(std::move(z));
  if (!periodic->links.empty()) kinds_.push_back(std::move(periodic));
  if (!bounce->links.empty()) kinds_.push_back(std::move(bounce));
  if (!slip->links.empty()) kinds_.push_back(std::move(slip));
  if (!outflow->links.empty()) kinds_.push_back(std::move(outflow));
  if (solid->nodes) kinds_.push_back(std::move(solid));
  imposeSides(time_ + p_.dt);
  // Until the next step's list.
  static_cast<FluidNode&>(*kinds_.front()).planSweep(covered_.cells, covered_.ascending);

  // Nodes that start to hold fluid begin at rest at the reference density.
  kind_ = std::move(kind);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::int64_t x = index(i, j);
      if (holdsFluidKind(kind_[x]) && !previous.empty() && !holdsFluidKind(previous[x]))
        setNodeState(x, rho0, Vec2::Zero());
    }
  fill();
}

}  // namespace sf::lb
