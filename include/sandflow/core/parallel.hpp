#pragma once
// Where the step's work goes parallel, and on how many threads.
//
// Below each threshold a parallel region costs more than it saves, so the
// work runs on the calling thread whatever the thread count. Every region
// splits its work so that the result does not depend on the count (fixed
// blocks, fixed reduction order); tests/kernel/thread_determinism_test.cpp
// runs scenes at least twice each threshold to check it.
#include <cstddef>

#include "sandflow/core/assert.hpp"

namespace sf::parallel {

// Lattice nodes of one sweep (the bulk fluid, the covered cells' pass).
inline constexpr std::ptrdiff_t kLatticeNodes = 16384;
// Links filled after a lattice step (bounce-back, slip, periodic).
inline constexpr std::ptrdiff_t kLinks = 4096;
// Solids whose coverage the coupler measures (one task each).
inline constexpr std::ptrdiff_t kCoverSolids = 16;
// Covered cells one coupling task takes (the fastest-cell scan goes parallel
// above one chunk, the cell list above two quarter chunks).
inline constexpr std::ptrdiff_t kCellChunk = 8192;
// Covered cells whose solid velocities are blended in parallel.
inline constexpr std::ptrdiff_t kBlendCells = 16384;
// Solids (elements and circular walls) whose fluid loads are summed in parallel.
inline constexpr std::ptrdiff_t kLoadOwners = 64;
// Element slots integrated in parallel.
inline constexpr std::ptrdiff_t kIntegrateSlots = 2048;
// Candidate pairs whose contact forces are evaluated in parallel.
inline constexpr std::ptrdiff_t kContactPairs = 512;

// The threads for `work` items: `threads` from `threshold` on, else one.
inline int team(std::ptrdiff_t work, std::ptrdiff_t threshold, int threads) {
  SF_ASSERT(threshold > 0 && threads >= 1);
  return work >= threshold && threads > 1 ? threads : 1;
}

}  // namespace sf::parallel

namespace sf {

// The thread count a part of a scene (lattice, coupler, elements) runs on.
// A scene's Manager owns the one count and attaches it to its parts; a part
// on its own (tests, benchmarks) keeps one of its own. A copy (or a moved
// part) keeps the count it had, as its own.
class ThreadCount {
 public:
  ThreadCount() = default;
  ThreadCount(const ThreadCount& o) : own_(o.get()) {}
  ThreadCount& operator=(const ThreadCount& o) {
    own_ = o.get(), attached_ = nullptr;
    return *this;
  }
  void attach(const int* count) { attached_ = count; }
  void set(int count) { own_ = count < 1 ? 1 : count; }
  int get() const { return attached_ ? *attached_ : own_; }

 private:
  int own_ = 1;
  const int* attached_ = nullptr;
};

}  // namespace sf
