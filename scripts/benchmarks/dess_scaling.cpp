// Cost of the DESS broad phase against the number of elements, for coherent
// motion (every element moves a little between calls), in a dense 2D packing
// with mixed sizes. Prints N, microseconds per call, nanoseconds per element
// and the log-log slope between successive N.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include "sandflow/dem/dess.hpp"

using namespace sf;
using namespace sf::dem;

int main() {
  std::printf("%10s %12s %12s %8s\n", "N", "us/call", "ns/element", "slope");
  double previousN = 0, previousT = 0;
  for (int n : {1000, 4000, 16000, 64000, 256000, 1024000}) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(0, 1);
    const int side = int(std::ceil(std::sqrt(double(n))));
    std::vector<Box> boxes(n);
    std::vector<Vec2> centre(n);
    std::vector<double> radius(n);
    for (int i = 0; i < n; ++i) {
      radius[i] = 0.5 + 0.5 * u(rng);  // mixed sizes, pitch 2.05
      centre[i] = Vec2((i % side) * 2.05 + 0.1 * u(rng), (i / side) * 2.05 + 0.1 * u(rng));
    }
    Dess dess;
    std::vector<std::pair<int, int>> pairs;
    auto update = [&] {
      for (int i = 0; i < n; ++i) {
        centre[i] += Vec2(0.01 * (u(rng) - 0.5), 0.01 * (u(rng) - 0.5));
        const Vec2 r(radius[i] + 0.1, radius[i] + 0.1);
        boxes[i] = {centre[i] - r, centre[i] + r};
      }
    };
    update();
    dess.findPairs(boxes, pairs);  // first sort
    const int calls = std::max(3, 2000000 / n);
    double seconds = 0;
    for (int c = 0; c < calls; ++c) {
      update();
      const auto t0 = std::chrono::steady_clock::now();
      dess.findPairs(boxes, pairs);
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    const double t = seconds / calls;
    const double slope = previousN > 0 ? std::log(t / previousT) / std::log(n / previousN) : 0;
    std::printf("%10d %12.1f %12.1f %8.2f\n", n, t * 1e6, t * 1e9 / n, slope);
    previousN = n, previousT = t;
  }
  return 0;
}
