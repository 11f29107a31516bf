#pragma once
// Everything that defines a lattice, in the user's physical units, and its
// resolution into lattice units. Validation lives here so that a command can
// check a whole definition before it touches the scene.
#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "sandflow/geometry/vec2.hpp"
#include "sandflow/lb/collision.hpp"

namespace sf::lb {

enum class SideKind { periodic, noslip, slip, velocity, pressure };
enum Side { left = 0, right = 1, bottom = 2, top = 3 };
inline constexpr std::array<const char*, 4> sideNames = {"left", "right", "bottom", "top"};
inline constexpr std::array<const char*, 5> sideKindNames = {"periodic", "noslip", "slip",
                                                             "velocity", "pressure"};

struct SideDef {
  SideKind kind = SideKind::noslip;
  Vec2 velocity = Vec2::Zero();  // wall velocity (noslip) or inflow velocity (velocity)
  double pressure = 0.0;         // pressure boundary, p = c_s^2 rho
};

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

}  // namespace sf::lb
