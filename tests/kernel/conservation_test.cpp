// Conservation, determinism and the stability watch of the lattice.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <random>

#include "lattice_helpers.hpp"
#include "sandflow/core/error.hpp"
#include "sandflow/core/parallel.hpp"

namespace sf {
namespace {

// A random but smooth-enough initial state, repeatable.
void randomize(lb::Lattice& lattice, double speed, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1, 1);
  lattice.initialize([&](const Vec2&, double& rho, Vec2& u) {
    rho = 1.0 + 0.01 * d(rng);
    u = speed * Vec2(d(rng), d(rng)) + Vec2(0.3 * speed, 0.1 * speed);
  });
}

lb::LatticeDef periodicBox(int n) {
  lb::LatticeDef def;
  def.size = Vec2(n, n);
  def.cells = n;
  def.viscosity = 0.05;
  for (auto& side : def.sides) side = lb::SideDef{lb::SideKind::periodic};
  return def;
}

TEST(Conservation, MassOverTenThousandStepsWithWallsObstacleAndForcing) {
  lb::LatticeDef def = test::channelDef(48, 32, 0.9);
  def.forcing = Vec2(1e-6, 0);
  lb::Lattice lattice(lb::resolve(def));
  lattice.addObstacle({-1, Vec2(10, 10), Vec2(16, 20), false});
  lattice.addObstacle({-1, Vec2(30, 4), Vec2(36, 12), true});
  const double m0 = lattice.mass();
  for (int s = 0; s < 10000; ++s) lattice.step();
  EXPECT_LE(std::abs(lattice.mass() - m0) / m0, 1e-12);
}

TEST(Conservation, MassAndMomentumOnAPeriodicLattice) {
  for (lb::Collision c : {lb::Collision::bgk, lb::Collision::trt}) {
    lb::LatticeDef def = periodicBox(32);
    def.collision = c;
    lb::Lattice lattice(lb::resolve(def));
    const double cl = lattice.params().latticeSpeed();
    randomize(lattice, 0.02 * cl, 7);
    const double m0 = lattice.mass();
    const Vec2 p0 = lattice.momentum();
    for (int s = 0; s < 10000; ++s) lattice.step();
    EXPECT_LE(std::abs(lattice.mass() - m0) / m0, 1e-12);
    EXPECT_LE((lattice.momentum() - p0).norm() / p0.norm(), 1e-12);
  }
}

TEST(Conservation, ForcingAddsExactlyItsImpulse) {
  lb::LatticeDef def = periodicBox(16);
  def.forcing = Vec2(2e-5, -1e-5);
  for (lb::ForceScheme s : {lb::ForceScheme::nodal, lb::ForceScheme::guo}) {
    def.forceScheme = s;
    lb::Lattice lattice(lb::resolve(def));
    const int steps = 500;
    for (int k = 0; k < steps; ++k) lattice.step();
    const double area = 16.0 * 16.0;
    const Vec2 expected = def.forcing * area * steps * lattice.params().dt;
    EXPECT_LE((lattice.momentum() - expected).norm() / expected.norm(), 1e-10);
  }
}

// Everything at once: walls, moving wall, slip, obstacles, Zou-He, forcing.
lb::LatticeDef busyScene(int nx = 96, int ny = 40) {
  lb::LatticeDef def = test::channelDef(nx, ny, 0.7);
  const double cs = lb::resolve(def).soundSpeed();
  def.sides[lb::left] = lb::SideDef{lb::SideKind::velocity, Vec2(0.001, 0)};
  def.sides[lb::right] = lb::SideDef{lb::SideKind::pressure, Vec2::Zero(), cs * cs};
  def.sides[lb::top] = lb::SideDef{lb::SideKind::noslip, Vec2(0.002, 0)};
  def.forcing = Vec2(1e-7, 1e-8);
  return def;
}

// 512 x 64: twice the nodes from which the sweep goes parallel.
TEST(Determinism, OneAndTwoThreadsGiveIdenticalPopulations) {
  for (lb::Collision c : {lb::Collision::bgk, lb::Collision::trt}) {
    std::vector<double> result[2];
    for (int threads : {1, 2}) {
      lb::LatticeDef def = busyScene(512, 64);
      def.collision = c;
      lb::Lattice lattice(lb::resolve(def));
      lattice.setThreads(threads);
      lattice.addObstacle({-1, Vec2(20, 15), Vec2(28, 25), false});
      lattice.addObstacle({-1, Vec2(50, 0), Vec2(60, 6), true});
      ASSERT_GE(lattice.nodes(), std::size_t(2 * parallel::kLatticeNodes));
      for (int s = 0; s < 200; ++s) lattice.step();
      result[threads - 1] = lattice.populations();
    }
    ASSERT_EQ(result[0].size(), result[1].size());
    EXPECT_EQ(0,
              std::memcmp(result[0].data(), result[1].data(), result[0].size() * sizeof(double)));
  }
}

// A channel wide enough that its wall and periodic links (over 9,000) are
// filled on several threads: the same populations as on one.
TEST(Determinism, LinksFilledOnTwoThreadsAsOnOne) {
  std::vector<double> result[2];
  for (int threads : {1, 2}) {
    lb::LatticeDef def = test::channelDef(1500, 12, 0.8);
    def.sides[lb::top] = lb::SideDef{lb::SideKind::noslip, Vec2(0.003, 0)};  // moving: links add
    lb::Lattice lattice(lb::resolve(def));
    lattice.setThreads(threads);
    randomize(lattice, 0.02, 11);
    for (int s = 0; s < 50; ++s) lattice.step();
    result[threads - 1] = lattice.populations();
  }
  ASSERT_EQ(result[0].size(), result[1].size());
  EXPECT_EQ(0, std::memcmp(result[0].data(), result[1].data(), result[0].size() * sizeof(double)));
}

// A lattice that keeps its previous state goes back to the last good one; one
// streamed in place has taken the step that found the flow too fast.
TEST(Stability, MachBlowUpStopsAndKeepsTheLastGoodState) {
  for (const bool keep : {true, false}) {
    lb::LatticeDef def = test::channelDef(16, 16, 1.0);
    def.forcing = Vec2(5e-4, 0);  // accelerates without bound in a periodic box
    for (auto& side : def.sides) side = lb::SideDef{lb::SideKind::periodic};
    lb::Lattice lattice(lb::resolve(def));
    lattice.keepPrevious(keep);
    std::vector<double> good;
    int steps = 0;
    try {
      for (; steps < 100000; ++steps) {
        good = lattice.populations();
        lattice.step(0.3);
      }
      FAIL() << "no instability reported";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), "UNSTABLE MACH");
      EXPECT_NE(std::string(e.what()).find("node ("), std::string::npos) << e.what();
    }
    EXPECT_GT(steps, 10);
    EXPECT_EQ(lattice.populations() == good, keep);
    EXPECT_TRUE(lattice.validate().empty());
    if (keep) {
      EXPECT_LE(lattice.maxMach(), 0.3);
    }
  }
}

TEST(Stability, NanIsReportedWithItsNode) {
  lb::LatticeDef def = periodicBox(8);
  lb::Lattice lattice(lb::resolve(def));
  lattice.initialize([&](const Vec2& x, double& rho, Vec2&) {
    if (x.x() > 3 && x.x() < 4 && x.y() > 5 && x.y() < 6) rho = 1e308;
  });
  try {
    for (int s = 0; s < 10; ++s) lattice.step();
    FAIL() << "no instability reported";
  } catch (const Error& e) {
    EXPECT_EQ(e.code().rfind("UNSTABLE", 0), 0u) << e.code();
  }
}

TEST(Obstacle, DragBalancesTheBodyForceAtSteadyState) {
  // Fully periodic: the obstacle alone holds the fluid back, so at steady state
  // its drag equals the body force on all the fluid.
  lb::LatticeDef def = periodicBox(24);
  def.viscosity = 0.2;
  def.tau = 1.4;
  def.forcing = Vec2(2e-6, 0);
  lb::Lattice lattice(lb::resolve(def));
  const int id = lattice.addObstacle({-1, Vec2(8, 8), Vec2(16, 16), false});
  test::runToSteady(lattice, 1e-11, 200000);
  const lb::ObstacleInfo info = lattice.obstacleInfo(id);
  const double fluidArea = 24.0 * 24.0 - double(info.nodes);
  EXPECT_NEAR(info.force.x() / (def.forcing.x() * fluidArea), 1.0, 1e-6);
  EXPECT_NEAR(info.force.y(), 0.0, 1e-9 * info.force.x());
  EXPECT_NEAR(info.torque, 0.0, 1e-6 * info.force.x());  // symmetric about y
}

TEST(Lattice, RefusesUnstableAndInconsistentDefinitions) {
  lb::LatticeDef def = test::channelDef(8, 8, 0.5);
  EXPECT_THROW(lb::resolve(def), Error);
  def = test::channelDef(8, 8, 1.0);
  def.size = Vec2(8, 8.5);
  EXPECT_THROW(lb::resolve(def), Error);
  def = test::channelDef(8, 8, 1.0);
  def.sides[lb::left] = lb::SideDef{lb::SideKind::noslip};
  EXPECT_THROW(lb::resolve(def), Error);  // right is still periodic
  def = test::channelDef(100000, 100000, 1.0);
  EXPECT_THROW(lb::resolve(def), Error);  // beyond memory, refused before allocating
}

// The bulk computes every fluid node and the covered pass its cells again,
// over that. With eps = 0 that pass is plain BGK, so a lattice with covered
// cells given out of order and twice must follow the plain one to round-off:
// cells the pass wrote wrongly, or a mass counted twice, would not.
TEST(Covered, CellsWithZeroRatioFollowThePlainLattice) {
  lb::LatticeDef def = periodicBox(32);
  def.forcing = Vec2(1e-6, 2e-7);
  lb::Lattice plain(lb::resolve(def)), covered(lb::resolve(def));
  randomize(plain, 0.02, 5);
  randomize(covered, 0.02, 5);
  std::vector<lb::CoveredCell> cells;
  for (int j : {20, 3, 11, 11, 31, 0})
    for (int i : {0, 7, 8, 9, 31, 7})
      cells.push_back({std::int32_t(covered.nodeIndex(i, j)), false, 0.0, 0.0, 0.0});
  covered.setCoveredCells(cells, false);
  for (int s = 0; s < 200; ++s) plain.step(), covered.step();
  double worst = 0;
  for (int d = 0; d < 9; ++d)
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i)
        worst = std::max(worst, std::abs(plain.population(d, i, j) - covered.population(d, i, j)));
  EXPECT_LT(worst, 1e-14);
  EXPECT_NEAR(covered.mass(), plain.mass(), 1e-12 * plain.mass());
}

// In node order the covered cells run inside the bulk's sweep, block by block;
// out of order, in a pass of their own after it. Both compute each node with
// the same operator, so the populations, each cell's exchange and the step's
// mass (summed span by span, whatever the blocks) agree bit for bit, with one
// thread or two, over a lattice of many blocks; the nodes and the cells are
// twice as many as the sweep and the separate pass need to go parallel.
TEST(Covered, SweepWithTheBulkEqualsTheSeparatePass) {
  const int n = 256;
  lb::LatticeDef def = periodicBox(n);
  def.forcing = Vec2(1e-6, 2e-7);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  lb::Lattice probe(lb::resolve(def));
  std::vector<lb::CoveredCell> sorted;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (u(rng) < 0.6) {
        const double eps = u(rng) < 0.3 ? 1.0 : u(rng);
        const double ux = 0.02 * (u(rng) - 0.5), uy = 0.02 * (u(rng) - 0.5);
        const bool interior = eps == 1.0 && u(rng) < 0.5;
        sorted.push_back({std::int32_t(probe.nodeIndex(i, j)), interior, eps, ux, uy});
      }
  ASSERT_GE(std::ptrdiff_t(sorted.size()), 2 * parallel::kLatticeNodes);
  std::vector<lb::CoveredCell> shuffled = sorted;
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  std::vector<std::vector<double>> finals;
  std::vector<std::map<std::int64_t, Vec2>> exchanges;
  std::vector<double> masses;
  for (int threads : {1, 2})
    for (const auto* cells : {&sorted, &shuffled}) {
      lb::Lattice l(lb::resolve(def));
      l.setThreads(threads);
      randomize(l, 0.02, 5);
      double mass = 0;
      for (int s = 0; s < 30; ++s) {
        l.setCoveredCells(*cells, true);
        mass = l.step().mass;
      }
      masses.push_back(mass);
      std::vector<double> f;
      for (int d = 0; d < 9; ++d)
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i) f.push_back(l.population(d, i, j));
      finals.push_back(f);
      std::map<std::int64_t, Vec2> e;
      for (std::size_t k = 0; k < cells->size(); ++k) e[(*cells)[k].node] = l.coveredExchange()[k];
      exchanges.push_back(e);
    }
  for (std::size_t k = 1; k < finals.size(); ++k) {
    EXPECT_EQ(std::memcmp(finals[0].data(), finals[k].data(), finals[0].size() * sizeof(double)), 0)
        << k;
    EXPECT_TRUE(exchanges[0] == exchanges[k]) << k;
    EXPECT_EQ(std::memcmp(&masses[0], &masses[k], sizeof(double)), 0) << k;
  }
}

// BGK with nodal forcing runs its covered cells eight at a time in vector
// lanes; TRT with omega- = omega+ (Lambda = (tau - 1/2)^2) is the same
// collision, computed cell by cell. Runs both over `cells` on an n x n box and
// expects every population and every cell's exchange to agree to round-off.
void expectLanesAgreeWithCellByCell(int n, const std::vector<lb::CoveredCell>& cells) {
  lb::LatticeDef def = periodicBox(n);
  def.forcing = Vec2(1e-6, -3e-7);
  lb::LatticeDef trt = def;
  trt.collision = lb::Collision::trt;
  const double tau = lb::resolve(def).tau;
  trt.magic = (tau - 0.5) * (tau - 0.5);
  lb::Lattice lattices[2] = {lb::Lattice(lb::resolve(def)), lb::Lattice(lb::resolve(trt))};
  for (lb::Lattice& l : lattices) {
    randomize(l, 0.02, 6);
    for (int s = 0; s < 20; ++s) {
      l.setCoveredCells(cells, true);
      l.step();
    }
  }
  double worst = 0, scale = 0;
  for (int d = 0; d < 9; ++d)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double a = lattices[0].population(d, i, j), b = lattices[1].population(d, i, j);
        worst = std::max(worst, std::abs(a - b)), scale = std::max(scale, std::abs(a));
      }
  EXPECT_LT(worst, 1e-13 * scale);
  double worstExchange = 0, largest = 0;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const Vec2 a = lattices[0].coveredExchange()[k], b = lattices[1].coveredExchange()[k];
    worstExchange = std::max(worstExchange, (a - b).norm()), largest = std::max(largest, a.norm());
  }
  EXPECT_GT(largest, 1e-4);
  EXPECT_LT(worstExchange, 1e-12 * largest);
}

// Cells of every kind (partial, fully covered, interior in runs of eight and
// alone), a count that is not a multiple of eight, blocks of the sweep that
// end mid-batch.
TEST(Covered, VectorLanesAgreeWithTheCellByCellOperator) {
  const int n = 120;
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0, 1);
  lb::Lattice probe(lb::resolve(periodicBox(n)));
  std::vector<lb::CoveredCell> cells;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const bool solidRow = j % 10 == 3 && i >= 20 && i < 20 + 8 * (j % 7 + 1) + j % 5;
      if (solidRow) {
        cells.push_back({std::int32_t(probe.nodeIndex(i, j)), true, 1.0, 0.01, -0.004});
      } else if (u(rng) < 0.12) {
        const double eps = u(rng) < 0.3 ? 1.0 : u(rng);
        const double ux = 0.02 * (u(rng) - 0.5), uy = 0.02 * (u(rng) - 0.5);
        const bool interior = eps == 1.0 && u(rng) < 0.5;
        cells.push_back({std::int32_t(probe.nodeIndex(i, j)), interior, eps, ux, uy});
      }
    }
  cells.pop_back();  // not a multiple of eight
  ASSERT_NE(cells.size() % 8, 0u);
  expectLanesAgreeWithCellByCell(n, cells);
}

// A list out of node order: eight entries whose first and last nodes are
// seven apart need not be eight consecutive nodes (here the second and third
// are swapped), and each cell keeps its own solid ratio and velocity.
TEST(Covered, VectorLanesTakeCellsOutOfNodeOrder) {
  const int n = 64;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  lb::Lattice probe(lb::resolve(periodicBox(n)));
  std::vector<lb::CoveredCell> cells;
  for (int j = 4; j < n; j += 6)
    for (int i = 8; i < 8 + 24; ++i)
      cells.push_back({std::int32_t(probe.nodeIndex(i, j)), false, 0.2 + 0.8 * u(rng),
                       0.02 * (u(rng) - 0.5), 0.02 * (u(rng) - 0.5)});
  for (std::size_t k = 0; k + 8 <= cells.size(); k += 8) std::swap(cells[k + 1], cells[k + 2]);
  expectLanesAgreeWithCellByCell(n, cells);
}

}  // namespace
}  // namespace sf
