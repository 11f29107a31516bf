// The DEM benchmark bed of shared/reference/dem-bed.md: N discs, radii uniform
// in [0.5, 1] mm, settled under gravity in a box open at the top, then timed.
// Prints, per thread count, particle-steps per second of the timed phase,
// contacts per disc, the kinetic energy at its end and the time per step by
// stage.
//
//   sandflow_dem_bed N ?settle? ?timed? ?threads? ?options?
//
//   threads           a list, e.g. 1,2: the settle runs once (with the most
//                     threads; the step is deterministic, so the state does
//                     not depend on it), then each count is timed in turn,
//                     each from the settled state (kept with saveState): every
//                     count times the same steps (timing them one after the
//                     other had the second count time a later, denser stretch
//                     of a bed still falling: more pairs, more builds)
//   --reps R          time the phase R times per thread count (each from the
//                     settled state) and report the best; contacts per disc
//                     and kinetic energy are those of the first repetition
//                     (steps settle+1..settle+timed, as dem-bed.md defines)
//   --reference       time the slow reference step (Assembly::referenceStep:
//                     the step's sums and integration as they were before
//                     issue 38) beside the step, in alternate repetitions:
//                     lines with step=reference
//   --settled FILE    not the benchmark's timing of the settle: load the
//                     settled bed from FILE (an assembly's saveState) when it
//                     exists, else settle and write it there (settle_s=0 and
//                     no deepest overlap when loaded)
//   --bonded G        after the settle, bond every pair of elements closer
//                     than G metres (bondAll; the material's bond stiffness
//                     and strength): a cemented bed, timed like the loose one
//   --trace K         print the kinetic energy and more every K steps of the settle
//   --fine S K        ... and every K steps after step S (to resolve the bed's
//                     vertical oscillation, tens of ms, without printing all of it)
//   --diagnose        where the kinetic energy sits at the end of the settle
//   --beside FILE     for timing beside another code on the other core: the
//                     settle and the 1-thread phase run on CPU 0 alone; then
//                     the 1-thread phase is repeated, one line "beside
//                     start=<unix s> end=<unix s> psps=<x>" each, until FILE
//                     exists; then the other thread counts, on every CPU
//   --lammps-data F   after the settle, write the settled bed as a LAMMPS data
//                     file F (atom_style sphere, with velocities and spins),
//                     for LAMMPS to time the same bed without its own settle;
//                     with --beside the settle runs on every CPU, the pinning
//                     to CPU 0 starts once F is written, and the stamped
//                     1-thread phases come before the repetitions (the other
//                     code's run is short)
//   --restitution E   not the benchmark: another restitution (default 0.5) or
//   --friction M      friction coefficient (default 0.5), to see what damps
//                     the settle's residual motion
//
// The time per step is split into pair upkeep (the skin check and, when it
// fires, the DESS sort and contact-list merge), narrow phase, forces and
// integration (with the stability checks). The step computes the overlap and
// the force of a pair in one loop, so the narrow phase alone is timed here as
// a separate pass of the narrow phase over the same candidate pairs (best of 50), and
// forces are that loop's time less the narrow pass. The timing covers the
// steps only (contacts are counted between them, untimed). other_cpu_s: CPU
// seconds other processes used during the best repetition (from /proc/stat).
// pairs_per_disc: candidate pairs (the contact list) per disc at the end;
// deepest_overlap: the largest overlap over the smaller disc's radius seen
// during the settle (sampled every 10 steps) and the step it was seen at.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <sched.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "sandflow/core/byte_stream.hpp"
#include "sandflow/dem/assembly.hpp"
#include "sandflow/io/checkpoint.hpp"

using namespace sf;
using namespace sf::dem;

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}
double unixSeconds() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

// Contacts of each slot (walls included as partners).
std::vector<int> contactCounts(const Assembly& a) {
  std::vector<int> count(a.bodies().size(), 0);
  for (const Contact& c : a.contacts())
    if (c.touching) ++count[c.a], ++count[c.b];
  return count;
}

struct Energy {
  double translational = 0, rotational = 0, vmax = 0, vy = 0, y = 0, mass = 0;
};
Energy energy(const Assembly& a) {
  const Bodies& b = a.bodies();
  Energy e;
  double py = 0, my = 0;
  for (int s = 0; s < b.size(); ++s) {
    if (b.invMass[s] == 0) continue;
    e.translational += 0.5 * b.mass[s] * b.v[s].squaredNorm();
    e.rotational += 0.5 * b.inertia[s] * b.w[s] * b.w[s];
    e.vmax = std::max(e.vmax, b.v[s].norm());
    py += b.mass[s] * b.v[s].y();
    my += b.mass[s] * b.x[s].y();
    e.mass += b.mass[s];
  }
  e.vy = py / e.mass;
  e.y = my / e.mass;
  return e;
}

// Where the kinetic energy sits: the fastest discs, discs by contact count,
// discs on a wall, layers of height, and the bed's mean motion.
void diagnose(const Assembly& a, int walls) {
  const Bodies& b = a.bodies();
  const std::vector<int> count = contactCounts(a);
  std::vector<char> onWall(b.size(), 0);
  for (const Contact& c : a.contacts())
    if (c.touching && (c.a < walls || c.b < walls)) onWall[c.a] = onWall[c.b] = 1;
  std::vector<double> ke;
  std::vector<std::pair<double, int>> bySpeed;
  double top = 0, total = 0;
  for (int s = walls; s < b.size(); ++s) top = std::max(top, b.x[s].y());
  double byCount[4] = {}, wall = 0, layer[5] = {}, cx = 0, cy = 0, mass = 0, wallRot = 0;
  int nCount[4] = {}, nWall = 0;
  for (int s = walls; s < b.size(); ++s) {
    const double k = 0.5 * b.mass[s] * b.v[s].squaredNorm() + 0.5 * b.inertia[s] * b.w[s] * b.w[s];
    total += k;
    ke.push_back(k);
    bySpeed.push_back({b.v[s].norm(), s});
    const int c = std::min(count[s], 3);
    byCount[c] += k, ++nCount[c];
    if (onWall[s]) wall += k, wallRot += 0.5 * b.inertia[s] * b.w[s] * b.w[s], ++nWall;
    layer[std::min(4, int(5 * b.x[s].y() / top))] += k;
    cx += b.mass[s] * b.v[s].x(), cy += b.mass[s] * b.v[s].y(), mass += b.mass[s];
  }
  std::sort(ke.rbegin(), ke.rend());
  std::sort(bySpeed.rbegin(), bySpeed.rend());
  const int n = int(ke.size());
  double top1 = 0, top10 = 0;
  for (int i = 0; i < n; ++i) {
    if (i < n / 100) top1 += ke[i];
    if (i < n / 10) top10 += ke[i];
  }
  std::printf("diagnose: kinetic=%.3g J/m, mean motion M vcm^2/2=%.3g (vcm=%.3g,%.3g m/s)\n", total,
              0.5 * (cx * cx + cy * cy) / mass, cx / mass, cy / mass);
  std::printf("  share of the fastest 1%%: %.1f%%, fastest 10%%: %.1f%%\n", 100 * top1 / total,
              100 * top10 / total);
  for (int c = 0; c < 4; ++c)
    std::printf("  discs with %s contacts: %6d, %.1f%% of the energy\n",
                c == 3 ? ">=3" : std::to_string(c).c_str(), nCount[c], 100 * byCount[c] / total);
  std::printf("  discs on a wall: %d, %.1f%% of the energy (%.1f%% of it rotation)\n", nWall,
              100 * wall / total, wall > 0 ? 100 * wallRot / wall : 0.0);
  for (int l = 0; l < 5; ++l)
    std::printf("  height layer %d/5 (bottom = 1): %.1f%% of the energy\n", l + 1,
                100 * layer[l] / total);
  for (int i = 0; i < 5 && i < n; ++i) {
    const int s = bySpeed[i].second;
    std::printf("  fast disc %d: |v|=%.3g m/s w=%.3g rad/s at (%.4g, %.4g) m, %d contacts%s\n",
                b.id[s], bySpeed[i].first, b.w[s], b.x[s].x(), b.x[s].y(), count[s],
                onWall[s] ? ", on a wall" : "");
  }
}

// CPU seconds the whole machine spent busy (as scripts/bench counts them:
// user, nice, system, irq, softirq, steal) and those of this process.
double machineBusy() {
  std::FILE* f = std::fopen("/proc/stat", "r");
  if (!f) return 0;
  unsigned long long v[8] = {};
  const int got = std::fscanf(f, "cpu %llu %llu %llu %llu %llu %llu %llu %llu", &v[0], &v[1], &v[2],
                              &v[3], &v[4], &v[5], &v[6], &v[7]);
  std::fclose(f);
  if (got < 8) return 0;
  return double(v[0] + v[1] + v[2] + v[5] + v[6] + v[7]) / double(sysconf(_SC_CLK_TCK));
}
double ownCpu() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// One pass of the narrow phase alone over the current candidate pairs.
double narrowPass(const Assembly& a, int threads) {
  const Bodies& b = a.bodies();
  const std::vector<Contact>& cs = a.contacts();
  const std::ptrdiff_t nc = std::ptrdiff_t(cs.size());
  long hits = 0;
  const auto t0 = Clock::now();
#pragma omp parallel for schedule(static) num_threads(threads) reduction(+ : hits)
  for (std::ptrdiff_t k = 0; k < nc; ++k) {
    const Contact& c = cs[k];
    Manifold m;
    hits += c.discs ? collideDiscs(b.x[c.a], b.reach[c.a], b.x[c.b], b.reach[c.b], m)
                    : collide(*b.shape[c.a], {b.x[c.a], b.angle[c.a]}, *b.shape[c.b],
                              {b.x[c.b], b.angle[c.b]}, m);
  }
  const double t = since(t0);
  if (hits < 0) std::printf("?");  // keeps the loop
  return t;
}

}  // namespace

// The settled bed as a LAMMPS data file (atom_style sphere: id type diameter
// density x y z, then id vx vy vz wx wy wz), the box and walls of
// shared/peers/lammps-bed. Written beside and renamed, so that a reader
// waiting for the file never sees half of it.
bool writeLammpsData(const Assembly& a, int walls, double W, double H, const std::string& path) {
  const Bodies& b = a.bodies();
  const int n = int(b.x.size()) - walls;
  const std::string part = path + ".part";
  FILE* f = std::fopen(part.c_str(), "w");
  if (!f) return false;
  std::fprintf(f,
               "sandflow settled bed %d\n\n%d atoms\n1 atom types\n\n0 %.17g xlo xhi\n0 %.17g ylo "
               "yhi\n-0.001 0.001 zlo zhi\n\nAtoms # sphere\n\n",
               n, n, W, H);
  for (int i = 0; i < n; ++i)
    std::fprintf(f, "%d 1 %.17g 2650 %.17g %.17g 0\n", i + 1,
                 2 * static_cast<const Disc&>(*b.shape[walls + i]).radius(), b.x[walls + i].x(),
                 b.x[walls + i].y());
  std::fprintf(f, "\nVelocities\n\n");
  for (int i = 0; i < n; ++i)
    std::fprintf(f, "%d %.17g %.17g 0 0 0 %.17g\n", i + 1, b.v[walls + i].x(), b.v[walls + i].y(),
                 b.w[walls + i]);
  const bool ok = std::fclose(f) == 0;
  return ok && std::rename(part.c_str(), path.c_str()) == 0;
}

int main(int argc, char** argv) {
  std::vector<std::string> pos;
  int reps = 1, trace = 0, fine = 0;
  long fineFrom = 0;
  bool diag = false;
  std::string beside;      // --beside FILE
  std::string lammpsData;  // --lammps-data FILE
  double restitution = 0.5, friction = 0.5, bondGap = -1;
  bool reference = false;
  std::string settledFile;  // --settled FILE
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--reps") && i + 1 < argc)
      reps = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--trace") && i + 1 < argc)
      trace = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--fine") && i + 2 < argc)
      fineFrom = std::atol(argv[i + 1]), fine = std::atoi(argv[i + 2]), i += 2;
    else if (!std::strcmp(argv[i], "--restitution") && i + 1 < argc)
      restitution = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--friction") && i + 1 < argc)
      friction = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--beside") && i + 1 < argc)
      beside = argv[++i];
    else if (!std::strcmp(argv[i], "--lammps-data") && i + 1 < argc)
      lammpsData = argv[++i];
    else if (!std::strcmp(argv[i], "--reference"))
      reference = true;
    else if (!std::strcmp(argv[i], "--settled") && i + 1 < argc)
      settledFile = argv[++i];
    else if (!std::strcmp(argv[i], "--bonded") && i + 1 < argc)
      bondGap = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--diagnose"))
      diag = true;
    else
      pos.push_back(argv[i]);
  }
  const int n = pos.size() > 0 ? std::atoi(pos[0].c_str()) : 10000;
  const long settle = pos.size() > 1 ? std::atol(pos[1].c_str()) : 100000;
  const long timed = pos.size() > 2 ? std::atol(pos[2].c_str()) : 2000;
  std::vector<int> threadList;
  for (const char* p = pos.size() > 3 ? pos[3].c_str() : "1"; *p;) {
    threadList.push_back(std::max(1, std::atoi(p)));
    while (*p && *p != ',') ++p;
    if (*p == ',') ++p;
  }

  Assembly a;
  a.setThreads(*std::max_element(threadList.begin(), threadList.end()));
  // Beside another code: this one keeps to CPU 0 until that one is done.
  cpu_set_t everyCpu;
  sched_getaffinity(0, sizeof everyCpu, &everyCpu);
  auto pinToFirstCpu = [&] {
    cpu_set_t first;
    CPU_ZERO(&first);
    CPU_SET(0, &first);
    if (sched_setaffinity(0, sizeof first, &first) != 0) std::perror("sched_setaffinity");
  };
  if (!beside.empty()) {
    if (std::find(threadList.begin(), threadList.end(), 1) == threadList.end())
      threadList.push_back(1);
    std::sort(threadList.begin(), threadList.end());
    // The code beside starts from this one's settled bed: until it is
    // written, this one has the machine to itself.
    if (lammpsData.empty()) pinToFirstCpu(), a.setThreads(1);
  }
  // The fall's impacts press discs deep at this stiffness: up to 0.57 of the
  // smaller radius at N = 100,000, past sandflow's default safety limit of 0.5
  // (LAMMPS has none). The settled bed is what is timed, so the limit is
  // raised for the bed; the largest overlap reached is printed.
  a.setMaxOverlap(1.0);
  Material m{"glass"};
  m.density = 2650;
  m.kn = m.ks = 1e5;
  m.restitution = restitution;
  m.friction = friction;
  const int mat = a.materials().add(m);

  const double pitch = 2.05e-3;
  const int cols = (n + 127) / 128;
  const int rows = (n + cols - 1) / cols;
  const double W = (cols + 0.25) * pitch, H = 1.05e-3 + rows * pitch + 0.01;
  auto wall = [&](Vec2 p, Vec2 q) {
    ElementDef d;
    d.shape = std::make_unique<Wall>((q - p).norm(), 1e-3);
    d.material = mat;
    d.x = 0.5 * (p + q);
    d.angle = std::atan2((q - p).y(), (q - p).x());
    d.hold = holdX | holdY | holdRotation;
    a.add(std::move(d));
  };
  wall({0, 0}, {W, 0});
  wall({0, 0}, {0, H});
  wall({W, 0}, {W, H});
  const int walls = 3;
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> radius(0.5e-3, 1.0e-3), jitter(-0.02e-3, 0.02e-3);
  for (int i = 0; i < n; ++i) {
    const int row = i / cols;
    ElementDef d;
    d.shape = std::make_unique<Disc>(radius(rng));
    d.material = mat;
    d.x = Vec2((i % cols + 0.5 + 0.25 * (row % 2)) * pitch + jitter(rng), 1.05e-3 + row * pitch);
    a.add(std::move(d));
  }
  const double mMin = 2650 * std::numbers::pi * 0.25e-6;
  const double dt = 2 * std::sqrt(mMin / 1e5) / 20;
  const Vec2 g(0, -9.81);

  const auto s0 = Clock::now();
  double deepest = 0;
  long deepestStep = 0;
  struct stat settledStat;
  const bool loadSettled = !settledFile.empty() && stat(settledFile.c_str(), &settledStat) == 0;
  if (loadSettled) {
    std::ifstream file(settledFile, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(file)),
                                  std::istreambuf_iterator<char>());
    ByteReader in(bytes.data(), bytes.size(), io::kCheckpointVersion);
    Assembly fresh;
    fresh.loadState(in);
    fresh.setThreads(a.threads());
    a = std::move(fresh);
  }
  for (long s = 0; s < (loadSettled ? 0 : settle); ++s) {
    a.step(dt, g);
    if (s % 10 == 0)
      for (const Contact& c : a.contacts())
        if (c.touching) {
          const double r = c.overlap / std::min(a.bodies().extent[c.a], a.bodies().extent[c.b]);
          if (r > deepest) deepest = r, deepestStep = s + 1;
        }
    if ((trace > 0 && (s + 1) % trace == 0) ||
        (fine > 0 && s + 1 >= fineFrom && (s + 1) % fine == 0)) {
      const Energy e = energy(a);
      std::printf(
          "trace step=%ld t=%.4f kinetic=%.4g translational=%.4g rotational=%.4g "
          "vmax=%.3g vcm_y=%.3g ycm=%.7g contacts_per_disc=%.3f\n",
          s + 1, a.time(), e.translational + e.rotational, e.translational, e.rotational, e.vmax,
          e.vy, e.y, double(a.touchingCount()) / n);
      std::fflush(stdout);
    }
  }
  const double settleSeconds = since(s0);
  if (!settledFile.empty() && !loadSettled) {
    ByteWriter out;
    a.saveState(out);
    std::ofstream(settledFile, std::ios::binary)
        .write(out.bytes().data(), std::streamsize(out.bytes().size()));
  }
  if (diag) diagnose(a, walls);
  if (!lammpsData.empty()) {
    if (!writeLammpsData(a, walls, W, H, lammpsData)) {
      std::fprintf(stderr, "cannot write %s\n", lammpsData.c_str());
      return 1;
    }
    if (!beside.empty()) pinToFirstCpu();
  }

  const int bonds = bondGap >= 0 ? a.bondAll({}, bondGap) : 0;
  // Every timed phase starts from here.
  ByteWriter settled;
  a.saveState(settled);
  auto restore = [&](int threads) {
    Assembly fresh;
    ByteReader in(settled.bytes().data(), settled.bytes().size(), io::kCheckpointVersion);
    fresh.loadState(in);
    a = std::move(fresh);
    a.setThreads(threads);
  };

  bool first = true, referenceMode = false;
  double contactsFirst = 0, discContactsFirst = 0, kineticFirst = 0, translationalFirst = 0;
  // One timed phase: its wall seconds (steps only); contacts are counted
  // between the steps, untimed, and those of the first phase are kept: each
  // contact once, walls included, and disc-disc contacts alone (what
  // LAMMPS's contact/atom counts).
  auto phase = [&]() {
    restore(a.threads());
    a.referenceStep = referenceMode;
    double contacts = 0, discContacts = 0, seconds = 0;
    for (long s = 0; s < timed; ++s) {
      const auto t0 = Clock::now();
      a.step(dt, g);
      seconds += since(t0);
      if (first)
        for (const Contact& c : a.contacts())
          if (c.touching) contacts += 1, discContacts += c.a >= walls;
    }
    if (first) {
      contactsFirst = contacts / timed / n, discContactsFirst = discContacts / timed / n;
      const Energy e = energy(a);
      kineticFirst = e.translational + e.rotational, translationalFirst = e.translational;
    }
    first = false;
    return seconds;
  };
  // The same phase again and again, each stamped with the wall clock, until
  // the code beside is done; then every CPU for the next thread count.
  auto besidePhases = [&]() {
    struct stat st;
    while (stat(beside.c_str(), &st) != 0) {
      const double start = unixSeconds();
      const double seconds = phase();
      std::printf("beside start=%.3f end=%.3f psps=%.4g\n", start, unixSeconds(),
                  n * double(timed) / seconds);
      std::fflush(stdout);
    }
    sched_setaffinity(0, sizeof everyCpu, &everyCpu);
  };
  for (int threads : timed > 0 ? threadList : std::vector<int>{}) {
    a.setThreads(threads);
    // From this code's settled bed the other code times only its 2,000 steps,
    // over by the end of this one's repetitions: the stamped phases first.
    const bool besideHere = !beside.empty() && threads == 1;
    if (besideHere && !lammpsData.empty()) besidePhases();
    // The step, and with --reference the slow reference step beside it, in
    // alternate repetitions (both meet the same machine).
    struct Best {
      double best = 1e300, worst = 0, sort = 0, pass = 0, sums = 0, integrate = 0, other = 0;
      double otherTotal = 0, timedTotal = 0;
      long builds = 0;
    };
    const std::vector<bool> modes =
        reference ? std::vector<bool>{false, true} : std::vector<bool>{false};
    Best results[2];
    for (int r = 0; r < reps; ++r)
      for (bool ref : modes) {
        Best& res = results[ref];
        referenceMode = ref;
        const double busy0 = machineBusy(), own0 = ownCpu();
        const double seconds = phase();
        const double other = std::max(0.0, (machineBusy() - busy0) - (ownCpu() - own0));
        res.otherTotal += other, res.timedTotal += seconds;
        const Profile& after = a.profile();  // a fresh one since the restore
        auto per = [&](Stage stage) { return after.seconds(stage) / timed; };
        res.worst = std::max(res.worst, seconds);
        if (seconds < res.best) {
          res.best = seconds, res.other = other;
          res.sort = per(Stage::demPairs);
          res.pass = per(Stage::demContacts);
          res.sums = per(Stage::demSums);
          res.integrate = per(Stage::demIntegrate);
          res.builds = long(a.broadPhaseBuilds());  // since the restore
        }
      }
    referenceMode = false;
    if (besideHere && lammpsData.empty()) besidePhases();
    double narrowOnly = 1e300;
    for (int r = 0; r < 50; ++r) narrowOnly = std::min(narrowOnly, narrowPass(a, threads));
    for (bool ref : modes) {
      const Best& res = results[ref];
      const double narrow = std::min(narrowOnly, res.pass + res.sums);
      std::printf(
          "N=%d%s%s threads=%d dt=%.3g settle_s=%.1f timed_s=%.3f reps=%d psps=%.4g psps_min=%.4g "
          "contacts_per_disc=%.3f disc_contacts_per_disc=%.3f kinetic=%.3g translational=%.3g "
          "sort_us=%.1f narrow_us=%.1f forces_us=%.1f pass_us=%.1f sums_us=%.1f "
          "integrate_us=%.1f step_us=%.1f "
          "builds=%ld pairs_per_disc=%.3f deepest_overlap=%.3f deepest_step=%ld other_cpu_s=%.2f "
          "other_cpu_all_s=%.2f timed_all_s=%.2f\n",
          n, bondGap >= 0 ? (" bonds=" + std::to_string(bonds)).c_str() : "",
          ref ? " step=reference" : "", threads, dt, settleSeconds, res.best, reps,
          n * double(timed) / res.best, n * double(timed) / res.worst, contactsFirst,
          discContactsFirst, kineticFirst, translationalFirst, res.sort * 1e6, narrow * 1e6,
          (res.pass + res.sums - narrow) * 1e6, res.pass * 1e6, res.sums * 1e6, res.integrate * 1e6,
          res.best / timed * 1e6, res.builds, double(a.contacts().size()) / n, deepest, deepestStep,
          res.other, res.otherTotal, res.timedTotal);
    }
    std::fflush(stdout);
  }
  return 0;
}
