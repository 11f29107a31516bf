// Wall and periodic kinds: after the swap, write the slots that fluid nodes pull
// from. Links never read a slot that another link writes (they read fluid nodes
// only), so their order does not matter.
#include "sandflow/core/parallel.hpp"
#include "sandflow/lb/node.hpp"

namespace sf::lb {

void LinkNode::fill(double* f, int threads) const {
  // On several threads when there are enough: the slots are scattered over
  // the lattice's edges, each a wait on memory, and the waits overlap.
  const std::ptrdiff_t n = std::ptrdiff_t(links.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (n >= parallel::kLinks)
  for (std::ptrdiff_t k = 0; k < n; ++k) f[links[k].dst] = f[links[k].src] + links[k].add;
}

}  // namespace sf::lb
