// sim estimate against the time it predicts (issue 26), on three scenes: a
// pure lattice, a pure element bed and a coupled scene. For each: the
// estimate of N steps from trial steps on a copy (nothing run yet), then N
// steps timed; then the estimate from that run, and N more steps timed. The
// ratio estimate / measured should lie within 0.7 to 1.3.
//
//   sandflow_estimate_bench ?--steps N? ?--threads T?
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <numbers>
#include <random>
#include <string>

#include "bench_scenes.hpp"
#include "sandflow/sim/estimate.hpp"

namespace {

using namespace sf;
using Clock = std::chrono::steady_clock;
using bench::channel;

int softMaterial(dem::Assembly& a, double kn) {
  dem::Material mat{"soft"};
  mat.density = 3.0;
  mat.kn = mat.ks = kn;
  mat.friction = 0.3;
  return a.materials().add(mat);
}

// A dense bed of 3,600 discs, stirred: they press on each other at once.
void bed(sim::Manager& m) {
  const int mat = softMaterial(m.assembly(), 0.1);  // critical step about 10
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 3600; ++k) {
    dem::ElementDef d;
    d.shape = std::make_unique<dem::Disc>(0.5 + 0.02 * u(rng));
    d.material = mat;
    d.x = Vec2((k % 60) * 1.02, (k / 60) * 1.02);
    d.v = 0.005 * Vec2(u(rng), u(rng));
    m.assembly().add(std::move(d));
  }
  m.setTimestep(1.0);
  // Past the first jostle, whose contacts come and go faster than later on.
  for (int k = 0; k < 300; ++k) m.step();
}

// The coupled bench's scene: discs of radius 8 covering 10% of a 1024^2 lattice.
void coupled(sim::Manager& m) {
  const int n = 1024;
  m.createLattice(channel(n));
  bench::scatterDiscs(m, n, 0.10, 11, softMaterial(m.assembly(), 1e-4));
}

// N steps as `run` takes them: the profile reset, then timed.
sim::RunRecord timedRun(sim::Manager& m, int steps) {
  m.profile().reset();
  const auto t0 = Clock::now();
  for (int k = 0; k < steps; ++k) m.step();
  return sim::recordRun(m, std::chrono::duration<double>(Clock::now() - t0).count(), steps);
}

void scene(const char* name, const std::function<void(sim::Manager&)>& build, int steps,
           int threads) {
  sim::Manager m;
  m.setThreads(threads);
  build(m);
  const auto t0 = Clock::now();
  const sim::Estimate trial = sim::estimate(m, steps, nullptr);
  const double trialCost = std::chrono::duration<double>(Clock::now() - t0).count();
  const sim::RunRecord first = timedRun(m, steps);
  const sim::Estimate fromRun = sim::estimate(m, steps, &first);
  const sim::RunRecord second = timedRun(m, steps);
  std::printf(
      "%-34s trial (%lld steps, took %.2f s): estimate %8.3f s, measured %8.3f s, ratio %.2f\n",
      name, trial.basisSteps, trialCost, trial.seconds, first.seconds,
      trial.seconds / first.seconds);
  std::printf(
      "%-34s last run (%lld steps):            estimate %8.3f s, measured %8.3f s, ratio %.2f\n",
      "", fromRun.basisSteps, fromRun.seconds, second.seconds, fromRun.seconds / second.seconds);
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  int steps = 100, threads = 2;
  for (int k = 1; k < argc; ++k) {
    if (!std::strcmp(argv[k], "--steps") && k + 1 < argc)
      steps = std::max(1, std::atoi(argv[++k]));
    else if (!std::strcmp(argv[k], "--threads") && k + 1 < argc)
      threads = std::max(1, std::atoi(argv[++k]));
    else {
      std::fprintf(stderr, "usage: %s ?--steps N? ?--threads T?\n", argv[0]);
      return 2;
    }
  }
  std::printf("sim estimate of %d steps against the same steps timed, %d threads\n", steps,
              threads);
  scene(
      "lattice 1024^2", [](sim::Manager& m) { m.createLattice(channel(1024)); }, steps, threads);
  scene("element bed, 3600 discs", bed, steps, threads);
  scene("coupled 1024^2, discs covering 10%", coupled, steps, threads);
  std::printf("target: each ratio within 0.7 to 1.3\n");
  return 0;
}
