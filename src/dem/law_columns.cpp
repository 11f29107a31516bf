// The contact laws' per-step parts that the assembly keeps for the contact
// pass: each contact's damping coefficient, solved for the step
// (contact_damping.hpp), and its normal-force mode.
#include "contact_force.hpp"
#include "sandflow/dem/assembly.hpp"

namespace sf::dem {

// 2 zeta sqrt(m* kn) for the linear law and 2 zeta sqrt(m*) for Hertz (whose
// kn changes with the overlap), with the ratio zeta that gives the
// restitution: for the linear law solved for the step (h = dt sqrt(kn/m*)),
// for Hertz that of the continuous law. A fixed -damping is taken as it is.
double Assembly::dampingPart(const ContactList& l, std::size_t k) const {
  const PairLaw& law = laws_[l.law[k]];
  if (law.damping >= 0) return law.damping;
  const double meff = 1.0 / (bodies_.invMass[l.a[k]] + bodies_.invMass[l.b[k]]);
  if (law.hertz)
    return 2.0 * dampingRatios_.hertz(law.restitution, law.compressive) * std::sqrt(meff);
  const double h = dampingDt_ * std::sqrt(law.kn / meff);
  return 2.0 * dampingRatios_.linear(law.restitution, law.compressive, h) *
         std::sqrt(meff * law.kn);
}

// The pair build gives each contact its law (prepareContact); its damping
// and mode are set here, for the step, and kept until the next build or
// change of step (sim configure -timestep, -substeps, a lattice's).
void Assembly::prepareDamping(double dt) {
  if (dt == dampingDt_ && builds_ == dampingBuild_ && generation_ == dampingGeneration_ &&
      materials_.version() == dampingMaterials_)
    return;
  dampingDt_ = dt, dampingBuild_ = builds_, dampingGeneration_ = generation_;
  dampingMaterials_ = materials_.version();
  ContactList& l = list_;
  for (std::size_t k = 0; k < l.size(); ++k) {
    const PairLaw& law = laws_[l.law[k]];
    const double meff = 1.0 / (bodies_.invMass[l.a[k]] + bodies_.invMass[l.b[k]]);
    l.dampingPart[k] = dampingPart(l, k);
    l.normalFloor[k] = detail::normalFloor(law);
    // The span goes with a restitution's damping: for Hertz, whose ratio is
    // the continuous law's, it still takes a rebound set at 0.1 from -22% to
    // -6% at 10 steps a contact (docs/dem.md). A fixed -damping, and linear
    // contacts too short to solve for (the continuous ratio), keep the plain
    // dashpot, as before.
    const bool solved = law.hertz || dt * std::sqrt(law.kn / meff) <= largestSolvedStep;
    l.spanned[k] = law.damping < 0 && solved;
  }
  viewValid_ = false;
}

}  // namespace sf::dem
