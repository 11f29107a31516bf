#pragma once
// Helpers for the coupled (fluid + elements) tests: a Manager scene with a
// periodic or channel lattice and elements of a soft material.
#include <memory>

#include "sandflow/sim/manager.hpp"

namespace sf::test {

// A material whose critical step is far above any lattice step used here.
inline int softMaterial(sim::Manager& m, double density) {
  dem::Material mat{"soft"};
  mat.density = density;
  mat.kn = mat.ks = 1e-3;
  mat.friction = 0;
  return m.assembly().materials().add(mat);
}

inline int addDisc(sim::Manager& m, int material, const Vec2& x, double r,
                   const Vec2& v = Vec2::Zero(), double w = 0, std::uint8_t hold = 0) {
  dem::ElementDef d;
  d.shape = std::make_unique<dem::Disc>(r);
  d.material = material;
  d.x = x;
  d.v = v;
  d.w = w;
  d.hold = hold;
  return m.assembly().add(std::move(d));
}

inline lb::LatticeDef periodicSquare(double size, int cells, double viscosity, double tau = 1.0) {
  lb::LatticeDef def;
  def.size = Vec2(size, size);
  def.cells = cells;
  def.viscosity = viscosity;
  def.tau = tau;
  for (auto& side : def.sides) side = lb::SideDef{lb::SideKind::periodic};
  return def;
}

// Total momentum of fluid and elements. The central-difference integrator
// conserves it in its half-step velocities: the fluid's momentum after step n
// pairs with v(n + 1/2).
inline Vec2 totalMomentum(const sim::Manager& m) {
  const dem::Bodies& b = m.assembly().bodies();
  Vec2 p = m.lattice().momentum();
  for (int s = 0; s < b.size(); ++s)
    p +=
        b.mass[s] *
        (m.assembly().integrator == dem::Integrator::central && b.started[s] ? b.vHalf[s] : b.v[s]);
  return p;
}

}  // namespace sf::test
