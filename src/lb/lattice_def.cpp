#include "sandflow/lb/lattice_def.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "sandflow/core/error.hpp"
#include "sandflow/core/memory.hpp"

namespace sf::lb {

std::string unstableTau(double tau) {
  return "tau " + formatNumber(tau) + " is unstable: must exceed " + formatNumber(kTauMin);
}

bool sameSide(const SideDef& a, const SideDef& b) {
  return a.kind == b.kind && a.velocity == b.velocity && a.pressure == b.pressure &&
         a.profile == b.profile && a.ramp == b.ramp && a.expr == b.expr && a.timed == b.timed &&
         a.values == b.values;
}

int sideNodeCount(const ResolvedLattice& r, int side) {
  return side == left || side == right ? r.ny : r.nx;
}

double sideLength(const ResolvedLattice& r, int side) {
  return sideNodeCount(r, side) * r.h;
}

double rampFactor(double t, double T) {
  if (!(T > 0) || t >= T) return 1.0;
  if (t <= 0) return 0.0;
  return 0.5 * (1 - std::cos(std::numbers::pi * t / T));
}

Vec2 sideVelocityAt(const ResolvedLattice& r, int side, int k) {
  const SideDef& d = r.def.sides[side];
  if (d.byExpression()) return d.values[k];
  if (d.profile == SideProfile::uniform) return d.velocity;
  const double s = sideNodeDistance(r, k), L = sideLength(r, side);
  return d.velocity * (4 * s * (L - s) / (L * L));
}

void checkSideValues(const ResolvedLattice& r, int side, const std::vector<Vec2>& values) {
  const std::string name = sideNames[side];
  const int n = sideNodeCount(r, side);
  if (int(values.size()) != n)
    throw Error("VALUE WALLS", name + " side: " + std::to_string(values.size()) +
                                   " velocities for its " + std::to_string(n) + " nodes");
  for (int k = 0; k < n; ++k) {
    const Vec2& u = values[k];
    const std::string at = " at s = " + formatNumber(sideNodeDistance(r, k));
    if (!u.allFinite())
      throw Error("VALUE WALLS", name + " side: velocity {" + formatNumber(u.x()) + " " +
                                     formatNumber(u.y()) + "}" + at + " is not finite");
    const double mach = r.velocityToLattice(u.norm());
    if (mach > maxBoundaryMach)
      throw Error("VALUE WALLS", name + " velocity " + formatNumber(u.norm()) + at + " is Mach " +
                                     formatNumber(mach) +
                                     " on this lattice (c = " + formatNumber(r.latticeSpeed()) +
                                     "): must be below " + formatNumber(maxBoundaryMach));
  }
}
namespace {

using sf::formatNumber;

std::string upper(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// The message names the field; the command layer names its option.
void requirePositive(double value, const char* field) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw Error("VALUE " + upper(field),
                std::string("a lattice's ") + field + " must be > 0, got " + formatNumber(value));
}

// A length rounded for a suggestion (12 significant digits: no 0.8999999999999999).
std::string roundedLength(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.12g", v);
  return buffer;
}

// Whole number of spacings in `length`, or an error naming both values. A
// double: the count may be far beyond an int until the memory check refuses it.
double wholeCells(double length, double h, const char* what) {
  const double n = std::round(length / h);
  if (!std::isfinite(n))
    throw Error("VALUE SPACING", "spacing " + formatNumber(h) + " is too small for a " + what +
                                     " of " + formatNumber(length) +
                                     ": the count of cells overflows");
  if (n < 1 || std::abs(n * h - length) > 1e-9 * std::max(length, h))
    throw Error("VALUE SIZE", std::string("the lattice's ") + what + " " + formatNumber(length) +
                                  " is not a whole number of spacings (h = " + formatNumber(h) +
                                  "): use " + roundedLength(std::max(1.0, n) * h));
  return n;
}

// A node count as a user would write it: 100000, or 1e+12 when that long.
std::string count(double n) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, n < 1e15 ? "%.0f" : "%.3g", n);
  return buffer;
}

// Refuses a lattice that would not fit in memory, or whose populations (nine
// per node, padded) a 32-bit link index could not reach, before anything is
// allocated or narrowed to int.
void checkNodeCount(double nx, double ny) {
  const double nodes = (nx + 2) * (ny + 2);
  const std::string lattice = "a " + count(nx) + " x " + count(ny) + " lattice";
  checkMemory(nodes * bytesPerNode, lattice);
  if (nodes * 9 > 2.0e9)
    throw Error("RESOURCE SIZE", lattice + " has " + count(nodes) + " nodes, more than the " +
                                     count(2.0e9 / 9) + " one lattice can index");
}

}  // namespace

double ResolvedLattice::soundSpeed() const {
  return latticeSpeed() / std::sqrt(3.0);
}

ResolvedLattice resolve(const LatticeDef& def) {
  ResolvedLattice r;
  r.def = def;
  if (!def.origin.allFinite()) throw Error("VALUE ORIGIN", "a lattice's origin must be finite");
  requirePositive(def.size.x(), "size");
  requirePositive(def.size.y(), "size");
  if ((def.cells > 0) == (def.spacing > 0.0))
    throw Error("VALUE CELLS", "give exactly one of the cell count and the spacing");
  double nx = def.cells;
  if (def.cells > 0) {
    r.h = def.size.x() / def.cells;
  } else {
    requirePositive(def.spacing, "spacing");
    r.h = def.spacing;
    nx = wholeCells(def.size.x(), r.h, "width");
  }
  const double ny = wholeCells(def.size.y(), r.h, "height");
  checkNodeCount(nx, ny);
  r.nx = static_cast<int>(nx);
  r.ny = static_cast<int>(ny);
  requirePositive(def.density, "density");

  // Two of viscosity, tau and timestep give the third: nu = (2 tau - 1)/6 h^2/dt.
  const double h2 = r.h * r.h;
  if (def.viscosity) requirePositive(*def.viscosity, "viscosity");
  if (def.tau && !std::isfinite(*def.tau))
    throw Error("VALUE TAU", "a lattice's tau must be finite");
  if (def.tau && *def.tau <= kTauMin) throw Error("VALUE TAU", unstableTau(*def.tau));
  if (def.timestep) requirePositive(*def.timestep, "timestep");
  if (def.viscosity && (def.tau || !def.timestep)) {
    r.viscosity = *def.viscosity;
    r.tau = def.tau.value_or(1.0);
    r.dt = (2 * r.tau - 1) / 6 * h2 / r.viscosity;
  } else if (def.viscosity) {
    r.viscosity = *def.viscosity;
    r.dt = *def.timestep;
    r.tau = 0.5 + 3 * r.viscosity * r.dt / h2;
    if (r.tau <= kTauMin + 1e-12)
      throw Error("VALUE TAU", "tau " + formatNumber(r.tau) + " (from viscosity " +
                                   formatNumber(r.viscosity) + ", spacing " + formatNumber(r.h) +
                                   ", timestep " + formatNumber(r.dt) +
                                   ") is unstable: must exceed 0.5");
  } else if (def.timestep) {
    r.tau = def.tau.value_or(1.0);
    r.dt = *def.timestep;
    r.viscosity = (2 * r.tau - 1) / 6 * h2 / r.dt;
  } else {
    throw Error("VALUE VISCOSITY", "the lattice needs a viscosity", Remedy::viscosityOrTimestep);
  }
  if (!(r.dt > 0) || !std::isfinite(r.dt))
    throw Error("VALUE TIMESTEP", "derived timestep " + formatNumber(r.dt) + " is not usable");

  requirePositive(def.magic, "magic");  // used by TRT only, but never valid <= 0
  if (!def.forcing.allFinite()) throw Error("VALUE FORCING", "a lattice's forcing must be finite");

  // Periodic sides come in pairs; two open (velocity/pressure) sides may not meet.
  for (int axis = 0; axis < 2; ++axis) {
    const auto a = def.sides[2 * axis].kind, b = def.sides[2 * axis + 1].kind;
    if ((a == SideKind::periodic) != (b == SideKind::periodic))
      throw Error("VALUE WALLS", std::string(sideNames[2 * axis]) + " is " + sideKindNames[int(a)] +
                                     " but " + sideNames[2 * axis + 1] + " is " +
                                     sideKindNames[int(b)] + ": periodic sides come in pairs");
  }
  auto open = [&](int s) {
    const SideKind k = def.sides[s].kind;
    return k == SideKind::velocity || k == SideKind::pressure || k == SideKind::outflow;
  };
  for (int v : {left, right})
    for (int hzn : {bottom, top})
      if (open(v) && open(hzn))
        throw Error(
            "VALUE WALLS",
            std::string(sideNames[v]) + " and " + sideNames[hzn] +
                " are both open (velocity, pressure or outflow) sides: they may not meet at "
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
    if (side.kind != SideKind::velocity &&
        (side.byExpression() || side.ramp != 0 || side.profile != SideProfile::uniform))
      throw Error("VALUE WALLS",
                  std::string(sideNames[s]) +
                      ": a profile, an expression or a ramp belongs to a velocity side");
    if (!(side.ramp >= 0) || !std::isfinite(side.ramp))
      throw Error("VALUE WALLS", std::string(sideNames[s]) +
                                     " side: the ramp must be a time >= 0, got " +
                                     formatNumber(side.ramp));
    if (side.byExpression()) checkSideValues(r, s, side.values);
    if (side.kind == SideKind::pressure && !(side.pressure > 0))
      throw Error("VALUE WALLS", std::string(sideNames[s]) + " pressure must be > 0, got " +
                                     formatNumber(side.pressure));
  }
  return r;
}

}  // namespace sf::lb
