#pragma once
// The fluid-solid coupling of one step (physics.md §3 and §5): before the
// lattice step, the cells the elements and the lattice's circular walls cover,
// with their solid ratio and solid velocity; after it, the momentum each cell
// exchanged summed back, as force and torque, to whatever covers it.
#include <cstdint>
#include <string>
#include <vector>

#include "sandflow/core/parallel.hpp"
#include "sandflow/core/profile.hpp"
#include "sandflow/coupling/coverage.hpp"
#include "sandflow/dem/assembly.hpp"
#include "sandflow/lb/lattice.hpp"

namespace sf::coupling {

using Vec3 = Eigen::Vector3d;

// How a cell covered by several solids shares its force: in proportion to each
// one's coverage (exact), or equally (the thesis's per-node counter).
enum class Share { coverage = 0, equal = 1 };
inline constexpr const char* shareNames[] = {"coverage", "equal", nullptr};

struct Settings {
  int subcells = kExact;  // solid ratio: kExact, or n x n subcell centres
  Share share = Share::coverage;
  bool buoyancy = true;             // static buoyancy -rho_f A g on immersed elements
  bool equilibriumInterior = true;  // interior cells at f^eq(rho, u_s) (see lb::CoveredNode)
  bool implicit = false;            // element velocity solved with its exchange (solveVelocities)
};

// The fastest solid surface over the fluid in the last `prepare`.
struct SolidSpeed {
  double mach = 0.0;  // |u_s| / c
  int element = -1;   // its element id, or -1
  int obstacle = -1;  // or its obstacle id
};

// The solids that met their own periodic image in the last `prepare`
// (selfOverlap): the first, by element or obstacle id, and how many.
struct SelfOverlap {
  int element = -1;   // its element id, or -1
  int obstacle = -1;  // or its obstacle id
  int axes = 0;       // selfOverlap's bits: 1 x, 2 y
  int count = 0;
};

class Coupler {
 public:
  // True when the scene has anything that may cover lattice cells (an element
  // wholly beyond a side that is not periodic does not).
  static bool needed(const lb::Lattice& lattice, const dem::Assembly& assembly);

  // Covers the lattice for the next step. Only what moved since the last call is
  // measured again. Nothing in the scene changes until setCoveredCells at the end.
  void prepare(lb::Lattice& lattice, const dem::Assembly& assembly, const Settings& settings,
               const Vec2& gravity);
  // After the lattice step: the fluid force and torque on every element (and
  // the buoyancy, for `gravity`), and the load on every circular wall.
  void collect(lb::Lattice& lattice, dem::Assembly& assembly, const Settings& settings,
               const Vec2& gravity);
  // Forgets the cached coverage (and zeroes the fluid forces) when the lattice goes.
  void clear(dem::Assembly& assembly);

  // Its own thread count, or its owner's once attached (sf::ThreadCount).
  void setThreads(int threads) { threads_.set(threads); }
  void attachThreads(const int* count) { threads_.attach(count); }

  const SolidSpeed& fastest() const { return fastest_; }
  const SelfOverlap& selfOverlapping() const { return overlap_; }
  // The explicit coupling's one-step feedback on element slot s as the last
  // `prepare` covered it (docs/coupling.md, Stability): r = rho_f A_int / m,
  // A_int the sum of B h^2 over its cells (the implicit solve's gain), or the
  // same with each cell's arm squared over its moment of inertia, the larger
  // of the two over its free degrees of freedom. 0 when held or uncovered.
  double explicitFeedback(const lb::Lattice& lattice, const dem::Bodies& b, int s) const;
  std::size_t coveredCells() const { return cells_; }
  // The last `prepare`'s covered cells by kind, and the cells of the solids it
  // measured again (those that moved, turned or changed; a disc that only
  // turned keeps its cells).
  struct CellCounts {
    std::size_t partial = 0;     // eps < 1
    std::size_t interior = 0;    // eps = 1 with eight such neighbours
    std::size_t remeasured = 0;  // of the solids measured again
  };
  const CellCounts& cellCounts() const { return counts_; }
  // The slow reference (tests): every solid measured and the cell list
  // rebuilt each step, nothing kept from the step before.
  void setRebuildEveryStep(bool on) { rebuildEveryStep_ = on; }
  // The profile prepare and collect record into (Stage::coverage*,
  // Stage::fluidForces): the owner's, once attached, else its own.
  void attachProfile(Profile* profile) { profile_.attach(profile); }
  const Profile& profile() const { return profile_.get(); }

 private:
  // A run: consecutive lattice nodes that one solid covers, cells
  // [first, first + length) of its coverage (a row of a disc, mostly).
  struct Run {
    std::uint32_t node;  // the first node
    std::int32_t first, length;
  };
  struct Cached {  // the coverage of one solid at the pose it was measured at
    int id = -1;
    Vec2 x = Vec2::Zero();
    double angle = 0, area = 0, reach = 0, radius = 0;
    bool outside = false;
    CellCovers cells;
    std::vector<Run> runs, before;  // its runs, and those of the pose before
    int overlap = 0;                // selfOverlap of its footprint
    bool runsChanged = true;        // in the last prepare: the list must be rebuilt
    bool measuredNow = false;       // in the last prepare: measured again
  };
  // A piece is one solid's share of one cell: its global index g numbers the
  // solids' cells solid by solid (elements, then circles), pieceStart_[o] + m
  // for cell m of owner o.
  const CellCover& piece(std::int32_t g) const {
    const std::int32_t o = pieceOwner_[g];
    return coverOf(o).cells[std::size_t(g) - pieceStart_[o]];
  }
  const Cached& coverOf(std::int32_t owner) const {
    return owner < std::int32_t(elements_.size()) ? elements_[owner]
                                                  : circles_[owner - elements_.size()];
  }
  // The solid velocity of the cell whose pieces are order_[first, last) and
  // whose coverages sum to epsSum, lattice units: the coverage-weighted mean of
  // its owners' rigid velocities at the cell centre.
  Vec2 cellVelocity(std::ptrdiff_t first, std::ptrdiff_t last, double epsSum,
                    const std::vector<lb::CircleObstacle>& circles, double toLattice) const;
  // An owner's rigid motion: velocity of its reference point and spin.
  struct Motion {
    Vec2 v;
    double w;
  };
  Motion ownerMotion(std::int32_t owner, const std::vector<lb::CircleObstacle>& circles) const;
  Vec2 ownerVelocity(std::int32_t owner, const Vec2& arm,
                     const std::vector<lb::CircleObstacle>& circles) const;
  void blendVelocities(const lb::Lattice& lattice, const std::vector<lb::CircleObstacle>& circles,
                       std::vector<lb::CoveredCell>& cells) const;
  void solveVelocities(const lb::Lattice& lattice, const dem::Assembly& assembly,
                       const Settings& settings, const std::vector<lb::CoveredCell>& cells,
                       const Vec2& gravity);
  void radixSort(std::vector<std::uint32_t>& keys, std::vector<std::int32_t>& order);
  void groupRuns();
  // `blendNow`: the explicit coupling's velocities, and lone runs' pieces
  // left out of order_, pieceCell_ and epsSum_ (see pieceCell_).
  void fillCells(const std::vector<lb::CircleObstacle>& circles, double toLattice, bool blendNow,
                 std::vector<lb::CoveredCell>& cells);
  // How many solids cover covered cell c (its pieces).
  int sharing(std::int32_t c) const { return cellStart_[c + 1] - cellStart_[c]; }
  // `turns`: whether the coverage depends on the angle (not for a disc).
  bool stale(const Cached& c, int id, const Vec2& x, double angle, double area, double reach,
             double radius, bool outside, bool turns) const;

  std::vector<Cached> elements_, circles_;
  std::vector<std::uint8_t> open_;        // per cell: bulk fluid (Grid::open), per topology
  std::vector<std::uint8_t> openChunks_;  // Grid::openChunks of open_
  std::vector<std::size_t> pieceStart_;   // per owner (elements, then circles): first piece
  // Per piece: its owner. With explicit coupling, only shared cells' pieces
  // (the rest have their owner in their run's).
  std::vector<std::int32_t> pieceOwner_;
  // Per piece: its covered cell. With explicit coupling, only shared cells'
  // pieces (and order_, epsSum_ only shared cells'): a lone run's cells are
  // runCell_ on, its pieces' coverages their cells' (fewer bytes a step).
  std::vector<std::int32_t> pieceCell_;
  // Every solid's runs, owner by owner (runOwner_, runKeys_: each one's owner
  // and first node), and their order by node (runOrder_).
  std::vector<Run> runs_;
  std::vector<std::int32_t> runOwner_, runOrder_;
  std::vector<std::int32_t> runStart_;  // per owner: its first run in runs_
  std::vector<std::int32_t> runCell_;   // per run: its first covered cell when alone, else -1
  std::vector<std::uint32_t> runKeys_;
  // Runs laid end to end in node order form groups: a run alone, whose cells
  // are its own, or runs whose nodes overlap (cells several solids share),
  // whose pieces are sorted one by one into groupPieces_.
  struct Group {
    std::int32_t run;         // the run, or -1 - the first of its pieces in groupPieces_
    std::int32_t pieces;      // how many pieces
    std::int32_t firstCell;   // its first covered cell, and its first entry in order_
    std::int32_t firstEntry;  // (the pieces in node order)
  };
  std::vector<Group> groups_;
  std::vector<std::pair<std::uint32_t, std::int32_t>> groupPieces_;  // shared groups': node, piece
  std::vector<std::int32_t> order_;  // pieces in node order, equal nodes in piece order
  // Per covered cell: its first entry in order_. With explicit coupling, only
  // shared cells and each lone run's first cell (sharing reads no other).
  std::vector<std::int32_t> cellStart_;
  std::vector<double> epsSum_;                            // per covered cell
  std::vector<Vec3> velocity_;                            // per element: (vx, vy, w) the fluid sees
  std::vector<std::int32_t> orderScratch_, bucketStart_;  // the radix sort's buffers
  std::vector<std::uint32_t> keysScratch_;
  struct Fastest {
    double u2 = 0;            // |u|^2 of its first fastest cell
    std::int32_t owner = -1;  // and that cell's (first) owner
  };
  std::vector<Fastest> chunkFastest_;   // per task
  std::vector<CellCounts> taskCounts_;  // per task of fillCells: partial, interior
  // Kept from step to step (a fresh buffer would fault in its pages).
  std::vector<lb::CoveredCell> cellsBuffer_;
  ThreadCount threads_;
  std::uint64_t topology_ = 0;
  Settings measuredWith_;
  std::size_t cells_ = 0;
  CellCounts counts_;
  bool rebuildEveryStep_ = false;
  bool listKept_ = false;  // the runs of the last prepare are still valid
  SolidSpeed fastest_;
  SelfOverlap overlap_;
  ProfileLink profile_;
};

}  // namespace sf::coupling
