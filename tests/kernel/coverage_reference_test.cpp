// The coverage kept between steps against the slow reference that measures
// every solid and rebuilds the cell list each step (Coupler::setRebuildEveryStep):
// over a long run of moving, turning, overlapping and leaving solids of every
// shape, across periodic edges and inside a turning container, the same
// covered cells and solid ratios to the bit, the same solid velocities,
// forces and torques to round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "coupled_helpers.hpp"
#include "sandflow/dem/polygon.hpp"
#include "sandflow/dem/superquadric.hpp"

namespace sf {
namespace {

constexpr std::uint8_t kHeld = dem::holdX | dem::holdY | dem::holdRotation;

// Inside a container the scene is drawn in to 0.6 of its size about the
// centre and slowed to 0.3: the solids keep clear of the container's wall
// (a held solid driven into it squeezes the fluid out faster than Mach 0.3).
double drawnIn = 1.0;

void add(sim::Manager& m, int material, std::unique_ptr<dem::Shape> shape, const Vec2& x,
         const Vec2& v, double w, double angle = 0) {
  dem::ElementDef d;
  d.shape = std::move(shape);
  d.material = material;
  const double slow = drawnIn < 1 ? 0.3 : 1.0;
  d.x = Vec2(0.5, 0.5) + drawnIn * (x - Vec2(0.5, 0.5)), d.v = slow * v, d.w = slow * w;
  d.angle = angle, d.hold = kHeld;
  m.assembly().add(std::move(d));
}

std::unique_ptr<dem::Shape> hexagon() {
  Vec2 centroid;
  return std::make_unique<dem::Polygon>(dem::Polygon::fromVertices(
      {{0, 0}, {0.1, -0.03}, {0.19, 0.04}, {0.17, 0.13}, {0.06, 0.16}, {-0.03, 0.08}}, centroid));
}

// Solids of every shape on a 1 x 1 lattice of 100 cells, held to their
// velocities (so that the two runs move them alike whatever the fluid does):
// across the periodic edges, through each other, only turning, out through a
// wall, and a moving circular wall; with `container` drawn in, inside a
// turning container.
void buildScene(sim::Manager& m, bool container) {
  lb::LatticeDef def = test::periodicSquare(1.0, 100, 0.01);
  if (!container) def.sides[lb::bottom] = def.sides[lb::top] = lb::SideDef{lb::SideKind::noslip};
  m.createLattice(def);
  const int mat = test::softMaterial(m, 3.0);
  drawnIn = container ? 0.6 : 1.0;
  // Across the periodic edge in x, turning.
  add(m, mat, std::make_unique<dem::Disc>(0.08), Vec2(0.9, 0.3), Vec2(0.25, 0.02), 2.0);
  // Only turning: its cells stay as they are.
  add(m, mat, std::make_unique<dem::Disc>(0.05), Vec2(0.5, 0.15), Vec2::Zero(), 3.0);
  // A polygon and a superquadric moving and turning; the superquadric out
  // through the bottom wall (or across the periodic bottom edge).
  add(m, mat, hexagon(), Vec2(0.3, 0.7), Vec2(-0.2, 0.05), 1.5, 0.3);
  add(m, mat, std::make_unique<dem::Superquadric>(0.07, 0.04, 4, 2.5, 48), Vec2(0.7, 0.09),
      Vec2(0.1, -0.3), -2.0, 0.2);
  add(m, mat, std::make_unique<dem::Superquadric>(0.05, 0.05, 1, 1, 16), Vec2(0.15, 0.5),
      Vec2(0.05, 0.2), 4.0);
  // Two discs that pass through each other (held: their contact moves neither).
  add(m, mat, std::make_unique<dem::Disc>(0.06), Vec2(0.35, 0.5), Vec2(0.2, 0.0), 0.0);
  add(m, mat, std::make_unique<dem::Disc>(0.06), Vec2(0.58, 0.53), Vec2(-0.2, 0.0), -1.0);
  // A wall element: it covers no area.
  add(m, mat, std::make_unique<dem::Wall>(0.3, 0.01), Vec2(0.5, 0.85), Vec2(0.05, 0), 0.5);
  lb::Lattice& l = m.lattice();
  // A moving circular wall that crosses the discs' path (cells shared with them).
  l.addCircle({-1, Vec2(0.5, 0.5) + drawnIn * Vec2(-0.05, -0.08), 0.05, false,
               Vec2(0.0, container ? 0.05 : 0.15), 0.0});
  if (container) l.addCircle({-1, Vec2(0.5, 0.5), 0.47, true, Vec2::Zero(), 1.0});
}

// The largest force or torque magnitude among the elements and circles: the
// scale of round-off.
double loadScale(const sim::Manager& m) {
  const dem::Bodies& b = m.assembly().bodies();
  double s = 1e-300;
  for (int k = 0; k < b.size(); ++k)
    s = std::max({s, b.fluidForce[k].norm(), std::abs(b.fluidTorque[k])});
  for (const lb::CircleObstacle& c : m.lattice().circles())
    s = std::max({s, c.force.norm(), std::abs(c.torque)});
  return s;
}

TEST(CoverageReference, KeptCoverageEqualsAFullRebuildEveryStep) {
  for (bool container : {false, true}) {
    sim::Manager kept, rebuilt;
    buildScene(kept, container);
    buildScene(rebuilt, container);
    rebuilt.coupler().setRebuildEveryStep(true);
    std::size_t compared = 0, partial = 0, interior = 0, remeasured = 0, total = 0;
    int fewerSteps = 0;  // steps that measured fewer cells than the reference
    for (int step = 0; step < 600; ++step) {
      kept.step();
      rebuilt.step();
      const std::vector<lb::CoveredCell>& a = kept.lattice().coveredCells();
      const std::vector<lb::CoveredCell>& b = rebuilt.lattice().coveredCells();
      ASSERT_EQ(a.size(), b.size()) << "step " << step;
      for (std::size_t k = 0; k < a.size(); ++k) {
        ASSERT_EQ(a[k].node, b[k].node) << "step " << step << " cell " << k;
        ASSERT_EQ(a[k].interior, b[k].interior) << "step " << step << " cell " << k;
        ASSERT_EQ(a[k].eps, b[k].eps) << "step " << step << " cell " << k;  // to the bit
        ASSERT_NEAR(a[k].ux, b[k].ux, 1e-15) << "step " << step << " cell " << k;
        ASSERT_NEAR(a[k].uy, b[k].uy, 1e-15) << "step " << step << " cell " << k;
      }
      compared += a.size();
      const coupling::Coupler::CellCounts& ka = kept.coupler().cellCounts();
      const coupling::Coupler::CellCounts& kb = rebuilt.coupler().cellCounts();
      EXPECT_EQ(ka.partial, kb.partial);
      EXPECT_EQ(ka.interior, kb.interior);
      EXPECT_GE(kb.remeasured, b.size());  // the reference measures every piece
      partial += ka.partial, interior += ka.interior;
      remeasured += ka.remeasured, total += kb.remeasured;
      fewerSteps += ka.remeasured < kb.remeasured;
      const double scale = loadScale(rebuilt);
      const dem::Bodies &ea = kept.assembly().bodies(), &eb = rebuilt.assembly().bodies();
      for (int s = 0; s < eb.size(); ++s) {
        ASSERT_EQ(ea.x[s], eb.x[s]) << "step " << step;
        EXPECT_NEAR(ea.fluidForce[s].x(), eb.fluidForce[s].x(), 1e-12 * scale) << step;
        EXPECT_NEAR(ea.fluidForce[s].y(), eb.fluidForce[s].y(), 1e-12 * scale) << step;
        EXPECT_NEAR(ea.fluidTorque[s], eb.fluidTorque[s], 1e-12 * scale) << step;
      }
      const auto &ca = kept.lattice().circles(), &cb = rebuilt.lattice().circles();
      for (std::size_t k = 0; k < cb.size(); ++k) {
        EXPECT_NEAR(ca[k].force.x(), cb[k].force.x(), 1e-12 * scale) << step;
        EXPECT_NEAR(ca[k].torque, cb[k].torque, 1e-12 * scale) << step;
        EXPECT_EQ(ca[k].cells, cb[k].cells) << step;
      }
    }
    std::printf("%s: %zu cells compared (%zu partial, %zu interior); %zu of %zu remeasured\n",
                container ? "container" : "channel", compared, partial, interior, remeasured,
                total);
    // The run covered cells of every kind, and the kept coverage measured
    // fewer cells than the reference (the turning disc, the fixed container).
    EXPECT_GT(partial, 10000u);
    EXPECT_GT(interior, 10000u);
    EXPECT_LT(remeasured, total);
    EXPECT_GT(fewerSteps, 590);
  }
}

// A scene where nothing moves but turning discs and a turning container:
// after the first step no cell is measured again.
TEST(CoverageReference, TurningDiscsKeepTheirCells) {
  sim::Manager m;
  m.createLattice(test::periodicSquare(1.0, 80, 0.01));
  const int mat = test::softMaterial(m, 3.0);
  for (int k = 0; k < 4; ++k)
    add(m, mat, std::make_unique<dem::Disc>(0.07), Vec2(0.25 + 0.5 * (k % 2), 0.25 + 0.5 * (k / 2)),
        Vec2::Zero(), 1.0 + k);
  m.lattice().addCircle({-1, Vec2(0.5, 0.5), 0.45, true, Vec2::Zero(), 0.5});
  m.step();
  EXPECT_GT(m.coupler().cellCounts().remeasured, 0u);
  for (int k = 0; k < 20; ++k) {
    m.step();
    EXPECT_EQ(m.coupler().cellCounts().remeasured, 0u) << k;
  }
  EXPECT_GT(m.coupler().coveredCells(), 1000u);
  EXPECT_NE(m.assembly().bodies().angle[0], 0.0);
}

}  // namespace
}  // namespace sf
