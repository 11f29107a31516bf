// Wall and periodic kinds: after the swap, write the slots that fluid nodes pull
// from. Links never read a slot that another link writes (they read fluid nodes
// only), so their order does not matter.
#include "sandflow/lb/node.hpp"

namespace sf::lb {

void LinkNode::fill(double* f) const {
  for (const Link& l : links) f[l.dst] = f[l.src] + l.add;
}

}  // namespace sf::lb
