// Cost of the DESS broad phase against the number of elements, for coherent
// motion (every element moves a little between calls, near its own site), in
// a dense 2D packing with mixed sizes. Prints N, microseconds per call,
// nanoseconds per element, the log-log slope between successive N and the
// pairs found per element, then the least-squares slope of log(time) against
// log(N) over all N.
//
//   sandflow_dess_scaling ?--reps R? ?--max N?
//
//   --reps R  time R blocks of calls at each N and keep the fastest block's
//             mean (default 3): the machine may be shared
//   --max N   largest N (default 1,024,000)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

#include "sandflow/dem/dess.hpp"

using namespace sf;
using namespace sf::dem;

namespace {

double fitSlope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = double(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

int main(int argc, char** argv) {
  int reps = 3;
  long maxN = 1024000;
  for (int i = 1; i + 1 < argc; ++i) {
    if (!std::strcmp(argv[i], "--reps"))
      reps = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--max"))
      maxN = std::atol(argv[++i]);
  }
  std::printf("%10s %12s %12s %8s %10s\n", "N", "us/call", "ns/element", "slope", "pairs/N");
  double previousN = 0, previousT = 0;
  std::vector<double> ns, ts;
  for (int n : {1000, 4000, 16000, 64000, 256000, 1024000}) {
    if (n > maxN) break;
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(0, 1);
    const int side = int(std::ceil(std::sqrt(double(n))));
    std::vector<Box> boxes(n);
    std::vector<Vec2> centre(n), site(n);
    std::vector<double> radius(n);
    for (int i = 0; i < n; ++i) {
      radius[i] = 0.5 + 0.5 * u(rng);  // mixed sizes, pitch 2.05
      site[i] = Vec2((i % side) * 2.05, (i / side) * 2.05);
      centre[i] = site[i] + Vec2(0.1 * u(rng), 0.1 * u(rng));
    }
    Dess dess;
    std::vector<std::pair<int, int>> pairs;
    auto update = [&] {
      for (int i = 0; i < n; ++i) {
        // A step of up to 0.005 each way, kept within 0.1 of the element's
        // site: the packing looks the same after any number of calls, so
        // every N is timed on the same kind of state.
        const Vec2 d = centre[i] + Vec2(0.01 * (u(rng) - 0.5), 0.01 * (u(rng) - 0.5)) - site[i];
        centre[i] = site[i] + Vec2(std::clamp(d.x(), 0.0, 0.1), std::clamp(d.y(), 0.0, 0.1));
        const Vec2 r(radius[i] + 0.1, radius[i] + 0.1);
        boxes[i] = {centre[i] - r, centre[i] + r};
      }
    };
    update();
    dess.findPairs(boxes, pairs);  // first sort
    const int calls = std::max(3, 2000000 / n);
    double best = 1e300;
    for (int r = 0; r < reps; ++r) {
      double seconds = 0;
      for (int c = 0; c < calls; ++c) {
        update();
        const auto t0 = std::chrono::steady_clock::now();
        dess.findPairs(boxes, pairs);
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      }
      best = std::min(best, seconds / calls);
    }
    const double t = best;
    const double slope = previousN > 0 ? std::log(t / previousT) / std::log(n / previousN) : 0;
    std::printf("%10d %12.1f %12.1f %8.2f %10.2f\n", n, t * 1e6, t * 1e9 / n, slope,
                double(pairs.size()) / n);
    std::fflush(stdout);
    previousN = n, previousT = t;
    ns.push_back(n), ts.push_back(t);
  }
  if (ns.size() >= 2) std::printf("fit_slope=%.3f (least squares, all N)\n", fitSlope(ns, ts));
  return 0;
}
