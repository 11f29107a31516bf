#pragma once
// Asks for the cache lines of [p, p + bytes) ahead of use: for the passes that
// visit records from places the hardware's prefetcher cannot guess (a solid's
// run of cells, a sweep block's few hundred covered cells), after the
// lattice's sweep has evicted them.
#include <cstddef>

namespace sf {

inline constexpr std::size_t kCacheLine = 64;

inline void prefetchForRead(const void* p, std::size_t bytes) {
  const char* c = static_cast<const char*>(p);
  for (std::size_t k = 0; k < bytes; k += kCacheLine) __builtin_prefetch(c + k, 0);
}

inline void prefetchForWrite(void* p, std::size_t bytes) {
  char* c = static_cast<char*>(p);
  for (std::size_t k = 0; k < bytes; k += kCacheLine) __builtin_prefetch(c + k, 1);
}

}  // namespace sf
