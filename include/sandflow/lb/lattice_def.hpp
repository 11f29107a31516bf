#pragma once
// Everything that defines a lattice, in the user's physical units, and its
// resolution into lattice units. Validation lives here so that a command can
// check a whole definition before it touches the scene.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sandflow/geometry/vec2.hpp"
#include "sandflow/lb/collision.hpp"

namespace sf::lb {

enum class SideKind { periodic, noslip, slip, velocity, pressure, outflow };
enum Side { left = 0, right = 1, bottom = 2, top = 3 };
inline constexpr std::array<const char*, 4> sideNames = {"left", "right", "bottom", "top"};
inline constexpr std::array<const char*, 6> sideKindNames = {"periodic", "noslip",   "slip",
                                                             "velocity", "pressure", "outflow"};

// How a velocity side's velocity varies along it: the same everywhere, or
// Poiseuille's parabola, zero at the side's two ends and `velocity` midway.
enum class SideProfile { uniform, parabolic };
inline constexpr std::array<const char*, 2> sideProfileNames = {"uniform", "parabolic"};

struct SideDef {
  SideDef() = default;
  SideDef(SideKind k, const Vec2& u = Vec2::Zero(), double p = 0.0)
      : kind(k), velocity(u), pressure(p) {}
  SideKind kind = SideKind::noslip;
  Vec2 velocity = Vec2::Zero();  // wall velocity (noslip) or inflow velocity (velocity)
  double pressure = 0.0;         // pressure boundary, p = c_s^2 rho
  // Velocity sides only.
  SideProfile profile = SideProfile::uniform;
  double ramp = 0.0;  // time over which the velocity rises smoothly from 0 (0: at once)
  // A profile given as expressions (the command layer's language, which the
  // kernel does not read): their text, kept for cget and checkpoints, and
  // their values at the side's nodes (physical units, one per node from the
  // side's start), which the command layer evaluates once, or before every
  // step when they depend on time (`timed`).
  std::array<std::string, 2> expr;
  bool timed = false;
  std::vector<Vec2> values;
  bool byExpression() const { return !expr[0].empty(); }
};
// Whether two sides impose the same thing (kind, values, profile, ramp, expressions).
bool sameSide(const SideDef& a, const SideDef& b);

struct LatticeDef {
  Vec2 origin = Vec2::Zero();
  Vec2 size = Vec2::Zero();
  int cells = 0;         // cells across x ...
  double spacing = 0.0;  // ... or the node spacing h: exactly one is set
  std::optional<double> viscosity;
  std::optional<double> tau;
  std::optional<double> timestep;  // used when tau is not given
  double density = 1.0;
  Vec2 forcing = Vec2::Zero();  // body force per unit area (rho a)
  Collision collision = Collision::bgk;
  ForceScheme forceScheme = ForceScheme::nodal;
  double magic = 3.0 / 16.0;  // TRT Lambda
  std::array<SideDef, 4> sides = {SideDef{SideKind::periodic}, SideDef{SideKind::periodic},
                                  SideDef{SideKind::noslip}, SideDef{SideKind::noslip}};
};

// BGK is stable only for tau above 1/2 (zero or negative viscosity below).
inline constexpr double kTauMin = 0.5;
// The refusal of a tau at or below kTauMin (the lattice's and the commands').
std::string unstableTau(double tau);

// A definition with every derived quantity filled in and checked.
struct ResolvedLattice {
  LatticeDef def;
  int nx = 0, ny = 0;
  double h = 0.0, dt = 0.0, tau = 0.0, viscosity = 0.0;
  double latticeSpeed() const { return h / dt; }
  // The antisymmetric relaxation time: TRT's from the magic product
  // Lambda = (tau - 1/2)(tau- - 1/2), BGK's tau itself.
  double tauMinus() const {
    return def.collision == Collision::trt ? def.magic / (tau - 0.5) + 0.5 : tau;
  }
  double soundSpeed() const;
  // Conversions between physical and lattice units.
  double velocityToLattice(double v) const { return v * dt / h; }
  double forceToLattice(double f) const { return f * dt * dt / h; }
};

// Bytes of memory per node that a lattice uses: one population array streamed
// in place and a node kind (twice the populations while it keeps its state
// before each step, Lattice::keepPrevious).
inline constexpr double bytesPerNode = 9.0 * sizeof(double) + 1;

// Checks the definition and derives nx, ny, h, dt, tau and viscosity. Throws
// sf::Error with the numbers on any inconsistency or instability. Exactly two of
// viscosity, tau and timestep determine the third (tau and viscosity win when all
// three are given; tau defaults to 1).
ResolvedLattice resolve(const LatticeDef& def);

// Largest lattice Mach number (|u| / c) a boundary may impose.
inline constexpr double maxBoundaryMach = 0.3;

// The nodes along side `side` (its edge row, from the side's start: the
// bottom for left and right, the left for bottom and top), their distance s
// from the start and the side's length L.
int sideNodeCount(const ResolvedLattice& r, int side);
double sideLength(const ResolvedLattice& r, int side);
inline double sideNodeDistance(const ResolvedLattice& r, int k) {
  return (k + 0.5) * r.h;
}
// The factor of a side's velocity at time t under a ramp over T:
// (1 - cos(pi t / T)) / 2 up to T (smooth: no jump in velocity nor
// acceleration's start), then 1.
double rampFactor(double t, double T);
// Side `side`'s velocity at its k-th node before any ramp (physical units).
Vec2 sideVelocityAt(const ResolvedLattice& r, int side, int k);
// Refuses values for an expression side that do not fit it (count, finite,
// Mach): sf::Error "VALUE WALLS" naming the side, the node's s and the value.
void checkSideValues(const ResolvedLattice& r, int side, const std::vector<Vec2>& values);

}  // namespace sf::lb
