// Wall and periodic kinds: after a step, write the slots that fluid nodes
// read their inputs from next step. Links never read a slot that another link
// writes (they read fluid nodes' outputs only), so their order does not matter.
#include "sandflow/core/parallel.hpp"
#include "sandflow/lb/node.hpp"

namespace sf::lb {

void LinkNode::resolve(const Slots& slots) {
  for (const Layout layout : {Layout::collided, Layout::streamed}) {
    std::vector<SlotCopy>& copies = copies_[int(layout)];
    copies.clear();
    copies.reserve(links.size());
    for (const Link& l : links)
      copies.push_back(
          {slots.input(layout, l.in, l.node), slots.post(layout, l.out, l.from), l.add});
  }
}

void LinkNode::fill(double* f, Layout layout, int threads) const {
  // On several threads when there are enough: the slots are scattered over
  // the lattice's edges, each a wait on memory, and the waits overlap.
  const std::vector<SlotCopy>& copies = copies_[int(layout)];
  const std::ptrdiff_t n = std::ptrdiff_t(copies.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (n >= parallel::kLinks)
  for (std::ptrdiff_t k = 0; k < n; ++k) f[copies[k].dst] = f[copies[k].src] + copies[k].add;
}

}  // namespace sf::lb
