#pragma once
// Broad phase by double-ended spatial sorting (DESS, Perkins & Williams 2001).
// Elements stay sorted by the lower end of their bounding box along one axis
// (insertion sort from the previous order: near O(N) when the order changes
// little). Every overlapping pair has the lower end of one box inside the
// other's range on that axis, so scanning forward from each element's own lower
// end to its upper end finds each pair exactly once, whatever the mix of sizes:
// a long wall pays for its own range, small grains do not pay for the wall.
// The scan runs within strips of the other axis, which keeps it O(N) when
// the domain is wide in both directions.
#include <utility>
#include <vector>

#include "sandflow/dem/shape.hpp"

namespace sf::dem {

class Dess {
 public:
  // All pairs (i < j, slots) whose closed boxes overlap, sorted: exactly the
  // set an O(N^2) test returns.
  void findPairs(const std::vector<Box>& boxes, std::vector<std::pair<int, int>>& pairs);
  // Forget the order (slots were renumbered).
  void reset() { order_.clear(); }
  int axis() const { return axis_; }
  long long lastChecks() const { return checks_; }

 private:
  void sortPairs(int n, std::vector<std::pair<int, int>>& pairs);

  std::vector<int> order_;
  std::vector<std::size_t> start_;           // sortPairs: per slot, its first pair
  std::vector<std::pair<int, int>> sorted_;  // sortPairs' output, swapped in
  std::vector<std::vector<int>> members_;    // per strip, sorted like order_
  int axis_ = 0;
  long long checks_ = 0;
};

}  // namespace sf::dem
