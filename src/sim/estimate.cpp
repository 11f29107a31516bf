#include "sandflow/sim/estimate.hpp"

#include <chrono>
#include <cstdlib>
#include <limits>

#include "sandflow/core/error.hpp"

namespace sf::sim {

SceneSize sceneSize(const Manager& m) {
  SceneSize s;
  s.nodes = m.hasLattice() ? m.lattice().nodes() : 0;
  s.covered = m.solidsCoverCells() ? m.lattice().coveredCells().size() : 0;
  s.elements = m.assembly().bodies().size();
  s.threads = m.threads();
  s.substeps = m.substeps();
  return s;
}

bool sameCost(const SceneSize& before, const SceneSize& now) {
  auto near = [](double a, double b, double share) {
    return std::abs(a - b) <= share * std::max(a, b);
  };
  return before.nodes == now.nodes && before.threads == now.threads &&
         before.substeps == now.substeps && near(before.elements, now.elements, 0.10) &&
         near(double(before.covered), double(now.covered), 0.25);
}

RunRecord recordRun(const Manager& m, double seconds, long long steps) {
  RunRecord r;
  r.profile = m.profile();
  r.scene = sceneSize(m);
  r.seconds = seconds;
  r.steps = steps;
  const double rest = seconds - r.profile.totalSeconds();
  if (steps > 0 && rest > 0) r.profile.set(Stage::other, rest, steps);
  return r;
}

namespace {

// Times trial steps on a copy of `m` loaded from its saved state.
RunRecord trialRun(const Manager& m) {
  using Clock = Profile::Clock;
  Manager copy;
  copy.setThreads(m.threads());
  {  // the bytes go before the steps: memory as the scene's own run has it
    ByteWriter bytes;
    m.saveState(bytes);
    // Bytes this build just wrote: its own format, whatever number the
    // checkpoint files give it (io, after sim, keeps that).
    ByteReader in(bytes.bytes().data(), bytes.bytes().size(), std::numeric_limits<int>::max());
    copy.loadState(in);
  }
  try {
    copy.step();  // warms up: pages, contact pairs, coverage caches
    copy.profile().reset();
    const auto t0 = Clock::now();
    double seconds = 0;
    long long steps = 0;
    while (steps < kTrialMin || (steps < kTrialMax && seconds < kTrialSeconds)) {
      copy.step();
      ++steps;
      seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    }
    return recordRun(copy, seconds, steps);
  } catch (const Error& e) {
    throw Error(e.code(), std::string("a trial step on a copy of the scene failed: ") + e.what(),
                e.remedy());
  }
}

}  // namespace

Estimate estimate(const Manager& m, long long steps, const RunRecord* lastRun) {
  Estimate e;
  e.steps = steps;
  const bool fromRun = lastRun && lastRun->steps > 0 && sameCost(lastRun->scene, sceneSize(m));
  const RunRecord trial = fromRun ? RunRecord() : trialRun(m);
  const RunRecord& basis = fromRun ? *lastRun : trial;
  e.trial = !fromRun;
  e.basisSteps = basis.steps;
  const double scale = double(steps) / double(basis.steps);
  e.seconds = basis.seconds * scale;
  for (int k = 0; k < kStageCount; ++k) {
    const StageTime& t = basis.profile[Stage(k)];
    e.ran[k] = t.steps > 0;
    e.stages[k] = t.seconds * scale;
  }
  return e;
}

}  // namespace sf::sim
