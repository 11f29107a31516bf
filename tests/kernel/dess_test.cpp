// The DESS broad phase returns exactly the pairs a brute-force test returns.
#include <gtest/gtest.h>

#include <random>

#include "sandflow/dem/dess.hpp"

namespace sf::dem {
namespace {

std::vector<std::pair<int, int>> bruteForce(const std::vector<Box>& boxes) {
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < int(boxes.size()); ++i)
    for (int j = i + 1; j < int(boxes.size()); ++j)
      if (boxes[i].overlaps(boxes[j])) pairs.emplace_back(i, j);
  return pairs;
}

TEST(Dess, MatchesBruteForceOnTenThousandConfigurations) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  Dess dess;
  std::vector<Box> boxes;
  std::vector<std::pair<int, int>> pairs;
  for (int config = 0; config < 10000; ++config) {
    // Every 50 configurations a fresh scene of mixed shapes and sizes; in
    // between, small coherent moves, and now and then an element leaves or
    // enters (the DESS order is then rebuilt).
    if (config % 50 == 0 || u(rng) < 0.02) {
      const int n = 2 + int(u(rng) * 60);
      boxes.clear();
      dess.reset();
      for (int k = 0; k < n; ++k) {
        const double kind = u(rng);
        Vec2 c(u(rng), u(rng)), half;
        if (kind < 0.6)
          half = Vec2::Constant(0.01 + 0.05 * u(rng));  // grains
        else if (kind < 0.8)
          half = Vec2(0.5 * u(rng), 0.001 * u(rng));  // horizontal walls
        else
          half = Vec2(0.001 * u(rng), 0.5 * u(rng));  // vertical walls
        if (u(rng) < 0.2) c = Vec2(std::round(c.x() * 10) / 10, std::round(c.y() * 10) / 10);
        boxes.push_back({c - half, c + half});
      }
      if (u(rng) < 0.3) boxes.push_back(boxes[0]);  // an exact duplicate: ties everywhere
    } else {
      for (Box& b : boxes) {
        const Vec2 d = 0.01 * Vec2(u(rng) - 0.5, u(rng) - 0.5);
        b.lo += d;
        b.hi += d;
      }
    }
    dess.findPairs(boxes, pairs);
    ASSERT_EQ(pairs, bruteForce(boxes)) << "configuration " << config;
  }
}

TEST(Dess, TouchingBoxesCount) {
  Dess dess;
  std::vector<Box> boxes = {{Vec2(0, 0), Vec2(1, 1)}, {Vec2(1, 1), Vec2(2, 2)}};
  std::vector<std::pair<int, int>> pairs;
  dess.findPairs(boxes, pairs);
  EXPECT_EQ(pairs.size(), 1u);
}

}  // namespace
}  // namespace sf::dem
