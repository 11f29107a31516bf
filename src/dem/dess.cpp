#include "sandflow/dem/dess.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sf::dem {

void Dess::findPairs(const std::vector<Box>& boxes, std::vector<std::pair<int, int>>& pairs) {
  pairs.clear();
  checks_ = 0;
  const int n = int(boxes.size());
  if (n < 2) return;

  // Sort along the axis where a box's range holds the fewest lower ends on
  // average: mean extent over the spread of the lower ends.
  double extent[2] = {0, 0}, lo[2] = {boxes[0].lo.x(), boxes[0].lo.y()}, hi[2] = {lo[0], lo[1]};
  for (const Box& b : boxes)
    for (int a = 0; a < 2; ++a) {
      extent[a] += b.hi[a] - b.lo[a];
      lo[a] = std::min(lo[a], b.lo[a]);
      hi[a] = std::max(hi[a], b.lo[a]);
    }
  const double density[2] = {extent[0] / std::max(hi[0] - lo[0], 1e-300),
                             extent[1] / std::max(hi[1] - lo[1], 1e-300)};
  // Keep the axis unless the other is clearly better: a new axis means a full
  // sort (insertion sort from another axis's order would be O(N^2)).
  int axis = axis_;
  if (density[1 - axis_] < 0.8 * density[axis_]) axis = 1 - axis_;
  if (int(order_.size()) != n || axis != axis_) {
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), 0);
    std::sort(order_.begin(), order_.end(),
              [&](int a, int b) { return boxes[a].lo[axis] < boxes[b].lo[axis]; });
  }
  axis_ = axis;

  // Insertion sort: cheap when elements moved little since the last call.
  for (int k = 1; k < n; ++k) {
    const int e = order_[k];
    const double key = boxes[e].lo[axis];
    int m = k - 1;
    while (m >= 0 && boxes[order_[m]].lo[axis] > key) {
      order_[m + 1] = order_[m];
      --m;
    }
    order_[m + 1] = e;
  }

  // Sweeping one axis alone costs O(N^1.5) on a square domain (each box's
  // range on the sweep axis holds a whole column). So the other axis is cut
  // into strips about two typical boxes wide; each strip's list, read off the
  // sorted order, is sorted too, and a box scans only its own strips. A pair
  // that shares several strips is reported in the strip holding the higher of
  // its two lower ends: exactly once.
  const int other = 1 - axis;
  std::vector<double> width(n);
  double lowest = boxes[0].lo[other];
  for (int i = 0; i < n; ++i) {
    width[i] = boxes[i].hi[other] - boxes[i].lo[other];
    lowest = std::min(lowest, boxes[i].lo[other]);
  }
  std::nth_element(width.begin(), width.begin() + n / 2, width.end());
  double stripWidth = 2 * width[n / 2];
  double highest = lowest;
  for (const Box& b : boxes) highest = std::max(highest, b.hi[other]);
  if (!(stripWidth > 0) || (highest - lowest) / stripWidth > n) stripWidth = (highest - lowest) / n;
  if (!(stripWidth > 0)) stripWidth = 1;
  // Boxes spread beyond what a double spans (one at 1e308, one at -1e308)
  // share one strip: correct, and no index overflows.
  const bool one = !std::isfinite((highest - lowest) / stripWidth);
  const int strips = one ? 1 : int((highest - lowest) / stripWidth) + 1;
  auto strip = [&](double v) {
    return one ? 0 : std::min(strips - 1, int((v - lowest) / stripWidth));
  };
  members_.resize(strips);
  for (std::vector<int>& m : members_) m.clear();  // keeps each strip's capacity
  for (int k = 0; k < n; ++k) {
    const int e = order_[k];
    for (int s = strip(boxes[e].lo[other]), last = strip(boxes[e].hi[other]); s <= last; ++s)
      members_[s].push_back(e);
  }
  for (int s = 0; s < strips; ++s) {
    const std::vector<int>& list = members_[s];
    const int m = int(list.size());
    for (int k = 0; k < m; ++k) {
      const int i = list[k];
      const Box& bi = boxes[i];
      const double upper = bi.hi[axis];
      for (int q = k + 1; q < m; ++q) {
        const int j = list[q];
        const Box& bj = boxes[j];
        if (bj.lo[axis] > upper) break;
        ++checks_;
        if (bj.lo[other] <= bi.hi[other] && bi.lo[other] <= bj.hi[other] &&
            strip(std::max(bi.lo[other], bj.lo[other])) == s)
          pairs.emplace_back(std::min(i, j), std::max(i, j));
      }
    }
  }
  sortPairs(n, pairs);
}

// The pairs come strip by strip: counted by their first slot into place, then
// each slot's few partners sorted (O(pairs + N), where a sort of all pairs
// cost more than the sweep).
void Dess::sortPairs(int n, std::vector<std::pair<int, int>>& pairs) {
  start_.assign(std::size_t(n) + 1, 0);
  for (const auto& p : pairs) ++start_[p.first + 1];
  for (int i = 0; i < n; ++i) start_[i + 1] += start_[i];
  sorted_.resize(pairs.size());
  for (const auto& p : pairs) sorted_[start_[p.first]++] = p;
  for (int i = n; i > 0; --i) start_[i] = start_[i - 1];  // back to each slot's first
  start_[0] = 0;
  for (int i = 0; i < n; ++i)
    std::sort(sorted_.begin() + start_[i], sorted_.begin() + start_[i + 1]);
  pairs.swap(sorted_);
}

}  // namespace sf::dem
