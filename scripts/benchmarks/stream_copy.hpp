#pragma once
// STREAM-style copy bandwidth, the memory roofline of the lattice benchmarks:
// two arrays of doubles far larger than the last-level cache, OpenMP over the
// given thread counts, best of several repetitions, 16 bytes counted per
// element as STREAM does. Plain stores (a store to a line not in cache first
// reads it, as the lattice's own stores do) and non-temporal stores.
#include <omp.h>

#if defined(__x86_64__) || defined(__SSE2__)
#include <emmintrin.h>
#define SF_BENCH_SSE2 1
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <vector>

namespace sf::bench {

struct Bandwidth {
  double copy = 0.0;    // GB/s, plain stores
  double copyNt = 0.0;  // GB/s, non-temporal stores
};
inline std::map<int, Bandwidth> bandwidth;  // by thread count

inline double* allocate(std::size_t n) {
  void* p = std::aligned_alloc(64, (n * sizeof(double) + 63) / 64 * 64);
  if (!p) {
    std::fprintf(stderr, "benchmark: cannot allocate %zu MB\n", n * sizeof(double) >> 20);
    std::exit(1);
  }
  return static_cast<double*>(p);
}

// One copy c = a with `threads` threads; each thread copies a contiguous block,
// as `omp for schedule(static)` would hand it. Explicit SSE2 loads and stores keep
// the compiler from turning the loop into a memcpy call (which would pick its own
// store kind).
inline void copyOnce(const double* a, double* c, std::size_t n, int threads, bool nt) {
#pragma omp parallel num_threads(threads)
  {
    const std::size_t id = omp_get_thread_num(), nt_ = omp_get_num_threads();
    const std::size_t lo = n * id / nt_ / 8 * 8,
                      hi = id + 1 == nt_ ? n : n * (id + 1) / nt_ / 8 * 8;
#ifdef SF_BENCH_SSE2
    if (nt) {
      for (std::size_t i = lo; i < hi; i += 2) _mm_stream_pd(c + i, _mm_load_pd(a + i));
      _mm_sfence();
    } else {
      for (std::size_t i = lo; i < hi; i += 2) _mm_store_pd(c + i, _mm_load_pd(a + i));
    }
#else
    (void)nt;
    for (std::size_t i = lo; i < hi; ++i) c[i] = a[i];
#endif
  }
}

inline void measureBandwidth(std::size_t megabytes, int reps,
                             const std::vector<int>& threadCounts) {
  const std::size_t n = megabytes * (1u << 20) / sizeof(double) / 8 * 8;
  double* a = allocate(n);
  double* c = allocate(n);
  const int maxThreads = *std::max_element(threadCounts.begin(), threadCounts.end());
#pragma omp parallel for schedule(static) num_threads(maxThreads)
  for (std::size_t i = 0; i < n; ++i) a[i] = 1.0, c[i] = 0.0;
  for (int t : threadCounts) {
    for (bool nt : {false, true}) {
      double best = 1e300;
      for (int r = 0; r < reps; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        copyOnce(a, c, n, t, nt);
        const auto t1 = std::chrono::steady_clock::now();
        best = std::min(best, std::chrono::duration<double>(t1 - t0).count());
      }
      volatile double sink = c[n / 3];  // keep the copies
      (void)sink;
      const double gbps = 2.0 * sizeof(double) * n / best / 1e9;
      (nt ? bandwidth[t].copyNt : bandwidth[t].copy) = gbps;
    }
  }
  std::free(a);
  std::free(c);
}

}  // namespace sf::bench
