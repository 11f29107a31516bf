#pragma once
// The fluid-solid coupling of one step (physics.md §3 and §5): before the
// lattice step, the cells the elements and the lattice's circular walls cover,
// with their solid ratio and solid velocity; after it, the momentum each cell
// exchanged summed back, as force and torque, to whatever covers it.
#include <cstdint>
#include <string>
#include <vector>

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

struct CouplingTimes {
  double coverage = 0, forces = 0;  // seconds, accumulated
};

class Coupler {
 public:
  // True when the scene has anything that covers lattice cells.
  static bool needed(const lb::Lattice& lattice, const dem::Assembly& assembly);

  // Covers the lattice for the next step. Only what moved since the last call is
  // measured again. Nothing in the scene changes until setCoveredCells at the end.
  void prepare(lb::Lattice& lattice, const dem::Assembly& assembly, const Settings& settings,
               const Vec2& gravity, int threads);
  // After the lattice step: the fluid force and torque on every element (and
  // the buoyancy, for `gravity`), and the load on every circular wall.
  void collect(lb::Lattice& lattice, dem::Assembly& assembly, const Settings& settings,
               const Vec2& gravity);
  // Forgets the cached coverage (and zeroes the fluid forces) when the lattice goes.
  void clear(dem::Assembly& assembly);

  const SolidSpeed& fastest() const { return fastest_; }
  std::size_t coveredCells() const { return cells_; }
  const CouplingTimes& times() const { return times_; }

 private:
  struct Piece {         // one solid's share of one cell
    std::int32_t cell;   // index into the lattice's covered cells
    std::int32_t owner;  // element slot, or -1 - circle index
    double eps;
    Vec2 arm;
    bool interior;  // interior of this solid (see CellCover)
  };
  struct Cached {  // the coverage of one solid at the pose it was measured at
    int id = -1;
    Vec2 x = Vec2::Zero();
    double angle = 0, area = 0, reach = 0, radius = 0;
    bool outside = false;
    std::vector<CellCover> cells;
  };
  // The solid velocity of the cell whose pieces are order_[first, last) and
  // whose coverages sum to epsSum, lattice units: the coverage-weighted mean of
  // its owners' rigid velocities at the cell centre.
  Vec2 cellVelocity(std::ptrdiff_t first, std::ptrdiff_t last, double epsSum,
                    const std::vector<lb::CircleObstacle>& circles, double toLattice) const;
  void blendVelocities(const lb::Lattice& lattice, const std::vector<lb::CircleObstacle>& circles,
                       std::vector<lb::CoveredCell>& cells) const;
  void solveVelocities(const lb::Lattice& lattice, const dem::Assembly& assembly,
                       const Settings& settings, const std::vector<lb::CoveredCell>& cells,
                       const Vec2& gravity);
  void radixSort(std::vector<std::uint32_t>& keys, std::vector<std::int32_t>& order);
  void sortByNode();
  // How many solids cover covered cell c (its pieces).
  int sharing(std::int32_t c) const { return cellStart_[c + 1] - cellStart_[c]; }
  bool stale(const Cached& c, int id, const Vec2& x, double angle, double area, double reach,
             double radius, bool outside) const;

  std::vector<Cached> elements_, circles_;
  std::vector<std::uint8_t> open_;       // per cell: bulk fluid (Grid::open), per topology
  std::vector<Piece> pieces_;            // solid by solid, each solid's in its own order
  std::vector<std::size_t> pieceStart_;  // per solid (elements, then circles): first piece
  std::vector<std::int32_t> order_;      // pieces in node order
  std::vector<std::uint32_t> keys_;      // per piece its node; after sortByNode, in node order
  std::vector<std::int32_t> orderScratch_, bucketStart_;  // the sort's buffers
  std::vector<std::uint32_t> keysScratch_, sortedKeys_, runKeys_;
  std::vector<std::int32_t> runFirst_, runOrder_;  // runs of consecutive nodes
  static constexpr std::ptrdiff_t kChunk = 8192;   // pieces or cells a parallel task takes
  std::vector<std::int32_t> chunkCells_;           // per chunk of sorted pieces: cells before it
  std::vector<std::pair<double, std::int32_t>> chunkFastest_;  // per chunk of cells: |u|^2, cell
  std::vector<std::int32_t> cellStart_;  // per covered cell: its first entry in order_
  std::vector<double> epsSum_;           // per covered cell
  std::vector<Vec3> velocity_;           // per element: (vx, vy, w) the fluid sees
  // Kept from step to step (a fresh buffer would fault in its pages).
  std::vector<lb::CoveredCell> cellsBuffer_;
  int threads_ = 1;
  std::uint64_t topology_ = 0;
  Settings measuredWith_;
  std::size_t cells_ = 0;
  SolidSpeed fastest_;
  CouplingTimes times_;
};

}  // namespace sf::coupling
