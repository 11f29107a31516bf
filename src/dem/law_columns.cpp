// The contact laws' parts that the contact set keeps for the contact pass:
// the pair-law table, each contact's law, size and radius (kept until the
// elements or materials change), and its damping coefficient, solved for the
// step (contact_damping.hpp), and its normal-force mode.
#include <algorithm>
#include <cmath>

#include "contact_force.hpp"
#include "sandflow/dem/contact_set.hpp"

namespace sf::dem {

void ContactSet::prepareContact(const Bodies& b, ContactList& l, std::size_t k) const {
  const int i = l.a[k], j = l.b[k], nm = lawMaterials_;
  l.law[k] = b.material[i] * nm + b.material[j];
  const PairLaw& law = laws_[l.law[k]];
  // The damping coefficient depends on the masses and materials only: 2 zeta
  // sqrt(m_eff kn) for the linear law, 2 zeta sqrt(m_eff) for Hertz, whose kn
  // changes with the overlap.
  const double meff = 1.0 / (b.invMass[i] + b.invMass[j]);
  l.dampingPart[k] = law.damping >= 0
                         ? law.damping
                         : 2.0 * law.zeta * std::sqrt(meff * (law.hertz ? 1.0 : law.kn));
  l.minSize[k] = std::min(b.extent[i], b.extent[j]);
  // The effective radius of curvature (Hertz): a wall's is infinite.
  const double ra = detail::curvatureRadius(*b.shape[i]), rb = detail::curvatureRadius(*b.shape[j]);
  l.radius[k] = !std::isfinite(ra) ? rb : !std::isfinite(rb) ? ra : ra * rb / (ra + rb);
}

bool ContactSet::lawsStale(const MaterialTable& materials, std::uint64_t generation) const {
  const int nm = materials.size();
  return lawsMaterials_ != materials.version() || int(laws_.size()) != nm * nm ||
         lawsAt_ != generation;
}

void ContactSet::buildLaws(const MaterialTable& materials) {
  const int nm = materials.size();
  laws_.resize(nm * nm);
  lawKn_.resize(nm * nm), lawKs_.resize(nm * nm), lawFriction_.resize(nm * nm);
  for (int i = 0; i < nm; ++i)
    for (int j = 0; j < nm; ++j) {
      const PairLaw law = combine(materials[i], materials[j]);
      laws_[i * nm + j] = law;
      lawKn_[i * nm + j] = law.kn, lawKs_[i * nm + j] = law.ks;
      lawFriction_[i * nm + j] = law.friction;
    }
  lawsMaterials_ = materials.version(), lawMaterials_ = nm;
}

// 2 zeta sqrt(m* kn) for the linear law and 2 zeta sqrt(m*) for Hertz (whose
// kn changes with the overlap), with the ratio zeta that gives the
// restitution: for the linear law solved for the step (h = dt sqrt(kn/m*)),
// for Hertz that of the continuous law. A fixed -damping is taken as it is.
double ContactSet::dampingPart(const Bodies& b, const ContactList& l, std::size_t k) const {
  const PairLaw& law = laws_[l.law[k]];
  if (law.damping >= 0) return law.damping;
  const double meff = 1.0 / (b.invMass[l.a[k]] + b.invMass[l.b[k]]);
  if (law.hertz)
    return 2.0 * dampingRatios_.hertz(law.restitution, law.compressive) * std::sqrt(meff);
  const double h = dampingDt_ * std::sqrt(law.kn / meff);
  return 2.0 * dampingRatios_.linear(law.restitution, law.compressive, h) *
         std::sqrt(meff * law.kn);
}

// The pair build gives each contact its law (prepareContact); its damping
// and mode are set here, for the step, and kept until the next build or
// change of step (sim configure -timestep, -substeps, a lattice's).
void ContactSet::prepareDamping(const Bodies& b, const MaterialTable& materials,
                                std::uint64_t generation, double dt) {
  if (dt == dampingDt_ && builds_ == dampingBuild_ && generation == dampingGeneration_ &&
      materials.version() == dampingMaterials_)
    return;
  dampingDt_ = dt, dampingBuild_ = builds_, dampingGeneration_ = generation;
  dampingMaterials_ = materials.version();
  ContactList& l = list_;
  for (std::size_t k = 0; k < l.size(); ++k) {
    const PairLaw& law = laws_[l.law[k]];
    const double meff = 1.0 / (b.invMass[l.a[k]] + b.invMass[l.b[k]]);
    l.dampingPart[k] = dampingPart(b, l, k);
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
