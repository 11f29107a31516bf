#pragma once
// Each element's contacts, in the contact list's order (compressed rows: one
// run of entries per slot). The contact sums gather over it, one element at
// a time: each element adds its contacts' forces in list order, exactly as a
// serial pass down the list would, so the sums are the same bits on any
// number of threads, and no two threads write one element.
#include <cstdint>
#include <vector>

#include "sandflow/dem/contact_list.hpp"

namespace sf::dem {

struct ContactsByElement {
  // Slot s's entries are entry[start[s] .. start[s + 1]); an entry is 2 k for
  // contact k where s is its a, 2 k + 1 where s is its b.
  std::vector<std::uint32_t> start;
  std::vector<std::uint32_t> entry;
  // Indexes `l` for n slots (a counting sort: O(contacts + n)).
  void build(const ContactList& l, int n);
  bool empty() const { return start.empty(); }
};

}  // namespace sf::dem
