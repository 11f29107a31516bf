#pragma once
// Linear spring-dashpot contacts between discs, the commonest pair of a bed,
// evaluated many at a time: the narrow phase inline and the shared law
// (contact_force.hpp), without branches, so that the compiler runs several
// contacts in one vector register. IEEE arithmetic rounds each lane as scalar
// code would: the results do not depend on the instruction set.
#include <cstddef>

#include "contact_force.hpp"

namespace sf::dem::detail {

// The pair-law table in columns (a gather takes one double per lane).
struct LawColumns {
  const double *kn, *ks, *friction;
};

// Contacts [begin, end) of the list's linear disc pairs, touching or not: the
// next history and the results. Returns the first that stops the step (see
// stops), or `end`.
std::size_t linearDiscContacts(ContactList& l, std::size_t begin, std::size_t end,
                               const ContactInputs& in, const LawColumns& laws);

}  // namespace sf::dem::detail
