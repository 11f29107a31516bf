// The Manager's overhead (issue 26): a pure lattice, pure elements and both
// apart (elements all outside the lattice) stepped through the Manager,
// against the bare kernels (Lattice::step, Assembly::step alone). Targets:
// the Manager within 2% of the bare kernel; the scene with both apart within
// 2% of the two pure scenes together. Every case builds its scene afresh in
// each repetition and takes the same steps, so bare and Manager do the same
// work; Google Benchmark interleaves the repetitions (scripts/bench
// --overhead) and the summary takes each case's best.
//
//   sandflow_overhead_bench ?--threads=T? [Google Benchmark flags...]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <random>
#include <string>

#include "bench_scenes.hpp"
#include "sandflow/sim/manager.hpp"

namespace {

using namespace sf;

int gThreads = 1;
constexpr int kLatticeSize = 512;  // cells a side
constexpr int kLatticeSteps = 100, kDemSteps = 400;
constexpr int kDiscsPerSide = 60;              // 3,600 discs
constexpr double kApart = 2.0 * kLatticeSize;  // the discs above the top wall (x is periodic)

lb::LatticeDef channel() {
  return bench::channel(kLatticeSize);
}

// Discs of radius 1 (two cells across: resolved, no warning) on a grid,
// moving at random (they meet and touch), soft enough for dt = 1 (their
// critical step is about 60).
void addDiscs(dem::Assembly& a, double y0) {
  dem::Material mat{"soft"};
  mat.density = 3.0;
  mat.kn = mat.ks = 0.01;
  const int material = a.materials().add(mat);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < kDiscsPerSide * kDiscsPerSide; ++k) {
    dem::ElementDef d;
    d.shape = std::make_unique<dem::Disc>(1.0);
    d.material = material;
    d.x = Vec2((k % kDiscsPerSide) * 2.1, y0 + (k / kDiscsPerSide) * 2.1);
    d.v = 0.01 * Vec2(u(rng), u(rng));
    a.add(std::move(d));
  }
}

void setRate(benchmark::State& state, int steps) {
  state.counters["ms/step"] =
      benchmark::Counter(double(steps) * 1e-3, benchmark::Counter::kIsIterationInvariantRate |
                                                   benchmark::Counter::kInvert);
}

void BM_LatticeBare(benchmark::State& state) {
  for (auto _ : state) {
    state.PauseTiming();
    lb::Lattice lattice(lb::resolve(channel()));
    lattice.setThreads(gThreads);
    lattice.step();  // its pages
    state.ResumeTiming();
    for (int k = 0; k < kLatticeSteps; ++k) lattice.step();
  }
  setRate(state, kLatticeSteps);
}

void BM_LatticeManager(benchmark::State& state) {
  for (auto _ : state) {
    state.PauseTiming();
    sim::Manager m;
    m.setThreads(gThreads);
    m.createLattice(channel());
    m.step();
    state.ResumeTiming();
    for (int k = 0; k < kLatticeSteps; ++k) m.step();
  }
  setRate(state, kLatticeSteps);
}

void BM_DemBare(benchmark::State& state) {
  for (auto _ : state) {
    state.PauseTiming();
    dem::Assembly a;
    a.setThreads(gThreads);
    addDiscs(a, 0);
    state.ResumeTiming();
    for (int k = 0; k < kDemSteps; ++k) a.step(1.0, Vec2::Zero());
  }
  setRate(state, kDemSteps);
}

void BM_DemManager(benchmark::State& state) {
  for (auto _ : state) {
    state.PauseTiming();
    sim::Manager m;
    m.setThreads(gThreads);
    addDiscs(m.assembly(), 0);
    m.setTimestep(1.0);
    state.ResumeTiming();
    for (int k = 0; k < kDemSteps; ++k) m.step();
  }
  setRate(state, kDemSteps);
}

// Both apart: kLatticeSteps steps of the two together; its cost should be the
// lattice's for those steps plus the elements' (kLatticeSteps of their steps).
void BM_ApartManager(benchmark::State& state) {
  for (auto _ : state) {
    state.PauseTiming();
    sim::Manager m;
    m.setThreads(gThreads);
    m.createLattice(channel());
    addDiscs(m.assembly(), kApart);
    m.step();
    state.ResumeTiming();
    for (int k = 0; k < kLatticeSteps; ++k) m.step();
  }
  setRate(state, kLatticeSteps);
}

// The elements' kLatticeSteps steps after one, bare: the other half of the
// apart scene's sum.
void BM_DemBareShort(benchmark::State& state) {
  for (auto _ : state) {
    state.PauseTiming();
    dem::Assembly a;
    a.setThreads(gThreads);
    addDiscs(a, kApart);
    a.step(1.0, Vec2::Zero());
    state.ResumeTiming();
    for (int k = 0; k < kLatticeSteps; ++k) a.step(1.0, Vec2::Zero());
  }
  setRate(state, kLatticeSteps);
}

// Keeps each case's best wall and CPU time (per iteration) over the
// repetitions. With one thread the CPU time is the steadier on a shared
// machine: time the process waits for a core is not in it.
class BestReporter : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, double> wall, cpu;
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs) {
      if (r.run_type != Run::RT_Iteration || r.iterations == 0) continue;
      const std::string name = r.run_name.function_name;
      keep(wall, name, r.real_accumulated_time / double(r.iterations));
      keep(cpu, name, r.cpu_accumulated_time / double(r.iterations));
    }
    ConsoleReporter::ReportRuns(runs);
  }

 private:
  static void keep(std::map<std::string, double>& best, const std::string& name, double t) {
    auto it = best.find(name);
    if (it == best.end() || t < it->second) best[name] = t;
  }
};

// The summary of one clock's bests; true when the targets are met.
bool summary(const char* clock, const std::map<std::string, double>& best) {
  auto get = [&](const char* name) {
    auto it = best.find(name);
    return it == best.end() ? 0.0 : it->second;
  };
  const double lb = get("BM_LatticeBare"), lm = get("BM_LatticeManager");
  const double db = get("BM_DemBare"), dm = get("BM_DemManager");
  const double ds = get("BM_DemBareShort"), am = get("BM_ApartManager");
  std::fflush(stdout);
  std::cout << std::flush;
  std::printf("%s time, best of the repetitions:\n", clock);
  if (lb > 0 && lm > 0)
    std::printf("  lattice %dx%d, %d thread(s): bare %.3f ms/step, Manager %.3f: %+.2f%%\n",
                kLatticeSize, kLatticeSize, gThreads, lb / kLatticeSteps * 1e3,
                lm / kLatticeSteps * 1e3, (lm / lb - 1) * 100);
  if (db > 0 && dm > 0)
    std::printf("  elements, %d discs: bare %.3f ms/step, Manager %.3f: %+.2f%%\n",
                kDiscsPerSide * kDiscsPerSide, db / kDemSteps * 1e3, dm / kDemSteps * 1e3,
                (dm / db - 1) * 100);
  if (lb > 0 && ds > 0 && am > 0)
    std::printf(
        "  both apart (elements outside the lattice): %.3f ms/step, the bare two together "
        "%.3f: %+.2f%%\n",
        am / kLatticeSteps * 1e3, (lb + ds) / kLatticeSteps * 1e3, (am / (lb + ds) - 1) * 100);
  return lb > 0 && dm > 0 && am > 0 && lm / lb <= 1.02 && dm / db <= 1.02 && am / (lb + ds) <= 1.02;
}

}  // namespace

BENCHMARK(BM_LatticeBare)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_LatticeManager)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_DemBare)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_DemManager)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_DemBareShort)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_ApartManager)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

int main(int argc, char** argv) {
  std::vector<char*> args;
  for (int k = 0; k < argc; ++k) {
    if (!std::strncmp(argv[k], "--threads=", 10))
      gThreads = std::max(1, std::atoi(argv[k] + 10));
    else
      args.push_back(argv[k]);
  }
  int n = int(args.size());
  benchmark::Initialize(&n, args.data());
  BestReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  const bool wallMet = summary("wall", reporter.wall);
  const bool cpuMet = summary("CPU", reporter.cpu);
  std::printf(
      "target Manager within 2%% of the bare kernels, apart within 2%% of the sum: wall %s, CPU "
      "%s\n",
      wallMet ? "MET" : "NOT MET", cpuMet ? "MET" : "NOT MET");
  benchmark::Shutdown();
  return 0;
}
