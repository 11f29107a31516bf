#pragma once
// The solid-ratio pass of physics.md §3: which lattice cells a footprint covers
// and by how much. Cells well inside get eps = 1 and cells well outside nothing
// without any area work (the cull); only cells the outline may cross are
// measured, exactly or by n x n subcell centres.
#include <cstdint>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include "sandflow/coupling/footprint.hpp"

namespace sf::coupling {

// The lattice as the pass sees it: cell (i, j) is the square of side h whose
// centre is origin + ((i + 1/2) h, (j + 1/2) h).
struct Grid {
  Vec2 origin = Vec2::Zero();
  double h = 1.0;
  int nx = 0, ny = 0;
  bool periodicX = false, periodicY = false;
  // Per cell (index j * nx + i), nonzero where coverage counts (bulk fluid);
  // every cell when null.
  const std::uint8_t* open = nullptr;
  // Optional, with `open`: per chunk of kOpenChunk cells of a row (index
  // openChunk(i, j)), nonzero where all its cells are open. Small enough to
  // stay in cache, so most cells are known open without reading `open`, whose
  // lines the lattice's sweep has evicted.
  const std::uint8_t* openChunks = nullptr;
  static constexpr int kOpenChunk = 64;
  int openChunksPerRow() const { return (nx + kOpenChunk - 1) / kOpenChunk; }
  std::size_t openChunk(int i, int j) const {
    return std::size_t(j) * openChunksPerRow() + i / kOpenChunk;
  }
  bool isOpen(int i, int j) const {
    if (!open) return true;
    if (openChunks && openChunks[openChunk(i, j)]) return true;
    return open[std::size_t(j) * nx + i] != 0;
  }
  // True when the chunks alone show cells lo..hi of row j (inside the
  // lattice) all open; false when some may not be.
  bool rowOpen(int lo, int hi, int j) const {
    if (!open) return true;
    if (!openChunks) return false;
    for (int i = lo / kOpenChunk * kOpenChunk; i <= hi; i += kOpenChunk)
      if (!openChunks[openChunk(i, j)]) return false;
    return true;
  }
};

// How a solid-ratio is measured: subcells 0 means exact areas, else the count
// of subcell centres inside out of n x n (n = 1 is the binarized stair-step).
inline constexpr int kExact = 0;

// 32 bytes: every covered cell's is written, then read twice, each step.
struct CellCover {
  Vec2 arm;                    // cell centre minus the footprint's reference point, unwrapped
  double eps;                  // covered fraction, (0, 1]
  std::int32_t i;              // cell, wrapped into the lattice
  std::int32_t j : 31;         // (rows fit 31 bits: the lattice's size limit is far below)
  std::uint32_t interior : 1;  // eps = 1 and so are its eight neighbours
};
static_assert(sizeof(CellCover) == 32);

// Storage whose new records are left unset, not zeroed: the pass writes each
// record whole right after taking its slot.
template <class T>
struct UnsetAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UnsetAllocator<U>;
  };
  UnsetAllocator() = default;
  template <class U>
  UnsetAllocator(const UnsetAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};
using CellCovers = std::vector<CellCover, UnsetAllocator<CellCover>>;

// Appends the cells that `f` covers. `reference` is the point arms are measured
// from (the element's centre). Periodic axes wrap; cells beyond a non-periodic
// edge are dropped.
void cover(const Footprint& f, const Vec2& reference, const Grid& grid, int subcells,
           CellCovers& out);

// The periodic axes (1: x, 2: y, 3: both) along which the footprint's box
// spans more cells than the lattice has: there the solid meets its own
// periodic image, which `cover` clips away rather than adds, so the cells of
// the overlap get wrong ratios (some deep inside get none). 0 when it fits.
int selfOverlap(const Footprint& f, const Grid& grid);

}  // namespace sf::coupling
