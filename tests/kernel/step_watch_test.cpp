// The step's watch (sim/step_watch.hpp): each check warns once with its own
// code when its scene leaves the trusted range, and not in a scene that
// stays in it; a checkpoint keeps what was given.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "coupled_helpers.hpp"
#include "lattice_helpers.hpp"
#include "sandflow/io/checkpoint.hpp"

namespace sf {
namespace {

using sim::WarningCode;

// The codes of the warnings given since the last call.
std::vector<WarningCode> codes(sim::Manager& m) {
  std::vector<WarningCode> out;
  for (const sim::Warning& w : m.takeWarnings()) out.push_back(w.code);
  return out;
}

int count(const std::vector<WarningCode>& c, WarningCode code) {
  int n = 0;
  for (WarningCode x : c) n += x == code;
  return n;
}

// Steps until the watch gives `code` or `steps` have run; the codes given.
std::vector<WarningCode> runFor(sim::Manager& m, int steps) {
  std::vector<WarningCode> all;
  for (int k = 0; k < steps; ++k) {
    m.step();
    for (WarningCode c : codes(m)) all.push_back(c);
  }
  return all;
}

TEST(StepWatch, MachOncePerLattice) {
  sim::Manager m;
  lb::LatticeDef def = test::periodicSquare(1.0, 16, 0.01, 0.8);
  const double h = 1.0 / 16, dt = (2 * 0.8 - 1) / 6 * h * h / 0.01;
  def.forcing = Vec2(2e-3 * h / (dt * dt), 0);  // 2e-3 a step in lattice units: past 0.1 by step 50
  m.createLattice(def);
  EXPECT_EQ(count(runFor(m, 120), WarningCode::mach), 1);
  m.deleteLattice();
  m.createLattice(def);
  EXPECT_EQ(count(runFor(m, 120), WarningCode::mach), 1);  // a new lattice's own
}

TEST(StepWatch, QuietSceneGivesNothing) {
  sim::Manager m;
  m.createLattice(test::channelDef(32, 16, 0.8));
  const int mat = test::softMaterial(m, 2.0);
  test::addDisc(m, mat, Vec2(10, 8), 3.0);
  EXPECT_TRUE(runFor(m, 50).empty());
}

TEST(StepWatch, SolidFasterThanMachPointOneOnce) {
  sim::Manager m;
  m.createLattice(test::periodicSquare(32.0, 32, 0.1, 0.8));  // h = 1
  const double c = m.lattice().params().latticeSpeed();
  const int mat = test::softMaterial(m, 2.0);
  test::addDisc(m, mat, Vec2(16, 16), 4.0, Vec2(0.15 * c, 0));
  const std::vector<WarningCode> given = runFor(m, 5);
  EXPECT_EQ(count(given, WarningCode::solidMach), 1);
}

TEST(StepWatch, UnderResolvedOncePerElement) {
  sim::Manager m;
  m.createLattice(test::periodicSquare(32.0, 32, 0.1, 0.8));
  const int mat = test::softMaterial(m, 2.0);
  const int a = test::addDisc(m, mat, Vec2(8, 8), 0.7);
  const int b = test::addDisc(m, mat, Vec2(24, 24), 0.8);
  runFor(m, 3);
  for (const sim::Warning& w : m.warnings())
    EXPECT_EQ(w.code, WarningCode::underResolved) << w.text;
  ASSERT_EQ(m.warnings().size(), 2u);
  EXPECT_EQ(m.warnings()[0].subject, a);
  EXPECT_EQ(m.warnings()[1].subject, b);
}

TEST(StepWatch, SolidMeetingItsPeriodicImage) {
  sim::Manager m;
  m.createLattice(test::periodicSquare(16.0, 16, 0.1, 0.8));
  test::addDisc(m, test::softMaterial(m, 2.0), Vec2(8, 8), 8.5);  // wider than the lattice
  EXPECT_EQ(count(runFor(m, 3), WarningCode::selfOverlap), 1);
}

TEST(StepWatch, ElementTooLightForTheExplicitCoupling) {
  sim::Manager m;
  m.createLattice(test::periodicSquare(32.0, 32, 0.1, 0.8));
  test::addDisc(m, test::softMaterial(m, 0.5), Vec2(16, 16), 5.0);  // half the fluid's density
  EXPECT_EQ(count(runFor(m, 3), WarningCode::lightElement), 1);
  coupling::Settings implicit;
  implicit.implicit = true;
  sim::Manager n;  // the same scene, implicit: stable, no warning
  n.createLattice(test::periodicSquare(32.0, 32, 0.1, 0.8));
  n.setCouplingSettings(implicit);
  test::addDisc(n, test::softMaterial(n, 0.5), Vec2(16, 16), 5.0);
  EXPECT_EQ(count(runFor(n, 3), WarningCode::lightElement), 0);
}

TEST(StepWatch, BgkWallsSlipPastTauTwo) {
  sim::Manager m;
  m.createLattice(test::channelDef(16, 16, 3.0));
  EXPECT_EQ(count(codes(m), WarningCode::bgkWallSlip), 1);
  lb::LatticeDef trt = test::channelDef(16, 16, 3.0);
  trt.collision = lb::Collision::trt;
  sim::Manager n;
  n.createLattice(trt);
  EXPECT_EQ(count(codes(n), WarningCode::bgkWallSlip), 0);
}

TEST(StepWatch, ElementStepOverItsAccurateStep) {
  sim::Manager m;
  dem::Material stiff{"stiff"};
  stiff.density = 2.0;
  stiff.kn = stiff.ks = 1e4;
  const int mat = m.assembly().materials().add(stiff);
  test::addDisc(m, mat, Vec2(0, 0), 0.1);
  test::addDisc(m, mat, Vec2(0.2, 0), 0.1);
  const double accurate = m.assembly().timestepLimits().accurate;
  m.setTimestep(0.9 * accurate);
  EXPECT_EQ(count(runFor(m, 2), WarningCode::demAccuracy), 0);
  m.setTimestep(1.5 * accurate);
  EXPECT_EQ(count(runFor(m, 2), WarningCode::demAccuracy), 1);
}

TEST(StepWatch, CellReynoldsNearTauHalf) {
  sim::Manager m;
  lb::LatticeDef def = test::channelDef(32, 16, 0.5005);
  const double c = lb::resolve(def).latticeSpeed();
  def.sides[lb::top] = lb::SideDef{lb::SideKind::noslip, Vec2(0.02 * c, 0)};  // a lid at 0.02 c
  m.createLattice(def);
  EXPECT_EQ(count(runFor(m, 20), WarningCode::cellReynolds), 1);
}

TEST(StepWatch, FlowOutrunningItsWalls) {
  sim::Manager m;
  lb::LatticeDef def = test::channelDef(16, 16, 0.8);
  def.sides[lb::top] = lb::SideDef{lb::SideKind::noslip, Vec2(1e-4, 0)};
  m.createLattice(def);
  // A flow a hundred times the lid's speed, which nothing here drives.
  m.lattice().initialize(
      [](const Vec2& x, double&, Vec2& u) { u = Vec2(0.01 * std::sin(0.4 * x.y()), 0); });
  const std::vector<WarningCode> given = runFor(m, 80);  // the start: 4 x 16 steps
  EXPECT_EQ(count(given, WarningCode::outrun), 1);
}

// What was given survives a checkpoint: a loaded scene does not warn again.
TEST(StepWatch, GivenSurvivesACheckpoint) {
  sim::Manager m;
  m.createLattice(test::channelDef(16, 16, 3.0));
  ASSERT_EQ(count(codes(m), WarningCode::bgkWallSlip), 1);
  ByteWriter out;
  m.saveState(out);
  sim::Manager n;
  ByteReader in(out.bytes().data(), out.bytes().size(), io::kCheckpointVersion);
  n.loadState(in);
  ASSERT_EQ(n.warnings().size(), 1u);
  EXPECT_EQ(n.warnings()[0].code, WarningCode::bgkWallSlip);
  EXPECT_TRUE(runFor(n, 3).empty());
}

}  // namespace
}  // namespace sf
