// A fixed disc in a body-forced channel (thesis case A, shortened): the steady
// drag converges under refinement, and at steady state the drag and the walls
// together balance the forcing on the whole channel.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "coupled_helpers.hpp"

namespace sf {
namespace {

struct Drag {
  double drag, lift, balance;
};

// Channel [0,1] x [0,0.5], disc of radius 0.051 at (0.3, 0.25), viscosity 0.05,
// forcing 0.02 (Re about 2): steady after a few H^2 / (pi^2 nu).
Drag steadyDrag(int cells) {
  sim::Manager m;
  lb::LatticeDef def;
  def.size = Vec2(1.0, 0.5);
  def.cells = cells;
  def.viscosity = 0.05;
  def.forcing = Vec2(0.02, 0);
  m.createLattice(def);
  const int id = test::addDisc(m, test::softMaterial(m, 2.0), Vec2(0.3, 0.25), 0.051, Vec2::Zero(),
                               0, dem::holdX | dem::holdY | dem::holdRotation);
  const long steps = std::lround(3.0 / m.lattice().params().dt);
  for (long k = 0; k < steps; ++k) m.step();
  const dem::Bodies& b = m.assembly().bodies();
  const Vec2 F = b.fluidForce[b.slot(id)];
  // The momentum the walls take (bounce-back links) plus the disc's drag
  // balance the forcing on the whole lattice at steady state.
  double wall = 0;
  const lb::Lattice& l = m.lattice();
  for (int i = 0; i < l.nx(); ++i) {
    // wall shear stress nu rho du/dy at the bottom and top, by one-sided
    // differences of the first two fluid rows (walls halfway)
    const double h = l.params().h;
    const double ub = (9 * l.velocity(i, 0).x() - l.velocity(i, 1).x()) / (3 * h);
    const double ut = (9 * l.velocity(i, l.ny() - 1).x() - l.velocity(i, l.ny() - 2).x()) / (3 * h);
    wall += 0.05 * (ub + ut) * h;
  }
  return {F.x(), F.y(), (F.x() + wall) / (0.02 * 0.5)};
}

TEST(ChannelDisc, SteadyDragConvergesUnderRefinement) {
  const Drag a = steadyDrag(24), b = steadyDrag(48), c = steadyDrag(96);
  std::printf("drag: %.6e %.6e %.6e; changes %.3e %.3e; balance %.4f %.4f %.4f\n", a.drag, b.drag,
              c.drag, b.drag - a.drag, c.drag - b.drag, a.balance, b.balance, c.balance);
  EXPECT_GT(c.drag, 0);
  // Halving h cuts the change by 3.2 (order 1.7) here: at least first order,
  // and the finest lattice (10 cells across the disc) within 5% of the next.
  EXPECT_GT((b.drag - a.drag) / (c.drag - b.drag), 2.0);
  EXPECT_LT(std::abs(c.drag - b.drag), 0.05 * c.drag);
  EXPECT_LT(std::abs(c.lift), 1e-6 * c.drag);  // symmetric about the centreline
  EXPECT_NEAR(c.balance, 1.0, 0.03);
}

}  // namespace
}  // namespace sf
