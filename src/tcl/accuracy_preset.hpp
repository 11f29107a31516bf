#pragma once
// sim configure -accuracy draft|normal|fine: three consistent sets of the
// lattice's and the step's accuracy knobs, as measured by scripts/tradeoff
// (docs/accuracy.md, "Recommended sets").
#include "sandflow/coupling/coupler.hpp"
#include "sandflow/dem/assembly.hpp"
#include "sandflow/lb/collision.hpp"
#include "sandflow/sim/manager.hpp"

namespace sf::tcl {

struct AccuracyPreset {
  // The lattice's part (applied to a lattice that exists; its viscosity is
  // kept, so tau sets the timestep).
  double tau;
  lb::Collision collision;
  lb::ForceScheme forceScheme;
  // The step's part.
  int subcells;  // coupling::kExact or n x n
  bool implicit;
  dem::Integrator integrator;
  int substeps;
};

// draft, normal, fine; "custom" (kCustomAccuracy) is any other combination.
inline constexpr const char* kAccuracyNames[] = {"draft", "normal", "fine", "custom", nullptr};
inline constexpr int kCustomAccuracy = 3;
const AccuracyPreset& accuracyPreset(int which);

// The set the Manager's settings match (its lattice's too, when it has one),
// or kCustomAccuracy.
int matchingAccuracy(const sim::Manager& m);

// The lattice definition the preset gives the Manager's lattice.
lb::LatticeDef presetLattice(const lb::ResolvedLattice& lattice, const AccuracyPreset& p);

}  // namespace sf::tcl
