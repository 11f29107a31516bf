#include "sandflow/lb/lattice_def.hpp"

#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdio>

#include "sandflow/core/error.hpp"

namespace sf::lb {
namespace {

using sf::formatNumber;

std::string upper(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

void requirePositive(double value, const char* option) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw Error("VALUE " + upper(option + 1),
                std::string(option) + " must be > 0, got " + formatNumber(value));
}

// A length rounded for a suggestion (12 significant digits: no 0.8999999999999999).
std::string roundedLength(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.12g", v);
  return buffer;
}

// Whole number of spacings in `length`, or an error naming both values.
int wholeCells(double length, double h, const char* what) {
  const double n = std::round(length / h);
  if (n < 1 || std::abs(n * h - length) > 1e-9 * std::max(length, h))
    throw Error("VALUE SIZE", std::string("-size ") + what + " " + formatNumber(length) +
                                  " is not a whole number of spacings (h = " + formatNumber(h) +
                                  "): use " + roundedLength(std::max(1.0, n) * h));
  if (n > 1e9) throw Error("VALUE SIZE", std::string("lattice ") + what + " too large");
  return static_cast<int>(n);
}

double physicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? static_cast<double>(pages) * pageSize : 0.0;
}

}  // namespace

double ResolvedLattice::soundSpeed() const {
  return latticeSpeed() / std::sqrt(3.0);
}

ResolvedLattice resolve(const LatticeDef& def) {
  ResolvedLattice r;
  r.def = def;
  if (!def.origin.allFinite()) throw Error("VALUE ORIGIN", "-origin must be finite");
  requirePositive(def.size.x(), "-size");
  requirePositive(def.size.y(), "-size");
  if ((def.cells > 0) == (def.spacing > 0.0))
    throw Error("VALUE CELLS", "give exactly one of -cells and -spacing");
  if (def.cells > 0) {
    r.nx = def.cells;
    r.h = def.size.x() / def.cells;
  } else {
    requirePositive(def.spacing, "-spacing");
    r.h = def.spacing;
    r.nx = wholeCells(def.size.x(), r.h, "width");
  }
  r.ny = wholeCells(def.size.y(), r.h, "height");
  requirePositive(def.density, "-density");

  // Memory: refuse before allocating rather than fail half way.
  const double nodes = double(r.nx + 2) * double(r.ny + 2);
  const double bytes = nodes * bytesPerNode;
  const double available = physicalMemoryBytes();
  if (nodes * 9 > 2.0e9 || (available > 0 && bytes > 0.8 * available))
    throw Error("RESOURCE MEMORY",
                "a " + std::to_string(r.nx) + " x " + std::to_string(r.ny) + " lattice needs " +
                    formatNumber(std::round(bytes / 1e8) / 10) + " GB, more than this machine's " +
                    formatNumber(std::round(available / 1e8) / 10) + " GB allows");

  // Two of viscosity, tau and timestep give the third: nu = (2 tau - 1)/6 h^2/dt.
  const double h2 = r.h * r.h;
  if (def.viscosity) requirePositive(*def.viscosity, "-viscosity");
  if (def.tau && !std::isfinite(*def.tau)) throw Error("VALUE TAU", "-tau must be finite");
  if (def.timestep) requirePositive(*def.timestep, "-timestep");
  if (def.viscosity && (def.tau || !def.timestep)) {
    r.viscosity = *def.viscosity;
    r.tau = def.tau.value_or(1.0);
    if (r.tau <= 0.5)
      throw Error("VALUE TAU", "tau " + formatNumber(r.tau) + " is unstable: must exceed 0.5");
    r.dt = (2 * r.tau - 1) / 6 * h2 / r.viscosity;
  } else if (def.viscosity) {
    r.viscosity = *def.viscosity;
    r.dt = *def.timestep;
    r.tau = 0.5 + 3 * r.viscosity * r.dt / h2;
    if (r.tau <= 0.5 + 1e-12)
      throw Error("VALUE TAU", "tau " + formatNumber(r.tau) + " (from viscosity " +
                                   formatNumber(r.viscosity) + ", spacing " + formatNumber(r.h) +
                                   ", timestep " + formatNumber(r.dt) +
                                   ") is unstable: must exceed 0.5");
  } else if (def.timestep) {
    r.tau = def.tau.value_or(1.0);
    if (r.tau <= 0.5)
      throw Error("VALUE TAU", "tau " + formatNumber(r.tau) + " is unstable: must exceed 0.5");
    r.dt = *def.timestep;
    r.viscosity = (2 * r.tau - 1) / 6 * h2 / r.dt;
  } else {
    throw Error("VALUE VISCOSITY",
                "the lattice needs -viscosity (or a timestep from \"sim configure -timestep\")");
  }
  if (!(r.dt > 0) || !std::isfinite(r.dt))
    throw Error("VALUE TIMESTEP", "derived timestep " + formatNumber(r.dt) + " is not usable");

  if (def.collision == Collision::trt) requirePositive(def.magic, "-magic");
  if (!def.forcing.allFinite()) throw Error("VALUE FORCING", "-forcing must be finite");

  // Periodic sides come in pairs; two open (velocity/pressure) sides may not meet.
  for (int axis = 0; axis < 2; ++axis) {
    const auto a = def.sides[2 * axis].kind, b = def.sides[2 * axis + 1].kind;
    if ((a == SideKind::periodic) != (b == SideKind::periodic))
      throw Error("VALUE WALLS", std::string(sideNames[2 * axis]) + " is " + sideKindNames[int(a)] +
                                     " but " + sideNames[2 * axis + 1] + " is " +
                                     sideKindNames[int(b)] + ": periodic sides come in pairs");
  }
  auto open = [&](int s) {
    return def.sides[s].kind == SideKind::velocity || def.sides[s].kind == SideKind::pressure;
  };
  for (int v : {left, right})
    for (int hzn : {bottom, top})
      if (open(v) && open(hzn))
        throw Error("VALUE WALLS", std::string(sideNames[v]) + " and " + sideNames[hzn] +
                                       " are both velocity/pressure sides: they may not meet at "
                                       "a corner (make one of them a wall)");
  for (int s = 0; s < 4; ++s) {
    const SideDef& side = def.sides[s];
    if (!side.velocity.allFinite())
      throw Error("VALUE WALLS", std::string(sideNames[s]) + " velocity must be finite");
    const double mach = r.velocityToLattice(side.velocity.norm());
    if (mach > maxBoundaryMach)
      throw Error("VALUE WALLS", std::string(sideNames[s]) + " velocity " +
                                     formatNumber(side.velocity.norm()) + " is Mach " +
                                     formatNumber(mach) +
                                     " on this lattice (c = " + formatNumber(r.latticeSpeed()) +
                                     "): must be below " + formatNumber(maxBoundaryMach));
    if (side.kind == SideKind::pressure && !(side.pressure > 0))
      throw Error("VALUE WALLS", std::string(sideNames[s]) + " pressure must be > 0, got " +
                                     formatNumber(side.pressure));
  }
  return r;
}

}  // namespace sf::lb
