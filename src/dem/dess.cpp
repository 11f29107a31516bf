#include "sandflow/dem/dess.hpp"

#include <algorithm>
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
  const int axis = density[1] < density[0] ? 1 : 0;
  if (int(order_.size()) != n) {
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

  const int other = 1 - axis;
  for (int k = 0; k < n; ++k) {
    const int i = order_[k];
    const Box& bi = boxes[i];
    const double upper = bi.hi[axis];
    for (int m = k + 1; m < n; ++m) {
      const int j = order_[m];
      const Box& bj = boxes[j];
      if (bj.lo[axis] > upper) break;
      ++checks_;
      if (bj.lo[other] <= bi.hi[other] && bi.lo[other] <= bj.hi[other])
        pairs.emplace_back(std::min(i, j), std::max(i, j));
    }
  }
  std::sort(pairs.begin(), pairs.end());
}

}  // namespace sf::dem
