#include "contact_force.hpp"

#include "sandflow/dem/narrow_phase.hpp"

namespace sf::dem::detail {

void evaluateOthers(ContactList& l, std::size_t begin, std::size_t end, const ContactInputs& in) {
  ContactHistory& next = l.history[1 - l.current];
  for (std::size_t k = begin; k < end; ++k) {
    const int i = l.a[k], j = l.b[k];
    Manifold m;
    // Disc pairs (Hertz) skip the dispatch (reach is a disc's radius).
    const bool hit = l.discs[k] ? collideDiscs(in.x[i], in.reach[i], in.x[j], in.reach[j], m)
                                : collide(*in.shape[i], {in.x[i], in.angle[i]}, *in.shape[j],
                                          {in.x[j], in.angle[j]}, m);
    next.touching[k] = hit;
    if (!hit) {
      next.nx[k] = l.now().nx[k], next.ny[k] = l.now().ny[k];
      next.sx[k] = next.sy[k] = 0;
      l.fx[k] = l.fy[k] = 0;
      continue;
    }
    LawInput c = lawInput(l, k, in);
    c.nx = m.normal.x(), c.ny = m.normal.y(), c.overlap = m.overlap;
    c.px = m.point.x(), c.py = m.point.y();
    const LawOutput f = contactLaw(c);
    next.nx[k] = c.nx, next.ny[k] = c.ny, next.sx[k] = f.sx, next.sy[k] = f.sy;
    l.fx[k] = f.fx, l.fy[k] = f.fy, l.px[k] = c.px, l.py[k] = c.py, l.overlap[k] = c.overlap;
  }
}

}  // namespace sf::dem::detail
