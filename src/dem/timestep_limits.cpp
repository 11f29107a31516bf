// The stable and the accurate DEM step (docs/stability.md, DEM timestep).
#include <algorithm>
#include <cmath>
#include <limits>

#include "contact_force.hpp"
#include "sandflow/dem/assembly.hpp"

namespace sf::dem {

double Assembly::stiffestContact(int s) const {
  const Material& m = materials_[bodies_.material[s]];
  const double r = detail::curvatureRadius(*bodies_.shape[s]);
  return m.law == ContactLaw::hertz && std::isfinite(r)
             ? 8.0 * m.youngs / (2 * (1 + m.poisson)) * std::sqrt(r * 0.01 * r)
             : std::max(m.kn, m.ks);
}

Assembly::TimestepLimits Assembly::timestepLimits() const {
  criticalTimestep();  // brings limits_ up to date
  return limits_;
}

// The linear contact stepped by any of the three integrators is the map of
// contact_damping.hpp; with h = dt sqrt(k/m*) and damping ratio zeta it stays
// bounded while h <= 2 (sqrt(1 + zeta^2) - zeta) (the eigenvalues of the
// damped central difference), which is 2 sqrt(m/k) for an undamped element
// on a wall. A pair of equal free elements has m* = m/2: sqrt(2) less.
Assembly::TimestepLimits Assembly::measureTimestepLimits(double critical) const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  double mMin = inf, kMax = 0, fixedDamping = 0, zetaMax = 0;
  int free = 0;
  for (int s = 0; s < bodies_.size(); ++s) {
    const Material& m = materials_[bodies_.material[s]];
    kMax = std::max(kMax, stiffestContact(s));
    if (bodies_.invMass[s] > 0 || bodies_.ghost[s]) {
      mMin = std::min(mMin, bodies_.mass[s]);
      free += bodies_.ghost[s] ? 2 : 1;  // a source's clones meet each other
    }
    if (m.damping >= 0)
      fixedDamping = std::max(fixedDamping, m.damping);
    else
      zetaMax = std::max(zetaMax, dampingRatio(m.restitution));
  }
  // A lone element touches nothing: no contact to keep stable or accurate.
  if (!std::isfinite(mMin) || kMax <= 0 || bodies_.size() < 2) return {critical, inf, inf, 0, 0, 0};
  const double mEff = free >= 2 ? mMin / 2 : mMin;
  // A fixed coefficient c damps the lightest contact most: zeta = c / (2 sqrt(m* k)).
  const double zeta = std::max(zetaMax, fixedDamping / (2 * std::sqrt(mEff * kMax)));
  const double period = std::sqrt(mEff / kMax);  // 1 / omega
  return {critical, 2 * period * (std::sqrt(1 + zeta * zeta) - zeta), 0.5 * period, mEff, kMax,
          zeta};
}

}  // namespace sf::dem
