#pragma once
// Linear spring-dashpot contacts between discs, the commonest pair of a bed,
// evaluated many at a time: the same operations as evaluateContact
// (contact_force.hpp) in the same order, on plain doubles and without
// branches, so that the compiler runs several contacts in one vector
// register. IEEE arithmetic rounds each lane as the scalar code does: the
// results are the same bits.
#include <cstddef>

#include "contact_force.hpp"

namespace sf::dem::detail {

// The listed contacts' data in columns (a contact's fields are 128 bytes
// apart, too far for the processor's gather), filled by `stage`.
struct DiscPairs {
  int *a, *b;
  double *kn, *ks, *friction, *damping;
  double* touching;           // 1 if the contact has a history, else 0
  double *nx, *ny, *sx, *sy;  // last step's normal and shear spring
};

// One contact's results, in the order evaluateContact stores them.
struct DiscResults {
  double *nx, *ny, *px, *py, *overlap, *fx, *fy, *sx, *sy;
};

// Puts contact c at position q of the columns.
[[gnu::always_inline]] inline void stage(const Contact& c, const PairLaw* laws, const DiscPairs& p,
                                         std::ptrdiff_t q) {
  const PairLaw& law = laws[c.law];
  p.a[q] = c.a, p.b[q] = c.b;
  p.kn[q] = law.kn, p.ks[q] = law.ks, p.friction[q] = law.friction, p.damping[q] = c.damping;
  p.touching[q] = c.touching ? 1.0 : 0.0;
  p.nx[q] = c.normal.x(), p.ny[q] = c.normal.y(), p.sx[q] = c.shear.x(), p.sy[q] = c.shear.y();
}

// The step's normal, point, overlap, force and shear spring of the staged
// contacts [begin, end), all touching disc pairs with a linear law.
void linearDiscContacts(const DiscPairs& pairs, std::ptrdiff_t begin, std::ptrdiff_t end,
                        const ContactInputs& in, const DiscResults& out);

}  // namespace sf::dem::detail
