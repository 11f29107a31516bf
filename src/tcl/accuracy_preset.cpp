#include "accuracy_preset.hpp"

#include <cmath>

namespace sf::tcl {

namespace {
// docs/accuracy.md: draft is the cheapest step (tau 0.8: a third of fine's
// steps at a given viscosity; TRT keeps straight walls exact there), fine
// the most accurate on moving grains and collisions.
constexpr AccuracyPreset kPresets[] = {
    {0.8, lb::Collision::trt, lb::ForceScheme::guo, 2, true, dem::Integrator::central, 1},
    {0.7, lb::Collision::bgk, lb::ForceScheme::guo, coupling::kExact, true,
     dem::Integrator::central, 2},
    {0.6, lb::Collision::bgk, lb::ForceScheme::guo, coupling::kExact, true,
     dem::Integrator::central, 4},
};
}  // namespace

const AccuracyPreset& accuracyPreset(int which) {
  return kPresets[which];
}

int matchingAccuracy(const sim::Manager& m) {
  for (int k = 0; k < kCustomAccuracy; ++k) {
    const AccuracyPreset& p = kPresets[k];
    if (m.couplingSettings().subcells != p.subcells ||
        m.couplingSettings().implicit != p.implicit || m.assembly().integrator != p.integrator ||
        m.substeps() != p.substeps)
      continue;
    if (m.hasLattice()) {
      const lb::ResolvedLattice& l = m.lattice().params();
      if (std::abs(l.tau - p.tau) > 1e-9 || l.def.collision != p.collision ||
          l.def.forceScheme != p.forceScheme)
        continue;
    }
    return k;
  }
  return kCustomAccuracy;
}

lb::LatticeDef presetLattice(const lb::ResolvedLattice& lattice, const AccuracyPreset& p) {
  lb::LatticeDef def = lattice.def;
  def.viscosity = lattice.viscosity;
  def.tau = p.tau;
  def.timestep.reset();
  def.collision = p.collision;
  def.forceScheme = p.forceScheme;
  return def;
}

}  // namespace sf::tcl
