// The full cylindrical Couette study (thesis case B, §5.1), for
// docs/validation.md: convergence of the stationary and the translating cell,
// the relaxation-time sweep, the interior treatment, the solid-ratio settings,
// and the transient Stokes layer against a finite-difference reference.
//
//   sandflow_validate_couette ?--quick|--smoke? ?--csv DIR?
//
// Prints tables; with --csv writes them as CSV files for plotting. --smoke
// runs every table on the coarsest lattices, for a check of scripts/validate
// itself (its numbers mean little).
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "couette_case.hpp"

namespace {

using namespace sf;
using namespace sf::validation;

FILE* csvFile(const std::string& dir, const char* name, const char* header) {
  if (dir.empty()) return nullptr;
  FILE* f = std::fopen((dir + "/" + name).c_str(), "w");
  if (f) std::fprintf(f, "%s\n", header);
  return f;
}

double slope(double e0, double e1) {
  return std::log(e0 / e1) / std::log(2.0);
}

void convergence(const char* title, const Vec2& translate, const std::vector<int>& cells,
                 FILE* csv) {
  std::printf("%s\n%8s %10s %8s %11s %6s %11s %6s %11s %10s %8s\n", title, "cells", "h", "steps",
              "velocity L2", "slope", "torque", "slope", "max |du|", "net force", "seconds");
  CouetteResult previous;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    CouetteSetup s;
    s.cells = cells[k];
    s.translate = translate;
    const CouetteResult r = runCouette(s);
    const bool first = k == 0;
    std::printf(
        "%8d %10.4g %8ld %11.3e %6s %11.3e %6s %11.3e %10.2e %8.1f\n", s.cells, 1.0 / s.cells,
        r.steps, r.velocityError,
        first ? ""
              : std::to_string(slope(previous.velocityError, r.velocityError)).substr(0, 4).c_str(),
        r.torqueError,
        first ? ""
              : std::to_string(slope(previous.torqueError, r.torqueError)).substr(0, 4).c_str(),
        r.maxError, r.netForce, r.seconds);
    if (csv)
      std::fprintf(csv, "%g,%g,%g,%g,%g\n", 1.0 / s.cells, r.velocityError, r.torqueError,
                   r.maxError, r.netForce);
    previous = r;
  }
  std::printf("\n");
}

// The transient of §5.1 (transientErrors in couette_case.hpp).
void transient(FILE* csv) {
  std::printf(
      "Transient Stokes layer, h = 6.25e-3, relative L2 error along theta = 90 deg "
      "(31 interior nodes) against Crank-Nicolson on 4000 intervals\n");
  std::printf("%10s %6s %14s %14s   %s\n", "dt", "tau", "t = 10 dt", "t = 20 dt", "thesis (x1e-2)");
  for (bool half : {false, true}) {
    const TransientErrors e = transientErrors(half);
    std::printf("%10.4g %6.2f %14.3e %14.3e   %s\n", e.dt, e.tau, e.at10, e.at20,
                half ? "1.58, 0.61" : "8.84, 3.80");
    if (csv) std::fprintf(csv, "%g,%g,%g,%g\n", e.dt, e.tau, e.at10, e.at20);
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // a line at a time, also into a file
  bool quick = false, smoke = false;
  std::string dir;
  for (int k = 1; k < argc; ++k) {
    if (!std::strcmp(argv[k], "--quick"))
      quick = true;
    else if (!std::strcmp(argv[k], "--smoke"))
      quick = smoke = true;
    else if (!std::strcmp(argv[k], "--csv") && k + 1 < argc)
      dir = argv[++k];
    else {
      std::fprintf(stderr, "usage: %s ?--quick|--smoke? ?--csv DIR?\n", argv[0]);
      return 2;
    }
  }
  const std::vector<int> cells = smoke   ? std::vector<int>{20, 40}
                                 : quick ? std::vector<int>{20, 40, 80}
                                         : std::vector<int>{20, 40, 80, 160, 320};
  const int fine = smoke ? 20 : 80;  // the lattice of the tables below
  const double h = 1.0 / fine;
  FILE* f = csvFile(dir, "couette-stationary.csv", "h,velocity,torque,max,netforce");
  convergence("Stationary cell (outer cylinder at 0.1 rad/s, inner at rest), t = 2.5", Vec2::Zero(),
              cells, f);
  if (f) std::fclose(f);
  f = csvFile(dir, "couette-translating.csv", "h,velocity,torque,max,netforce");
  convergence("Translating cell (both cylinders at {0.03 0.015})", Vec2(0.03, 0.015), cells, f);
  if (f) std::fclose(f);

  // Relaxation time at c = h/dt = 20, nu from tau.
  std::printf("Relaxation-time sweep, h = %.3g, c = 20 (dt = %.3g), nu = (2 tau - 1)/6 h c\n", h,
              h / 20);
  std::printf("%6s %10s %11s %11s %11s\n", "tau", "nu", "max |du|", "velocity L2", "torque");
  f = csvFile(dir, "couette-tau.csv", "tau,max,velocity,torque");
  for (double tau : {0.55, 0.6, 0.625, 0.65, 0.7, 0.8, 1.0, 1.25, 1.5}) {
    if (quick && tau != 0.625 && tau != 1.0) continue;
    CouetteSetup s;
    s.cells = fine;
    s.tau = tau;
    s.nu = (2 * tau - 1) / 6 * h * 20;
    s.time = 2.5 * 4.166e-2 / s.nu;  // the same number of diffusive times
    const CouetteResult r = runCouette(s);
    std::printf("%6.3f %10.4g %11.3e %11.3e %11.3e\n", tau, s.nu, r.maxError, r.velocityError,
                r.torqueError);
    if (f) std::fprintf(f, "%g,%g,%g,%g\n", tau, r.maxError, r.velocityError, r.torqueError);
  }
  if (f) std::fclose(f);
  std::printf("\n");

  std::printf("Interior cells (inner cylinder turning at 0.3, outer at rest, %d cells)\n", fine);
  std::printf("%12s %11s %11s %12s\n", "interior", "velocity L2", "torque", "torque value");
  for (bool eq : {true, false}) {
    CouetteSetup s;
    s.cells = fine;
    s.omega1 = 0.3;
    s.omega2 = 0;
    s.coupling.equilibriumInterior = eq;
    const CouetteResult r = runCouette(s);
    std::printf("%12s %11.3e %11.3e %12.6e\n", eq ? "equilibrium" : "collide", r.velocityError,
                r.torqueError, r.torque);
  }
  std::printf("\n");

  std::printf("Solid ratio settings (%d cells, stationary cell)\n", fine);
  std::printf("%10s %11s %11s %8s\n", "solidratio", "velocity L2", "torque", "seconds");
  f = csvFile(dir, "couette-solidratio.csv", "setting,velocity,torque,seconds");
  const int settings[] = {coupling::kExact, 1, 2, 4, 8};
  const char* names[] = {"exact", "1", "2", "4", "8"};
  for (int k = 0; k < 5; ++k) {
    CouetteSetup s;
    s.cells = fine;
    s.coupling.subcells = settings[k];
    const CouetteResult r = runCouette(s);
    std::printf("%10s %11.3e %11.3e %8.2f\n", names[k], r.velocityError, r.torqueError, r.seconds);
    if (f) std::fprintf(f, "%s,%g,%g,%g\n", names[k], r.velocityError, r.torqueError, r.seconds);
  }
  if (f) std::fclose(f);
  std::printf("\n");

  f = csvFile(dir, "couette-transient.csv", "dt,tau,error10,error20");
  transient(f);
  if (f) std::fclose(f);
  return 0;
}
