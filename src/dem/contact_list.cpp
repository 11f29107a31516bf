#include "sandflow/dem/contact_list.hpp"

namespace sf::dem {

void ContactList::resize(std::size_t n) {
  for (auto* c : {&a, &b, &idA, &idB, &law}) c->resize(n);
  discs.resize(n);
  for (auto* c :
       {&dampingPart, &minSize, &radius, &normalFloor, &fx, &fy, &px, &py, &overlap, &ta, &tb})
    c->resize(n);
  spanned.resize(n);
  for (ContactHistory& h : history) {
    h.touching.resize(n);
    for (auto* c : {&h.nx, &h.ny, &h.sx, &h.sy}) c->resize(n);
  }
}

}  // namespace sf::dem
