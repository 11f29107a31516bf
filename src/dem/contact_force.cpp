#include "contact_force.hpp"

#include "sandflow/dem/narrow_phase.hpp"

namespace sf::dem::detail {

std::size_t evaluateOthers(ContactList& l, std::size_t begin, std::size_t end,
                           const ContactInputs& in) {
  ContactHistory& next = l.history[1 - l.current];
  std::size_t first = end;
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
      l.fx[k] = l.fy[k] = l.ta[k] = l.tb[k] = 0;
      continue;
    }
    LawInput c = lawInput(l, k, in);
    c.nx = m.normal.x(), c.ny = m.normal.y(), c.overlap = m.overlap;
    c.px = m.point.x(), c.py = m.point.y();
    const LawOutput f = contactLaw(c);
    next.nx[k] = c.nx, next.ny[k] = c.ny, next.sx[k] = f.sx, next.sy[k] = f.sy;
    l.fx[k] = f.fx, l.fy[k] = f.fy, l.px[k] = c.px, l.py[k] = c.py, l.overlap[k] = c.overlap;
    l.ta[k] = (c.px - c.xi) * f.fy - (c.py - c.yi) * f.fx;
    l.tb[k] = (c.px - c.xj) * f.fy - (c.py - c.yj) * f.fx;
    if (first == end && stops(c.overlap, l.minSize[k], f.fx, f.fy, in.maxOverlap)) first = k;
  }
  return first;
}

}  // namespace sf::dem::detail
