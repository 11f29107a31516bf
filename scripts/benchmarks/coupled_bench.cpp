// Coupled-step benchmark (issue: coupling): a 1024^2 lattice with moving discs
// covering about 10% of its cells, the step split into its passes, against the
// fluid-only roofline of the same run and against the bare lattice; the same
// at 2048^2, whose lattice streams from memory on any machine; what the
// Manager costs over the bare kernels; and the solid-ratio knob: cost per
// covered cell and the Couette error of each setting.
//
//   sandflow_coupled_bench ?--steps N? ?--threads T? ?--reps R? ?--quick? ?--profile?
//
// --profile runs only the coupled scene with exact solid ratios and prints its
// profile, stage by stage (the Manager's, as `sim info` shows it).
//
// Prints plain tables and the targets' verdicts (scripts/bench --coupled runs
// it). Each time is the best of R repetitions. The bare kernels and the
// Manager step the same lattice or elements in quartets (bare, Manager,
// Manager, bare, or the other way round), and the overhead is the median of
// the quartets' ratios
// (101 quartets of single steps for the fluid, 1001 for the elements), so
// that a noisy neighbour, a drifting machine or state, or where the pages
// fall disturbs both alike. The coupled scene with exact areas runs 4R + 1
// times, each against a copy roofline measured just before it, and its
// verdict is the median share; each repetition's line also gives the speed of
// the slowest core around it (a shared machine's cores at times run far below
// their speed, which slows the step's arithmetic more than the copy), and
// its share of the bare lattice's speed: where the last-level cache holds the
// lattice, the bare lattice beats the memory's roofline and this is the
// stricter measure.
// Lattice units (h = dt = 1).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include "bench_scenes.hpp"
#include "sandflow/sim/manager.hpp"
#include "stream_copy.hpp"

namespace {

using namespace sf;
using Clock = std::chrono::steady_clock;
using bench::channel;

double seconds(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The speed of the slowest of `threads` cores, in billions of dependent
// integer additions a second (about a clock): a shared machine's cores at
// times run far below it, which slows the arithmetic of a step more than a
// copy. Each core's best of three.
double coreSpeed(int threads) {
  constexpr long kAdds = 30'000'000;
  double slowest = 1e300;
#pragma omp parallel num_threads(threads) reduction(min : slowest)
  {
    double best = 1e300;
    for (int r = 0; r < 3; ++r) {
      long x = 0;
      const auto t0 = Clock::now();
      for (long k = 0; k < kAdds; ++k) {
        x += k;
        asm volatile("" : "+r"(x));  // one addition per iteration, kept in order
      }
      best = std::min(best, seconds(t0));
    }
    slowest = std::min(slowest, kAdds / best / 1e9);
  }
  return slowest;
}

int softMaterial(sim::Manager& m) {
  dem::Material mat{"soft"};
  mat.density = 3.0;
  mat.kn = mat.ks = 1e-4;
  mat.friction = 0;
  return m.assembly().materials().add(mat);
}

// Discs of radius 8 covering `fraction` of the lattice; returns how many.
int addDiscs(sim::Manager& m, int n, double fraction, unsigned seed) {
  return bench::scatterDiscs(m, n, fraction, seed, softMaterial(m));
}

struct Split {
  double total = 0, bulk = 0, covered = 0, fill = 0, coverage = 0, forces = 0, dem = 0;
  double measure = 0, sort = 0, cellList = 0;  // parts of coverage
  double mlups = 0;
  std::size_t cells = 0;
  double partial = 0, interior = 0, remeasured = 0;  // cells, per step
};

Split timeSteps(sim::Manager& m, int steps) {
  for (int k = 0; k < 3; ++k) m.step();  // warm up
  const Profile p0 = m.profile();
  double partial = 0, interior = 0, remeasured = 0;
  const auto t0 = Clock::now();
  for (int k = 0; k < steps; ++k) {
    m.step();
    const coupling::Coupler::CellCounts& c = m.coupler().cellCounts();
    partial += double(c.partial), interior += double(c.interior),
        remeasured += double(c.remeasured);
  }
  Split s;
  s.partial = partial / steps, s.interior = interior / steps, s.remeasured = remeasured / steps;
  s.total = seconds(t0) / steps;
  const Profile& p = m.profile();
  auto per = [&](std::initializer_list<Stage> stages) {
    double sum = 0;
    for (Stage x : stages) sum += p.seconds(x) - p0.seconds(x);
    return sum / steps;
  };
  s.bulk = per({Stage::latticeBulk});
  s.covered = per({Stage::latticeCovered});
  s.fill = per({Stage::latticeFill});
  s.measure = per({Stage::coverageMeasure});
  s.sort = per({Stage::coverageSort});
  s.cellList = per({Stage::coverageCells});
  s.coverage = s.measure + s.sort + s.cellList;
  s.forces = per({Stage::fluidForces});
  s.dem = per({Stage::demPairs, Stage::demContacts, Stage::demSums, Stage::demIntegrate});
  s.mlups = double(m.lattice().nodes()) / s.total / 1e6;
  s.cells = m.coupler().coveredCells();
  return s;
}

// The profile of `steps` steps after a warm-up, stage by stage (--profile).
void printProfile(sim::Manager& m, int steps) {
  for (int k = 0; k < 3; ++k) m.step();  // warm up
  m.profile().reset();
  const auto t0 = Clock::now();
  for (int k = 0; k < steps; ++k) m.step();
  const double wall = seconds(t0);
  const Profile& p = m.profile();
  std::printf("%-16s %10s %7s %7s\n", "stage", "ms/step", "steps", "share");
  for (int k = 0; k < kStageCount; ++k) {
    const StageTime& t = p[Stage(k)];
    if (t.steps == 0) continue;
    std::printf("%-16s %10.3f %7lld %6.1f%%\n", std::string(stageName(Stage(k))).c_str(),
                t.seconds / steps * 1e3, t.steps, t.seconds / wall * 100);
  }
  const double rest = wall - p.totalSeconds();
  std::printf("%-16s %10.3f %7d %6.1f%%\n", "(Manager's own)", rest / steps * 1e3, steps,
              rest / wall * 100);
  std::printf("%-16s %10.3f %7d %6.1f%%\n", "step", wall / steps * 1e3, steps, 100.0);
  const coupling::Coupler::CellCounts& c = m.coupler().cellCounts();
  std::printf("covered cells of the last step: %zu (partial %zu, interior %zu); remeasured %zu\n",
              m.coupler().coveredCells(), c.partial, c.interior, c.remeasured);
}

// Cylindrical Couette (thesis case B) at 80 cells across, one solid-ratio
// setting: relative L2 velocity error and torque error.
std::pair<double, double> couette(int subcells) {
  const double r1 = 0.1, r2 = 0.3, om = 0.1, nu = 4.166e-2;
  sim::Manager m;
  coupling::Settings s;
  s.subcells = subcells;
  m.setCouplingSettings(s);
  lb::LatticeDef def;
  def.size = Vec2(1, 1);
  def.cells = 80;
  def.viscosity = nu;
  for (auto& side : def.sides) side = lb::SideDef{lb::SideKind::periodic};
  m.createLattice(def);
  lb::Lattice& l = m.lattice();
  const int inner = l.addCircle({-1, Vec2(0.5, 0.5), r1, false, Vec2::Zero(), 0});
  l.addCircle({-1, Vec2(0.5, 0.5), r2, true, Vec2::Zero(), om});
  const long steps = std::lround(2.5 / l.params().dt);
  for (long k = 0; k < steps; ++k) m.step();
  const double A = om * r2 * r2 / (r2 * r2 - r1 * r1),
               B = -om * r1 * r1 * r2 * r2 / (r2 * r2 - r1 * r1);
  double err = 0, norm = 0;
  for (int j = 0; j < l.ny(); ++j)
    for (int i = 0; i < l.nx(); ++i) {
      const Vec2 d = l.position(i, j) - Vec2(0.5, 0.5);
      const double r = d.norm();
      if (l.solidRatio(i, j) > 0 || r <= r1 || r >= r2) continue;
      const Vec2 exact = (A * r + B / r) * Vec2(-d.y(), d.x()) / r;
      err += (l.velocity(i, j) - exact).squaredNorm();
      norm += exact.squaredNorm();
    }
  const double T = 4 * std::numbers::pi * nu * om * r1 * r1 * r2 * r2 / (r2 * r2 - r1 * r1);
  return {std::sqrt(err / norm), std::abs(l.obstacleInfo(inner).torque - T) / T};
}

// The dense scene of issue 36 (after Yade's 2D coupling example): a closed
// 250 x 180 box, 70 discs 8 to 12 cells in radius covering about half the
// cells, at rest, settling under gravity. Lattice units.
void denseScene(sim::Manager& m, bool discs) {
  lb::LatticeDef def;
  def.size = Vec2(250, 180);
  def.cells = 250;
  def.tau = 0.8;
  def.timestep = 1.0;
  for (auto& side : def.sides) side = lb::SideDef{lb::SideKind::noslip};
  m.createLattice(def);
  if (!discs) return;
  dem::Material mat{"grain"};
  mat.density = 3.0;
  mat.kn = mat.ks = 20;
  mat.friction = 0.3;
  const int material = m.assembly().materials().add(mat);
  m.setGravity(Vec2(0, -2e-5));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 70; ++k) {
    const double pitchX = 25, pitchY = 180.0 / 7, r = 8 + 4 * u(rng);
    const double room = std::max(0.0, 0.5 * pitchY - r - 0.5);
    dem::ElementDef d;
    d.shape = std::make_unique<dem::Disc>(r);
    d.material = material;
    d.x = Vec2((k % 10 + 0.5) * pitchX + room * (2 * u(rng) - 1),
               (k / 10 + 0.5) * pitchY + room * (2 * u(rng) - 1));
    m.assembly().add(std::move(d));
  }
}

// What one covered cell of each kind costs the lattice step: the same
// lattice stepped with none, with only the partial and with only the interior
// cells of `cells` covered; the best of `reps` rounds of `steps` steps each.
struct CellCost {
  double bare = 0, partial = 0, interior = 0;  // ms/step, ns/cell, ns/cell
};
CellCost coveredCellCost(lb::Lattice& lattice, const std::vector<lb::CoveredCell>& cells, int steps,
                         int reps) {
  std::vector<lb::CoveredCell> partial, interior;
  for (const lb::CoveredCell& c : cells) (c.eps < 1 ? partial : interior).push_back(c);
  // Interior by the list's flags: cells with eps = 1 not flagged interior
  // (a solid's outline) count as partial work (the full operator).
  std::vector<lb::CoveredCell> full;
  for (const lb::CoveredCell& c : interior) (c.interior ? full : partial).push_back(c);
  const std::vector<lb::CoveredCell>* lists[] = {nullptr, &partial, &full};
  double best[3] = {1e300, 1e300, 1e300};
  for (int r = 0; r < reps; ++r)
    for (int k = 0; k < 3; ++k) {
      lattice.setCoveredCells(lists[k] ? *lists[k] : std::vector<lb::CoveredCell>{}, true);
      lattice.step();
      const auto t0 = Clock::now();
      for (int q = 0; q < steps; ++q) lattice.step();
      best[k] = std::min(best[k], seconds(t0) / steps);
    }
  lattice.setCoveredCells({}, true);
  return {best[0] * 1e3, (best[1] - best[0]) / std::max<std::size_t>(1, partial.size()) * 1e9,
          (best[2] - best[0]) / std::max<std::size_t>(1, full.size()) * 1e9};
}

// The dense scene: the coupled step against the same lattice bare, each pair
// in turn (the bare lattice first in even rounds), on 1 and 2 threads; the
// coupled step's split per step, and what a covered cell of each kind costs.
void denseBench(int reps, int steps) {
  std::printf(
      "dense: 250x180 closed box, 70 discs of radius 8-12 cells covering about half the "
      "cells, settling; best of %d rounds of %d steps\n",
      reps, steps);
  std::printf("%-8s %8s %8s %6s %7s %7s %8s %8s %8s %8s %8s %8s %8s %9s %9s %9s\n", "threads",
              "bare", "coupled", "ratio", "MLUPS", "bareML", "bulk", "covered", "fill", "measure",
              "sort", "list", "forces", "partial", "interior", "remeasur");
  double oneThread = 0;
  for (int threads : {1, 2}) {
    sim::Manager bareM, coupledM;
    bareM.setThreads(threads), coupledM.setThreads(threads);
    denseScene(bareM, false);
    denseScene(coupledM, true);
    for (int k = 0; k < 200; ++k) coupledM.step();  // the grains start to fall
    Split best, bare;
    std::vector<double> ratios;
    for (int r = 0; r < reps; ++r) {
      Split b, c;
      if (r % 2 == 0)
        b = timeSteps(bareM, steps), c = timeSteps(coupledM, steps);
      else
        c = timeSteps(coupledM, steps), b = timeSteps(bareM, steps);
      if (r == 0 || c.total < best.total) best = c;
      if (r == 0 || b.total < bare.total) bare = b;
      ratios.push_back(b.total / c.total);
    }
    std::sort(ratios.begin(), ratios.end());
    const double nodes = 250.0 * 180.0;
    std::printf(
        "%-8d %8.3f %8.3f %6.2f %7.1f %7.1f %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %9.0f %9.0f "
        "%9.0f\n",
        threads, bare.total * 1e3, best.total * 1e3, ratios[ratios.size() / 2],
        nodes / best.total / 1e6, nodes / bare.total / 1e6, best.bulk * 1e3, best.covered * 1e3,
        best.fill * 1e3, best.measure * 1e3, best.sort * 1e3, best.cellList * 1e3,
        best.forces * 1e3, best.partial, best.interior, best.remeasured);
    if (threads == 1)
      oneThread = best.total;
    else
      std::printf("  2 threads: %.2fx the one-thread coupled step (target >= 1.6)\n",
                  oneThread / best.total);
    if (threads == 1) {
      const CellCost cost =
          coveredCellCost(bareM.lattice(), coupledM.lattice().coveredCells(), steps, reps);
      std::printf(
          "  a covered cell's cost in the lattice step, 1 thread: partial %.1f ns, interior %.1f "
          "ns; a bulk node %.2f ns\n",
          cost.partial, cost.interior, cost.bare * 1e6 / nodes);
    }
  }
  std::printf(
      "  (ratio: median over the rounds of bare / coupled step time, the same lattice; target "
      ">= 0.60 on 1 thread)\n\n");
}

}  // namespace

// One Manager step, timed: its wall time, also added to `wall`, and the part
// of it inside the kernels added to `inside` (the rest is the Manager's own code).
double timedManagerStep(sim::Manager& m, double& wall, double& inside) {
  const double before = m.profile().totalSeconds();
  const auto t0 = Clock::now();
  m.step();
  const double t = seconds(t0);
  wall += t, inside += m.profile().totalSeconds() - before;
  return t;
}

// The Manager's cost over a bare kernel: the two timed in quartets, A B B A
// or B A A B, each giving one ratio (the Manager's two times over the bare
// kernel's two), so that a state or a machine that drifts steadily cancels
// out; the median of those ratios. Which one goes first is drawn for each
// quartet: with a fixed A B B A, work that recurs every few steps (the
// elements' contact upkeep) fell on the same places and gave a bare assembly
// timed against itself +2%. Also the best time of each. `quartets` of them.
struct Overhead {
  double bare = 1e300, managed = 1e300, percent = 0;
};
template <class Bare, class Managed>
Overhead overhead(Bare runBare, Managed runManaged, int quartets) {
  Overhead o;
  std::vector<double> ratios;
  std::mt19937 rng(7);  // which of the two goes first, quartet by quartet
  for (int q = 0; q < quartets; ++q) {
    double b1, m1, m2, b2;
    if (rng() & 1) {
      b1 = runBare(), m1 = runManaged(), m2 = runManaged(), b2 = runBare();
    } else {
      m1 = runManaged(), b1 = runBare(), b2 = runBare(), m2 = runManaged();
    }
    o.bare = std::min({o.bare, b1, b2}), o.managed = std::min({o.managed, m1, m2});
    ratios.push_back((m1 + m2) / (b1 + b2));
  }
  std::sort(ratios.begin(), ratios.end());
  const std::size_t h = ratios.size() / 2;
  const double median = ratios.size() % 2 ? ratios[h] : 0.5 * (ratios[h - 1] + ratios[h]);
  o.percent = (median - 1) * 100;
  return o;
}

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // a line at a time, also into a file
  int steps = 40, threads = 2, reps = 3;
  bool quick = false, profile = false, dense = false;
  for (int k = 1; k < argc; ++k) {
    if (!std::strcmp(argv[k], "--steps") && k + 1 < argc)
      steps = std::atoi(argv[++k]);
    else if (!std::strcmp(argv[k], "--threads") && k + 1 < argc)
      threads = std::atoi(argv[++k]);
    else if (!std::strcmp(argv[k], "--reps") && k + 1 < argc)
      reps = std::max(1, std::atoi(argv[++k]));
    else if (!std::strcmp(argv[k], "--quick"))
      quick = true;
    else if (!std::strcmp(argv[k], "--profile"))
      profile = true;
    else if (!std::strcmp(argv[k], "--dense"))
      dense = true;
    else {
      std::fprintf(
          stderr,
          "usage: %s ?--steps N? ?--threads T? ?--reps R? ?--quick? ?--profile? ?--dense?\n",
          argv[0]);
      return 2;
    }
  }
  const int n = 1024;
  if (dense) {
    denseBench(reps, steps);
    return 0;
  }
  if (profile) {
    sim::Manager m;
    m.setThreads(threads);
    m.createLattice(channel(n));
    const int discs = addDiscs(m, n, 0.10, 11);
    std::printf(
        "coupled: %dx%d lattice, %d discs of radius 8 covering ~10%%, %d threads, %d steps\n", n, n,
        discs, threads, steps);
    printProfile(m, steps);
    return 0;
  }
  denseBench(2 * reps + 1, 5 * steps);
  bench::measureBandwidth(512, 6, {threads});
  const double roof = bench::bandwidth[threads].copy * 1000 / 144.0;
  const long lastLevelCache = sysconf(_SC_LEVEL3_CACHE_SIZE);
  std::printf("copy bandwidth %.2f GB/s with %d threads -> fluid roofline %.1f MLUPS\n",
              bench::bandwidth[threads].copy, threads, roof);
  std::printf(
      "(last-level cache %s; the lattice's populations %.0f MiB)\n\n",
      lastLevelCache > 0 ? (std::to_string(lastLevelCache >> 20) + " MiB").c_str() : "unknown",
      double(n) * n * 2 * 9 * sizeof(double) / (1 << 20));

  // 1. Fluid only: one lattice, stepped bare and through the Manager in
  //    turn (one object, so that where its pages fall does not differ).
  // Also the Manager's own code alone: its steps' wall time less the time it
  // spends inside the kernels (its profile), which does not depend on the noise.
  double bare = 1e300, managed = 1e300, fluidOverhead = 0, managerWall = 0, managerInside = 0;
  const int fluidQuartets = quick ? 11 : 101;
  {
    sim::Manager m;
    m.setThreads(threads);
    m.createLattice(channel(n));
    lb::Lattice& lattice = m.lattice();
    for (int k = 0; k < 3; ++k) lattice.step();
    // Quartets of single steps: the machine's speed drifts over seconds.
    const Overhead o = overhead(
        [&] {
          const auto t0 = Clock::now();
          lattice.step();
          return seconds(t0);
        },
        [&] { return timedManagerStep(m, managerWall, managerInside); }, fluidQuartets);
    bare = o.bare, managed = o.managed, fluidOverhead = o.percent;
  }
  const double fluidOwn = (managerWall - managerInside) / managerWall * 100;
  std::printf(
      "fluid only, %dx%d, %d threads, %d quartets of single steps: bare lattice %.2f ms/step "
      "(%.1f MLUPS, %.1f%% of roofline), through the Manager %.2f ms/step (best of each; median of "
      "the quartets' ratios %+.2f%%; its own code %.3f%% of the step)\n",
      n, n, threads, fluidQuartets, bare * 1e3, n * n / bare / 1e6, n * n / bare / 1e6 / roof * 100,
      managed * 1e3, fluidOverhead, fluidOwn);

  // 2. Elements only: the bare assembly and the same through the Manager. The
  //    discs spread and collide, so the state each one meets changes: single
  //    steps, compared in quartets.
  double elementOverhead = 0, elementOwn = 0;
  {
    auto build = [](dem::Assembly& a) {
      std::mt19937 rng(3);
      std::uniform_real_distribution<double> u(-1, 1);
      for (int k = 0; k < 10000; ++k) {
        dem::ElementDef d;
        d.shape = std::make_unique<dem::Disc>(0.5e-3 + 0.25e-3 * (1 + u(rng)));
        d.x = Vec2((k % 100) * 2.1e-3, (k / 100) * 2.1e-3);
        d.v = 0.05 * Vec2(u(rng), u(rng));
        a.add(std::move(d));
      }
    };
    sim::Manager m;
    m.setThreads(threads);
    build(m.assembly());
    dem::Assembly& a = m.assembly();  // the same elements, bare and through the Manager
    const double dt = m.timestep();
    const int quartets = quick ? 101 : 1001;
    double wall = 0, within = 0;
    const Overhead o = overhead(
        [&] {
          const auto t0 = Clock::now();
          a.step(dt, Vec2::Zero());
          return seconds(t0);
        },
        [&] { return timedManagerStep(m, wall, within); }, quartets);
    elementOverhead = o.percent, elementOwn = (wall - within) / wall * 100;
    std::printf(
        "elements only, 10000 discs, %d quartets of single steps: bare assembly %.3f ms/step, "
        "through the Manager %.3f ms/step (best of each; median of the quartets' ratios %+.2f%%; "
        "its own code %.3f%% of the step)\n\n",
        quartets, o.bare * 1e3, o.managed * 1e3, elementOverhead, elementOwn);
  }

  // 3. The coupled scene, and 4. each solid-ratio setting on it.
  std::printf("coupled: %dx%d lattice, discs of radius 8 cells covering ~10%%, moving; ms/step\n",
              n, n);
  std::printf("%-10s %6s %8s %8s %8s %8s %8s %8s %8s %8s %7s %8s %8s\n", "solidratio", "discs",
              "cells", "total", "bulk", "covered", "fill", "ratio", "forces", "DEM", "MLUPS",
              "% roof", "ns/cell");
  Split exactSplit;
  const int exactRepetitions = 4 * reps + 1;
  struct Rep {
    double copy, core, step, share;  // GB/s, slower core speed around it, ms/step, % of roofline
    double ofBare;                   // % of the bare lattice's MLUPS (section 1)
  };
  const double bareMlups = n * n / bare / 1e6;
  std::vector<Rep> exactReps;
  const int settings[] = {coupling::kExact, 1, 2, 4, 8};
  const char* names[] = {"exact", "1", "2", "4", "8"};
  for (int k = 0; k < 5; ++k) {
    if (quick && k > 0 && k < 4) continue;
    sim::Manager m;
    m.setThreads(threads);
    m.createLattice(channel(n));
    coupling::Settings s;
    s.subcells = settings[k];
    m.setCouplingSettings(s);
    const int discs = addDiscs(m, n, 0.10, 11);
    Split t;
    // Exact areas (the target's case): each repetition against a roofline
    // measured just before it, and the core speed before and after it.
    for (int r = 0; r < (k == 0 ? exactRepetitions : reps); ++r) {
      const double core = k == 0 ? coreSpeed(threads) : 0;
      if (k == 0) bench::measureBandwidth(512, 3, {threads});
      const Split x = timeSteps(m, steps);
      if (r == 0 || x.total < t.total) t = x;
      if (k == 0) {
        const double copy = bench::bandwidth[threads].copy;
        exactReps.push_back({copy, std::min(core, coreSpeed(threads)), x.total * 1e3,
                             x.mlups / (copy * 1000 / 144.0) * 100, x.mlups / bareMlups * 100});
      }
    }
    if (k == 0) exactSplit = t;
    std::printf("%-10s %6d %8zu %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f %7.1f %7.1f%% %8.1f\n",
                names[k], discs, t.cells, t.total * 1e3, t.bulk * 1e3, t.covered * 1e3,
                t.fill * 1e3, t.coverage * 1e3, t.forces * 1e3, t.dem * 1e3, t.mlups,
                t.mlups / roof * 100, t.coverage / double(t.cells) * 1e9);
  }
  std::printf(
      "\n(best of the repetitions; %% roof: against the roofline at the top. ns/cell: the "
      "solid-ratio pass per\ncovered cell, every disc measured again each step)\n");
  // Each repetition, the verdict from the median of all. A shared machine's
  // cores at times run far below their speed (other load), which slows the
  // step's arithmetic but hardly the copy: the median of the repetitions whose
  // cores ran, before and after, within 10% of the fastest seen shows how much.
  double fastestCore = 0;
  for (const Rep& x : exactReps) fastestCore = std::max(fastestCore, x.core);
  std::vector<double> all, atSpeed, ofBare;
  std::printf("exact, each of %d repetitions against a roofline measured just before it:\n",
              exactRepetitions);
  for (std::size_t r = 0; r < exactReps.size(); ++r) {
    const Rep& x = exactReps[r];
    const bool full = x.core >= 0.9 * fastestCore;
    all.push_back(x.share);
    ofBare.push_back(x.ofBare);
    if (full) atSpeed.push_back(x.share);
    std::printf(
        "  repetition %2zu: copy %5.2f GB/s, cores %.2f G additions/s, %6.2f ms/step, %5.1f%% "
        "(%4.1f%% of the bare lattice)%s\n",
        r + 1, x.copy, x.core, x.step, x.share, x.ofBare, full ? "" : " (cores slow)");
  }
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t h = v.size() / 2;
    return v.empty() ? 0.0 : v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
  };
  const double exactShare = median(all), fullShare = median(atSpeed), bareShare = median(ofBare);
  std::printf(
      "  median %.1f%% of the roofline; %.1f%% over the %zu repetitions at full core speed\n",
      exactShare, fullShare, atSpeed.size());
  std::printf(
      "  median %.1f%% of the bare lattice's speed above (%.1f MLUPS, %.1f%% of the roofline%s)\n",
      bareShare, bareMlups, bareMlups / roof * 100,
      bareMlups > roof ? ": above it, the copy does not bound the lattice on this machine" : "");
  std::printf(
      "solid-ratio pass, exact: measure %.2f (cells and ratios of each disc), sort %.2f (in node "
      "order), cell list %.2f (with solid velocities) ms/step\n\n",
      exactSplit.measure * 1e3, exactSplit.sort * 1e3, exactSplit.cellList * 1e3);

  // 5. The same scene on a lattice four times the size (and four times the
  //    discs), bare and coupled in turn, each pair against a copy roofline
  //    measured just before it. Its 576 MiB of populations stream from memory
  //    on any machine of today, as the roofline supposes; at 1024^2 a large
  //    last-level cache may hold much of the bare lattice, and the coupled
  //    scene's own arrays (about 16 MB) push part of it out again.
  const int big = 2 * n;
  double bigBare = 1e300;
  Split bigSplit;
  std::vector<double> bigOfBare, bigShare;
  {
    sim::Manager bareM, coupledM;
    bareM.setThreads(threads), coupledM.setThreads(threads);
    bareM.createLattice(channel(big));
    coupledM.createLattice(channel(big));
    const int discs = addDiscs(coupledM, big, 0.10, 11);
    const int bigSteps = std::max(4, steps / 4);
    for (int r = 0; r < 2 * reps + 1; ++r) {
      bench::measureBandwidth(512, 3, {threads});
      const double bareStep = timeSteps(bareM, bigSteps).total;
      const Split x = timeSteps(coupledM, bigSteps);
      if (r == 0 || x.total < bigSplit.total) bigSplit = x;
      bigBare = std::min(bigBare, bareStep);
      bigOfBare.push_back(bareStep / x.total * 100);
      bigShare.push_back(x.mlups / (bench::bandwidth[threads].copy * 1000 / 144.0) * 100);
    }
    std::printf(
        "the same at %dx%d (%.0f MiB of populations), %d discs, %d pairs of %d steps, bare and "
        "coupled in turn:\n  bare lattice %.2f ms/step (%.1f MLUPS); coupled %.2f ms/step (bulk "
        "%.2f, covered %.2f, ratio %.2f, forces %.2f); best of each\n  median of the pairs: "
        "%.1f%% of the bare lattice's speed, %.1f%% of the roofline measured before each\n\n",
        big, big, double(big) * big * 2 * 9 * sizeof(double) / (1 << 20), discs, 2 * reps + 1,
        bigSteps, bigBare * 1e3, double(big) * big / bigBare / 1e6, bigSplit.total * 1e3,
        bigSplit.bulk * 1e3, bigSplit.covered * 1e3, bigSplit.coverage * 1e3, bigSplit.forces * 1e3,
        median(bigOfBare), median(bigShare));
  }

  std::printf("Couette (case B, 80 cells across, steady): error of each solid-ratio setting\n");
  std::printf("%-10s %12s %12s\n", "solidratio", "velocity L2", "torque");
  for (int k = 0; k < 5; ++k) {
    if (quick && k > 0 && k < 4) continue;
    const auto [ev, et] = couette(settings[k]);
    std::printf("%-10s %12.3e %12.3e\n", names[k], ev, et);
  }
  std::printf(
      "\ntarget >= 60%% of the fluid-only roofline, coupled scene, exact solid ratio: %s "
      "(%.1f%%, the median above; %.1f%% of the bare lattice's speed; at %dx%d, %.1f%% of the "
      "roofline and %.1f%% of the bare lattice's speed)\n",
      exactShare >= 60 ? "MET" : "NOT MET", exactShare, bareShare, big, big, median(bigShare),
      median(bigOfBare));
  std::printf(
      "target Manager within 2%% of the bare kernels: %s (fluid only %+.2f%%, elements only "
      "%+.2f%%; the Manager's own code %.3f%% and %.3f%% of a step)\n",
      fluidOverhead <= 2 && elementOverhead <= 2 ? "MET" : "NOT MET", fluidOverhead,
      elementOverhead, fluidOwn, elementOwn);
  return 0;
}
