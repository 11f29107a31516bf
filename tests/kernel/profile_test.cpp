// The step's profile: every stage a scene needs runs once a step, the stages
// do not overlap (their sum stays under the wall time), a bare kernel keeps
// its own, and an estimate leaves the scene as it was.
#include <gtest/gtest.h>

#include <chrono>

#include "coupled_helpers.hpp"
#include "lattice_helpers.hpp"
#include "sandflow/sim/estimate.hpp"

namespace sf {
namespace {

constexpr Stage kLatticeStages[] = {Stage::latticeBulk, Stage::latticeFill};
constexpr Stage kCouplingStages[] = {Stage::latticeCovered, Stage::coverageMeasure,
                                     Stage::coverageSort, Stage::coverageCells, Stage::fluidForces};
constexpr Stage kDemStages[] = {Stage::demPairs, Stage::demContacts, Stage::demSums,
                                Stage::demIntegrate};
// The run command's own: never recorded by a step.
constexpr Stage kRunStages[] = {Stage::outputs, Stage::pictures, Stage::scripts, Stage::tick,
                                Stage::other};

// Discs in a periodic box of fluid, moving and touching: every kernel stage runs.
int coupledScene(sim::Manager& m) {
  m.createLattice(test::periodicSquare(1.0, 64, 0.01));
  const int mat = test::softMaterial(m, 2.0);
  for (int k = 0; k < 6; ++k)
    test::addDisc(m, mat, Vec2(0.15 + 0.14 * k, 0.5 + 0.02 * (k % 2)), 0.07,
                  Vec2(k % 2 ? 1e-3 : -1e-3, 0));
  return mat;
}

// Steps `steps` times; returns the wall time.
double timedSteps(sim::Manager& m, int steps) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < steps; ++k) m.step();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(Profile, CoupledStepRunsEveryStageOnceAStepAndTheyPartitionIt) {
  sim::Manager m;
  coupledScene(m);
  m.step();
  m.profile().reset();
  const int steps = 20;
  const double wall = timedSteps(m, steps);
  const Profile& p = m.profile();
  for (const auto& group :
       {std::vector<Stage>(std::begin(kLatticeStages), std::end(kLatticeStages)),
        std::vector<Stage>(std::begin(kCouplingStages), std::end(kCouplingStages)),
        std::vector<Stage>(std::begin(kDemStages), std::end(kDemStages))})
    for (Stage s : group) {
      EXPECT_EQ(p[s].steps, steps) << stageName(s);
      EXPECT_GT(p[s].seconds, 0.0) << stageName(s);
    }
  for (Stage s : kRunStages) EXPECT_EQ(p[s].steps, 0) << stageName(s);
  EXPECT_GT(p.totalSeconds(), 0.0);
  EXPECT_LE(p.totalSeconds(), wall);
  EXPECT_EQ(m.assembly().profile().stepsBegun(), p.stepsBegun());  // the Manager's, attached
  EXPECT_EQ(&m.lattice().profile(), &p);
}

TEST(Profile, PureLatticeRecordsOnlyLatticeStages) {
  sim::Manager m;
  m.createLattice(test::periodicSquare(1.0, 32, 0.01));
  const double wall = timedSteps(m, 10);
  const Profile& p = m.profile();
  for (Stage s : kLatticeStages) EXPECT_EQ(p[s].steps, 10) << stageName(s);
  for (Stage s : kCouplingStages) EXPECT_EQ(p[s].steps, 0) << stageName(s);
  for (Stage s : kDemStages) EXPECT_EQ(p[s].steps, 0) << stageName(s);
  EXPECT_LE(p.totalSeconds(), wall);
}

TEST(Profile, SubstepsCountOnceAStep) {
  sim::Manager m;
  coupledScene(m);
  m.setSubsteps(3);
  timedSteps(m, 5);
  for (Stage s : kDemStages) EXPECT_EQ(m.profile()[s].steps, 5) << stageName(s);
}

TEST(Profile, BareKernelsRecordIntoTheirOwn) {
  lb::Lattice lattice(lb::resolve(test::channelDef(32, 16, 0.8)));
  for (int k = 0; k < 4; ++k) lattice.step();
  EXPECT_EQ(lattice.profile()[Stage::latticeBulk].steps, 4);
  EXPECT_EQ(lattice.profile()[Stage::latticeCovered].steps, 0);

  dem::Assembly bare;
  for (int k = 0; k < 4; ++k) {
    dem::ElementDef d;
    d.shape = std::make_unique<dem::Disc>(1.0);
    d.x = Vec2(2.1 * k, 0);
    d.v = Vec2(k % 2 ? -0.1 : 0.1, 0);
    bare.add(std::move(d));
  }
  const double dt = bare.criticalTimestep() / 10;
  for (int k = 0; k < 3; ++k) bare.step(dt, Vec2::Zero());
  EXPECT_EQ(bare.profile()[Stage::demIntegrate].steps, 3);
  EXPECT_EQ(bare.profile()[Stage::demPairs].steps, 3);
  // Moved into a Manager, it records into the Manager's.
  sim::Manager m;
  m.assembly() = std::move(bare);
  m.step();
  EXPECT_EQ(m.profile()[Stage::demIntegrate].steps, 1);
  EXPECT_EQ(&m.assembly().profile(), &m.profile());
}

TEST(Profile, ResetClearsEveryStage) {
  sim::Manager m;
  coupledScene(m);
  timedSteps(m, 2);
  m.profile().reset();
  EXPECT_EQ(m.profile().totalSeconds(), 0.0);
  for (int k = 0; k < kStageCount; ++k) EXPECT_EQ(m.profile()[Stage(k)].steps, 0);
}

TEST(Estimate, TrialLeavesTheSceneBitIdentical) {
  sim::Manager m;
  coupledScene(m);
  timedSteps(m, 3);
  const std::uint32_t before = m.stateHash();
  const sim::Estimate e = sim::estimate(m, 50, nullptr);
  EXPECT_EQ(m.stateHash(), before);
  EXPECT_TRUE(e.trial);
  EXPECT_GE(e.basisSteps, sim::kTrialMin);
  EXPECT_GT(e.seconds, 0.0);
  double sum = 0;
  for (int k = 0; k < kStageCount; ++k) sum += e.stages[k];
  EXPECT_LE(sum, e.seconds * (1 + 1e-12));
  for (Stage s : kDemStages) EXPECT_TRUE(e.ran[int(s)]) << stageName(s);
  // The scene goes on as if no estimate had been made.
  sim::Manager twin;
  coupledScene(twin);
  timedSteps(twin, 3);
  m.step(), twin.step();
  EXPECT_EQ(m.stateHash(), twin.stateHash());
}

TEST(Estimate, UsesTheLastRunWhileTheSceneKeepsItsSize) {
  sim::Manager m;
  const int mat = coupledScene(m);
  m.profile().reset();
  const double wall = timedSteps(m, 10);
  const sim::RunRecord run = sim::recordRun(m, wall, 10);
  EXPECT_EQ(run.profile[Stage::other].steps, 10);
  EXPECT_NEAR(run.profile.totalSeconds(), wall, 1e-9 * wall + 1e-12);
  const sim::Estimate e = sim::estimate(m, 40, &run);
  EXPECT_FALSE(e.trial);
  EXPECT_EQ(e.basisSteps, 10);
  EXPECT_DOUBLE_EQ(e.seconds, 4 * wall);
  EXPECT_DOUBLE_EQ(e.stages[int(Stage::latticeBulk)], 4 * run.profile.seconds(Stage::latticeBulk));
  // Twice the elements: the run no longer tells.
  for (int k = 0; k < 6; ++k) test::addDisc(m, mat, Vec2(0.15 + 0.14 * k, 0.2), 0.05);
  EXPECT_TRUE(sim::estimate(m, 40, &run).trial);
}

TEST(Estimate, SameCostFollowsTheSceneSize) {
  sim::SceneSize a{.nodes = 4096, .covered = 1000, .elements = 100, .threads = 2, .substeps = 1};
  sim::SceneSize b = a;
  EXPECT_TRUE(sim::sameCost(a, b));
  b.elements = 105, b.covered = 1200;
  EXPECT_TRUE(sim::sameCost(a, b));
  b.elements = 120;
  EXPECT_FALSE(sim::sameCost(a, b));
  b = a, b.nodes = 4097;
  EXPECT_FALSE(sim::sameCost(a, b));
  b = a, b.threads = 1;
  EXPECT_FALSE(sim::sameCost(a, b));
  b = a, b.covered = 2000;
  EXPECT_FALSE(sim::sameCost(a, b));
}

}  // namespace
}  // namespace sf
