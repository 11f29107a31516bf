// The DEM step against its slow reference (Assembly::referenceStep: the
// serial sums down the contact list, the speed checks and kicks slot by
// slot), and the pair upkeep on any thread count (issue 38).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "dem_helpers.hpp"
#include "sandflow/core/byte_stream.hpp"
#include "sandflow/core/error.hpp"
#include "sandflow/core/parallel.hpp"
#include "sandflow/dem/assembly.hpp"
#include "sandflow/dem/polygon.hpp"
#include "sandflow/dem/superquadric.hpp"

namespace sf::dem {
namespace {

const std::vector<int> kThreadCounts = {1, 2, 3, 4};

// A bed of `columns` x `rows` discs (neighbours overlapping a little) falling into a box, every
// part of a scene beside it when `mixed`: a second (Hertz) material, polygons, a superquadric,
// bonded discs, a disc held in x alone, one with an applied force and torque, a source, a plate
// pressing from above.
Assembly fallingBed(int columns, int rows, bool mixed, Integrator integrator) {
  Assembly a;
  a.integrator = integrator;
  Material m{"sand"};
  m.kn = m.ks = 1e5;
  m.restitution = 0.4;
  m.friction = 0.5;
  const int sand = a.materials().add(m);
  Material h{"rubber"};
  h.law = ContactLaw::hertz;
  h.youngs = 1e7;
  h.poisson = 0.3;
  h.restitution = 0.6;
  h.friction = 0.3;
  const int rubber = mixed ? a.materials().add(h) : sand;
  const double pitch = 1.6e-3, W = (columns + 0.6) * pitch, H = (rows + 4) * pitch;
  test::addWall(a, {0, 0}, {W, 0}, sand);
  test::addWall(a, {0, 0}, {0, H}, sand);
  test::addWall(a, {W, 0}, {W, H}, sand);
  std::mt19937 rng(38);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<int> ids;
  for (int row = 0; row < rows; ++row)
    for (int k = 0; k < columns; ++k) {
      const Vec2 x((k + 0.55 + 0.5 * (row % 2)) * pitch, 1.2e-3 + row * pitch);
      const Vec2 v = 0.05 * Vec2(u(rng) - 0.5, u(rng) - 0.5);
      const int mat = mixed && (k + row) % 7 == 0 ? rubber : sand;
      ElementDef d;
      d.material = mat;
      d.x = x, d.v = v, d.w = 20 * (u(rng) - 0.5);
      const int kind = mixed ? (k * 13 + row * 5) % 41 : 1;
      if (kind == 0) {
        Vec2 c;
        d.shape = std::make_unique<Polygon>(Polygon::fromVertices(
            {{-0.5e-3, -0.4e-3}, {0.5e-3, -0.4e-3}, {0.4e-3, 0.45e-3}, {-0.45e-3, 0.4e-3}}, c));
      } else if (kind == 1 && mixed) {
        d.shape = std::make_unique<Superquadric>(0.6e-3, 0.4e-3, 4, 4, 32);
      } else {
        d.shape = std::make_unique<Disc>(0.6e-3 + 0.25e-3 * u(rng));
      }
      ids.push_back(a.add(std::move(d)));
    }
  if (mixed) {
    // Three bonded pairs above the bed; a disc held in x; pushed and turned.
    for (int k = 0; k < 3; ++k) {
      const Vec2 x((0.2 + 0.25 * k) * W, (rows + 2.5) * pitch);
      a.bond(test::addDisc(a, x, 0.65e-3, Vec2::Zero(), sand),
             test::addDisc(a, x + Vec2(1.25e-3, 0), 0.65e-3, Vec2::Zero(), sand));
    }
    ElementEdit held;
    held.hold = holdX;
    a.configure(ids[std::size_t(columns)], held);
    ElementEdit pushed;
    pushed.force = Eigen::Vector3d(2e-4, 0, 1e-7);
    a.configure(ids[std::size_t(2 * columns + 3)], pushed);
    const int top = test::addDisc(a, {0.5 * W, H - 1e-3}, 0.7e-3, Vec2::Zero(), sand);
    a.makeSource(top, Vec2(0, 1e6), 0.0, 4);  // its clones fly up and away
    const int plate =
        test::addWall(a, {0.3 * W, (rows + 1) * pitch}, {0.7 * W, (rows + 1) * pitch}, sand);
    a.setPlateStress(plate, 2.0);
  }
  return a;
}

std::vector<char> state(const Assembly& a) {
  ByteWriter out;
  a.saveState(out);
  return out.bytes();
}

// The step gives the reference step's bits, on any thread count, for each
// integrator, with every kind of element, bonds, holds, a source and a plate.
TEST(DemStep, GivesTheReferenceStepsBitsOnAnyThreadCount) {
  for (Integrator integrator : {Integrator::central, Integrator::euler, Integrator::verlet}) {
    std::vector<std::vector<char>> states;
    for (bool reference : {true, false})
      for (int threads : kThreadCounts) {
        Assembly a = fallingBed(80, 52, true, integrator);
        a.setThreads(threads);
        a.referenceStep = reference;
        const double dt = a.criticalTimestep() / 10;
        for (int s = 0; s < 80; ++s) a.step(dt, Vec2(0, -9.81));
        if (states.empty()) {
          // Above the thresholds the sums and integration go parallel at.
          EXPECT_GE(a.bodies().size(), 2 * parallel::kIntegrateSlots);
          EXPECT_GT(a.touchingCount(), std::size_t(200));
          EXPECT_FALSE(a.bonds().empty());
          EXPECT_GT(a.sources()[0].made, 1);
        }
        states.push_back(state(a));
      }
    for (std::size_t k = 1; k < states.size(); ++k)
      EXPECT_TRUE(states[k] == states[0])
          << integratorNames[int(integrator)] << ": run " << k << " differs from the reference";
  }
}

// While the bed falls, the candidate pairs and the pair builds are the same
// at every step, whatever the thread count.
TEST(DemStep, PairUpkeepIsTheSameOnAnyThreadCount) {
  std::vector<std::vector<long long>> runs;
  for (int threads : kThreadCounts) {
    Assembly a = fallingBed(70, 60, false, Integrator::central);
    a.setThreads(threads);
    const double dt = a.criticalTimestep() / 10;
    std::vector<long long> counts;
    for (int s = 0; s < 400; ++s) {
      a.step(dt, Vec2(0, -9.81));
      counts.push_back(static_cast<long long>(a.contactList().size()));
      counts.push_back(a.broadPhaseBuilds());
    }
    EXPECT_GT(a.broadPhaseBuilds(), 5);  // it moves
    runs.push_back(counts);
  }
  for (std::size_t t = 1; t < runs.size(); ++t)
    EXPECT_EQ(runs[t], runs[0]) << kThreadCounts[t] << " threads against 1";
}

// What the step refuses, it refuses with the reference's words: a disc in
// contact driven to jump (UNSTABLE SPEED), one in free flight driven past
// what a double holds (UNSTABLE NAN), on one thread and on two.
TEST(DemStep, RefusesWhatTheReferenceRefuses) {
  auto refusal = [](bool reference, int threads, bool touching) -> std::string {
    Assembly a = fallingBed(70, 60, false, Integrator::central);
    a.setThreads(threads);
    a.referenceStep = reference;
    const double dt = a.criticalTimestep() / 10;
    for (int s = 0; s < 5; ++s) a.step(dt, Vec2(0, -9.81));
    // A disc of the bottom row, pressed into the floor (or taken far away).
    const int victim = a.bodies().id[std::size_t(3 + 11)];
    ElementEdit e;
    e.force = touching ? Eigen::Vector3d(1e8, 0, 0) : Eigen::Vector3d(-1e308, 0, 0);
    const std::size_t s = 3 + 11;
    e.center = touching ? Vec2(a.bodies().x[s].x(), 0.9 * a.bodies().reach[s]) : Vec2(1.0, 1.0);
    a.configure(victim, e);
    try {
      a.step(dt, Vec2(0, -9.81));
    } catch (const Error& err) {
      return err.code() + ": " + err.what();
    }
    return "no refusal";
  };
  for (bool touching : {true, false}) {
    const std::string expected = refusal(true, 1, touching);
    EXPECT_NE(expected.find(touching ? "UNSTABLE SPEED" : "UNSTABLE NAN"), std::string::npos)
        << expected;
    for (int threads : {1, 2}) EXPECT_EQ(refusal(false, threads, touching), expected);
  }
}

}  // namespace
}  // namespace sf::dem
