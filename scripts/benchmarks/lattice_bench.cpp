// Lattice benchmark (design.md "Performance and accuracy are measured"):
// fluid-only lattice-Boltzmann steps next to the machine's memory-bandwidth
// roofline.
//
// Before the benchmarks run, a STREAM-style copy (two arrays of doubles far larger
// than the last-level cache, OpenMP over 1 and 2 threads, best of several
// repetitions, 16 bytes counted per element as STREAM does) measures the copy
// bandwidth. A D2Q9 double-precision node update moves 144 bytes (9 reads + 9
// writes of 8 bytes), so a copy of B GB/s gives a roofline of
//   MLUPS_max = B * 1000 / 144,
// and every lattice benchmark reports its MLUPS as a percentage of the roofline of
// its own thread count.
//
// Two copies are timed:
//   copy-nt non-temporal (streaming) stores that skip the write-allocate read: the
//           raw bandwidth of the memory system. The lattice streams in place
//           (each step reads and writes the same lines, none read for
//           ownership), so this is the roofline it is measured against;
//   copy    plain loads and stores, as a C loop compiles; a store to a line not in
//           cache first reads it (write-allocate), as the two-array step's did:
//           a step above it shows what streaming in place saves.
// scripts/bench runs the AA-pattern yardstick (shared/peers/aa-probe) on the
// same sizes and gives each case's share of it.
//
// Counters per lattice benchmark (real time; --benchmark_out JSON has them all):
//   MLUPS         fluid node updates per second / 1e6
//   B/node        Lattice::memoryBytes() / Lattice::nodes()
//   roofline      MLUPS_max of this thread count (copy-nt)
//   pct_roofline  MLUPS / roofline * 100
//   pct_copy      MLUPS / MLUPS_max(copy) * 100
//   links         wall and periodic links filled per step
//
// Extra flags (before Google Benchmark's own):
//   --copy_mb=N       size of each copy array in MiB (default 512)
//   --copy_reps=N     repetitions of each copy, best taken (default 10)
//   --node_updates=N  node updates per timed run, sets the fixed iteration count
//                     of each lattice benchmark (default 3e8)
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "sandflow/lb/lattice.hpp"
#include "sandflow/lb/node.hpp"
#include "stream_copy.hpp"

namespace {

using namespace sf;

constexpr double bytesPerUpdate = 144.0;  // D2Q9, double: 9 reads + 9 writes of 8 bytes

using bench::Bandwidth;
using bench::bandwidth;
using bench::measureBandwidth;

// ---- lattice -----------------------------------------------------------------

struct Case {
  int nx, ny, threads;
  lb::Collision collision = lb::Collision::bgk;
  lb::ForceScheme force = lb::ForceScheme::nodal;
  bool walls = false;  // no-slip bottom/top and four square obstacles, else fully periodic

  std::string name() const {
    std::string s = "lattice/";
    s += collision == lb::Collision::bgk ? "bgk" : "trt";
    s += force == lb::ForceScheme::nodal ? "-nodal" : "-guo";
    s += walls ? "/walls+obstacles/" : "/periodic/";
    s += std::to_string(nx) + "x" + std::to_string(ny) + "/omp:" + std::to_string(threads);
    return s;
  }
  std::string latticeKey() const {  // what the cached lattice depends on
    return std::to_string(nx) + "x" + std::to_string(ny) + (walls ? "w" : "p") +
           std::to_string(int(collision)) + std::to_string(int(force));
  }
};

std::unique_ptr<lb::Lattice> build(const Case& c) {
  lb::LatticeDef def;
  def.size = Vec2(c.nx, c.ny);
  def.cells = c.nx;  // h = 1
  def.tau = 0.8;
  def.timestep = 1.0;  // dt = 1: lattice units throughout
  def.forcing = Vec2(1e-7, 0.0);
  def.collision = c.collision;
  def.forceScheme = c.force;
  const lb::SideKind ends = c.walls ? lb::SideKind::noslip : lb::SideKind::periodic;
  def.sides = {lb::SideDef{lb::SideKind::periodic}, lb::SideDef{lb::SideKind::periodic},
               lb::SideDef{ends}, lb::SideDef{ends}};
  auto lattice = std::make_unique<lb::Lattice>(lb::resolve(def));
  if (c.walls)  // squares of side ny/16 across the channel
    for (int k = 0; k < 4; ++k) {
      lb::RectObstacle r;
      r.id = -1;
      const double half = c.ny / 32.0, x = c.nx * (k + 0.5) / 4, y = c.ny * (k % 2 ? 0.3 : 0.6);
      r.lo = Vec2(x - half, y - half);
      r.hi = Vec2(x + half, y + half);
      lattice->addObstacle(r);
    }
  // A gentle shear wave so the collision works on non-trivial data.
  const double ly = c.ny;
  lattice->initialize([ly](const Vec2& x, double&, Vec2& u) {
    u = Vec2(0.01 * std::sin(2 * std::numbers::pi * x.y() / ly), 0.0);
  });
  return lattice;
}

// The lattice of the last case, reused by its repetitions (building a 4096 x 2048
// lattice takes longer than timing it).
std::string cachedKey;
std::unique_ptr<lb::Lattice> cached;

long long nodeUpdatesPerRun = 300'000'000;

void runCase(benchmark::State& state, Case c) {
  if (cachedKey != c.latticeKey()) {
    cached.reset();
    cached = build(c);
    cachedKey = c.latticeKey();
  }
  lb::Lattice& lattice = *cached;
  lattice.setThreads(c.threads);

  std::size_t fluid = 0, links = 0;
  for (const auto& k : lattice.kinds()) {
    if (dynamic_cast<const lb::FluidNode*>(k.get())) fluid += k->count();
    if (dynamic_cast<const lb::LinkNode*>(k.get())) links += k->count();
  }
  for (int k = 0; k < 3; ++k) lattice.step();  // warm up caches and threads

  for (auto _ : state) {
    const lb::StepStats s = lattice.step();
    benchmark::DoNotOptimize(s);
  }

  const double updates = double(fluid) * state.iterations() / 1e6;  // millions
  const Bandwidth bw = bandwidth.count(c.threads) ? bandwidth[c.threads] : Bandwidth{};
  const double roof = bw.copyNt * 1000.0 / bytesPerUpdate;
  const double roofCopy = bw.copy * 1000.0 / bytesPerUpdate;
  state.counters["MLUPS"] = benchmark::Counter(updates, benchmark::Counter::kIsRate);
  state.counters["B/node"] = double(lattice.memoryBytes()) / double(lattice.nodes());
  state.counters["roofline"] = roof;
  if (roof > 0)
    state.counters["pct_roofline"] =
        benchmark::Counter(updates * 100.0 / roof, benchmark::Counter::kIsRate);
  if (roofCopy > 0)
    state.counters["pct_copy"] =
        benchmark::Counter(updates * 100.0 / roofCopy, benchmark::Counter::kIsRate);
  state.counters["links"] = double(links);
  state.counters["nodes"] = double(fluid);
}

void registerCase(const Case& c) {
  const double nodes = double(c.nx) * c.ny;
  const auto iterations =
      static_cast<benchmark::IterationCount>(std::clamp(nodeUpdatesPerRun / nodes, 10.0, 20000.0));
  benchmark::RegisterBenchmark(c.name().c_str(), runCase, c)
      ->Iterations(iterations)
      ->UseRealTime()
      ->Unit(benchmark::kMillisecond);
}

bool takeFlag(const char* arg, const char* name, double& value) {
  const std::size_t n = std::strlen(name);
  if (std::strncmp(arg, name, n) != 0 || arg[n] != '=') return false;
  value = std::atof(arg + n + 1);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  double copyMb = 512, copyReps = 10, updates = double(nodeUpdatesPerRun);
  std::vector<char*> rest;
  for (int k = 0; k < argc; ++k) {
    if (k > 0 &&
        (takeFlag(argv[k], "--copy_mb", copyMb) || takeFlag(argv[k], "--copy_reps", copyReps) ||
         takeFlag(argv[k], "--node_updates", updates)))
      continue;
    rest.push_back(argv[k]);
  }
  nodeUpdatesPerRun = static_cast<long long>(updates);
  int restCount = static_cast<int>(rest.size());
  benchmark::Initialize(&restCount, rest.data());
  if (benchmark::ReportUnrecognizedArguments(restCount, rest.data())) return 1;

  const std::vector<int> threadCounts = {1, 2};
  measureBandwidth(static_cast<std::size_t>(copyMb), std::max(1, int(copyReps)), threadCounts);
  char text[64];
  std::snprintf(text, sizeof text, "%.0f", copyMb);
  benchmark::AddCustomContext("copy_array_MiB", text);
  benchmark::AddCustomContext("copy_reps", std::to_string(std::max(1, int(copyReps))));
  for (int t : threadCounts) {
    const Bandwidth& b = bandwidth[t];
    std::snprintf(text, sizeof text, "%.2f", b.copy);
    benchmark::AddCustomContext("copy_GBps_" + std::to_string(t), text);
    std::snprintf(text, sizeof text, "%.2f", b.copyNt);
    benchmark::AddCustomContext("copy_nt_GBps_" + std::to_string(t), text);
    std::fprintf(stderr,
                 "copy %d thread(s): %.2f GB/s (roofline %.1f MLUPS); non-temporal %.2f GB/s "
                 "(%.1f MLUPS)\n",
                 t, b.copy, b.copy * 1000 / bytesPerUpdate, b.copyNt,
                 b.copyNt * 1000 / bytesPerUpdate);
  }

  // BGK, nodal forcing (the default), fully periodic: sizes x threads.
  const int sizes[][2] = {{256, 256}, {1024, 1024}, {2048, 2048}, {4096, 2048}, {4096, 4096}};
  for (const auto& s : sizes)
    for (int t : threadCounts) registerCase({s[0], s[1], t});
  // What each accuracy knob and the link nodes cost, at 4096^2 (far beyond any
  // last-level cache) with 2 threads.
  registerCase({4096, 4096, 2, lb::Collision::trt, lb::ForceScheme::nodal});
  registerCase({4096, 4096, 2, lb::Collision::bgk, lb::ForceScheme::guo});
  registerCase({4096, 4096, 2, lb::Collision::trt, lb::ForceScheme::guo});
  registerCase({4096, 4096, 2, lb::Collision::bgk, lb::ForceScheme::nodal, true});

  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
