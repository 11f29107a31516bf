#include "sandflow/dem/contacts_by_element.hpp"

#include <limits>

#include "sandflow/core/assert.hpp"

namespace sf::dem {

void ContactsByElement::build(const ContactList& l, int n) {
  const std::size_t nc = l.size();
  SF_ASSERT(nc < std::numeric_limits<std::uint32_t>::max() / 2);
  start.assign(std::size_t(n) + 1, 0);
  const int* a = l.a.data();
  const int* b = l.b.data();
  for (std::size_t k = 0; k < nc; ++k)
    ++start[std::size_t(a[k]) + 1], ++start[std::size_t(b[k]) + 1];
  for (int s = 0; s < n; ++s) start[std::size_t(s) + 1] += start[std::size_t(s)];
  entry.resize(2 * nc);
  // Each slot's cursor walks its run from its start; contacts come in list
  // order, so each run is in list order.
  std::vector<std::uint32_t> cursor(start.begin(), start.end() - 1);
  for (std::size_t k = 0; k < nc; ++k) {
    entry[cursor[std::size_t(a[k])]++] = std::uint32_t(2 * k);
    entry[cursor[std::size_t(b[k])]++] = std::uint32_t(2 * k + 1);
  }
}

}  // namespace sf::dem
