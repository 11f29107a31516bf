// Zou & He (1997) velocity and pressure boundaries. The reconstruction is written
// once, for a left side (inward normal +x), and applied to any side by rotating
// directions and vectors into that frame.
#include "sandflow/lb/lattice_def.hpp"
#include "sandflow/lb/node.hpp"

namespace sf::lb {
namespace {

using d2q9::Q;

// Quarter turns that take the left side's frame onto the given side.
int quarterTurns(int side) {
  switch (side) {
    case left:
      return 0;
    case bottom:
      return 1;
    case right:
      return 2;
    default:
      return 3;  // top
  }
}

Vec2 rotateBack(const Vec2& v, int k) {  // rotate clockwise by k quarter turns
  Vec2 r = v;
  for (int i = 0; i < k; ++i) r = Vec2(r.y(), -r.x());
  return r;
}

// The side's frame: local direction -> global, and the imposed velocity and
// Guo's half force turned into it.
struct Frame {
  int k;
  int g[Q];
  Vec2 u, half;
  Frame(const ZouHeNode& z, const StepContext& ctx) : k(quarterTurns(z.side)) {
    for (int j = 0; j < Q; ++j) g[j] = d2q9::rotate(j, k);
    u = rotateBack(z.velocity, k);
    // Guo forcing defines the velocity with half the force: the rebuilt first
    // moment must be rho u - F/2 for the node to see velocity u.
    half = ctx.forceScheme == ForceScheme::guo
               ? Vec2(rotateBack(Vec2(ctx.params.fx, ctx.params.fy), k) * 0.5)
               : Vec2(Vec2::Zero());
  }
};

// Replaces the three populations of `f` (global directions) that would come
// from outside the side with Zou and He's; `u` is the velocity to impose, in
// the side's frame.
void rebuildUnknowns(const ZouHeNode& z, const Frame& fr, const Vec2& u, double (&f)[Q]) {
  const int* g = fr.g;
  // Known populations in the local frame: 0, 3, 7 (tangential), 4, 5, 6 (outgoing).
  const double tangential = f[g[0]] + f[g[3]] + f[g[7]];
  const double outgoing = f[g[4]] + f[g[5]] + f[g[6]];
  double rho, jx, jy;
  if (z.pressure) {
    rho = z.density;
    jx = rho - tangential - 2 * outgoing;
    jy = -fr.half.y();
  } else {
    rho = (tangential + 2 * outgoing - fr.half.x()) / (1 - u.x());
    jx = rho * u.x() - fr.half.x();
    jy = rho * u.y() - fr.half.y();
  }
  const double shear = 0.5 * (f[g[3]] - f[g[7]]);
  f[g[1]] = f[g[5]] + 2.0 / 3.0 * jx;
  f[g[2]] = f[g[6]] - shear + jx / 6 + 0.5 * jy;
  f[g[8]] = f[g[4]] + shear + jx / 6 - 0.5 * jy;
}

// The node's inputs in the step's layout (those from outside are stale).
void pull(const StepContext& ctx, std::int64_t node, double (&f)[Q]) {
  const Slots slots = ctx.slots();
  for (int i = 0; i < Q; ++i) f[i] = ctx.src[slots.input(ctx.from, i, node)];
}

template <Collision C, ForceScheme S>
StepStats run(const ZouHeNode& z, const StepContext& ctx) {
  const Frame frame(z, ctx);
  const Slots slots = ctx.slots();
  const Layout to = flipped(ctx.from);
  StepStats stats;
  const bool varies = !z.velocities.empty();
  for (std::size_t m = 0; m < z.nodes.size(); ++m) {
    const std::int64_t node = z.nodes[m];
    double f[Q];
    pull(ctx, node, f);
    rebuildUnknowns(z, frame, varies ? rotateBack(z.velocities[m], frame.k) : frame.u, f);
    double u2;
    const double density = collide<C, S>(f, ctx.params, u2);
    stats.merge({density, u2});
    // In place: every input was read above, and the outputs go to the same slots.
    for (int i = 0; i < Q; ++i) ctx.dst[slots.post(to, i, node)] = f[i];
  }
  return stats;
}

}  // namespace

StepStats ZouHeNode::streamCollide(const StepContext& ctx) const {
  const bool guo = ctx.forceScheme == ForceScheme::guo;
  if (ctx.collision == Collision::bgk)
    return guo ? run<Collision::bgk, ForceScheme::guo>(*this, ctx)
               : run<Collision::bgk, ForceScheme::nodal>(*this, ctx);
  return guo ? run<Collision::trt, ForceScheme::guo>(*this, ctx)
             : run<Collision::trt, ForceScheme::nodal>(*this, ctx);
}

void ZouHeNode::pulled(const StepContext& ctx, std::size_t m, double (&f)[Q]) const {
  pull(ctx, nodes[m], f);
  const Frame frame(*this, ctx);
  rebuildUnknowns(*this, frame, velocities.empty() ? frame.u : rotateBack(velocities[m], frame.k),
                  f);
}

}  // namespace sf::lb
