#pragma once
// The lattice-Boltzmann fluid: D2Q9 populations in structure-of-arrays storage
// on a grid padded by one node on each side, the node kinds acting on it, and
// the fields users read back, in physical units.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sandflow/core/assert.hpp"
#include "sandflow/core/byte_stream.hpp"
#include "sandflow/core/parallel.hpp"
#include "sandflow/core/profile.hpp"
#include "sandflow/lb/lattice_def.hpp"
#include "sandflow/lb/node.hpp"

namespace sf::lb {

// A fixed solid rectangle: nodes whose centres lie inside are solid; those that
// border fluid are bounce-back (or slip) nodes, the rest do no work.
struct RectObstacle {
  int id = 0;
  Vec2 lo = Vec2::Zero(), hi = Vec2::Zero();
  bool slip = false;
};

// A rigid circular wall of the lattice, solid inside the circle or, with
// `outside`, outside it (a container). It moves with `velocity` and turns at
// `spin`; the coupling pass covers its cells with the Noble-Torczynski operator
// and the exact solid ratio, and reports the load back (setCircleLoad).
struct CircleObstacle {
  int id = 0;
  Vec2 centre = Vec2::Zero();
  double radius = 0.0;
  bool outside = false;
  Vec2 velocity = Vec2::Zero();
  double spin = 0.0;
  // Of the last step: the fluid's force and torque (about the centre), cells covered.
  Vec2 force = Vec2::Zero();
  double torque = 0.0;
  std::size_t cells = 0;
};

struct ObstacleInfo {
  bool circle = false;  // which of the two shapes is filled in
  RectObstacle rect;
  CircleObstacle disc;
  std::size_t nodes = 0;      // solid nodes (rect) or covered cells (circle)
  Vec2 force = Vec2::Zero();  // force per unit thickness the fluid exerts on it
  double torque = 0.0;        // about the rectangle's or circle's centre
};

class Lattice {
 public:
  explicit Lattice(const ResolvedLattice& params);
  ~Lattice();
  Lattice(const Lattice&) = delete;
  Lattice& operator=(const Lattice&) = delete;

  const ResolvedLattice& params() const { return p_; }
  int nx() const { return p_.nx; }
  int ny() const { return p_.ny; }
  std::size_t nodes() const { return std::size_t(p_.nx) * p_.ny; }

  // Changes what may change on a live lattice (tau, viscosity, timestep, forcing,
  // walls, collision); the grid itself may not. Validated before anything changes.
  // The physical flow carries over: velocity, pressure and the viscous stress
  // (convertPopulations); a pressure side the change leaves alone keeps its
  // excess over the reference pressure c_s^2 rho0.
  // A change after which the flow would be faster than `machLimit` (or not
  // finite) is refused with nothing changed.
  void reconfigure(const ResolvedLattice& params, double machLimit = 0.3);

  // The time of the state (the clock velocity sides ramp by): each step adds
  // dt; the owner sets it to its own clock (a lattice made or loaded mid-run).
  double time() const { return time_; }
  void setTime(double t);
  // New values for a velocity side given by expressions (SideDef::values),
  // for the steps from now on; refused (sf::Error, nothing changed) when they
  // do not fit the side (checkSideValues). The command layer evaluates
  // expressions in $t before every step.
  void setSideValues(int side, std::vector<Vec2> values);

  // One step. On NaN or a Mach number above `machLimit` it throws sf::Error
  // (code "UNSTABLE ...") naming the node; with keepPrevious the state before
  // the step stays, else (in place) the step has been taken.
  StepStats step(double machLimit = 0.3);
  // Returns to the state before the last step (once; until anything else changes
  // the populations; with keepPrevious), for a coupled step whose solid part fails.
  void undoStep();
  // The profile its steps record into (Stage::lattice*): the owner's, once
  // attached, else its own.
  void attachProfile(Profile* profile) { profile_.attach(profile); }
  const Profile& profile() const { return profile_.get(); }
  // Its own thread count, or its owner's once attached (sf::ThreadCount).
  void setThreads(int threads);
  void attachThreads(const int* count) { threads_.attach(count); }
  int threads() const { return threads_.get(); }

  // Obstacles. Rects and circles share one id space.
  int addObstacle(const RectObstacle& rect);    // rect.id < 0: next free id
  int addCircle(const CircleObstacle& circle);  // circle.id < 0: next free id
  void deleteObstacle(int id);
  std::vector<int> obstacleIds() const;
  // True when a no-slip side, a no-slip rect or a circular wall bounds the
  // fluid: what BGK's tau-dependent wall position spoils (docs/lattice.md).
  bool hasNoSlipSurfaces() const;
  ObstacleInfo obstacleInfo(int id) const;  // throws if unknown
  const std::vector<CircleObstacle>& circles() const { return circles_; }
  const std::vector<RectObstacle>& rects() const { return obstacles_; }
  void setCircleLoad(std::size_t index, const Vec2& force, double torque, std::size_t cells);
  // Moves the circles by their velocity over dt (wrapping on periodic axes).
  void advanceCircles(double dt);

  // Cells covered by moving solids for the next step (bulk-fluid nodes only;
  // see CoveredNode), and the momentum each exchanged in the last step.
  void setCoveredCells(std::vector<CoveredCell> cells, bool equilibriumInterior);
  // The same, handing the previous list back in `cells` for reuse.
  // `inNodeOrder`: the caller vouches that the nodes ascend strictly (the
  // coupler's list does), which spares a pass over the list.
  void swapCoveredCells(std::vector<CoveredCell>& cells, bool equilibriumInterior,
                        bool inNodeOrder = false);
  const std::vector<CoveredCell>& coveredCells() const { return covered_.cells; }
  // Density and first moment (lattice units) of the populations that the
  // given cells will pull in the next step, before any collision.
  void pulledMoments(const std::vector<CoveredCell>& cells, std::vector<double>& rho,
                     std::vector<Vec2>& j) const;
  const std::vector<Vec2>& coveredExchange() const { return covered_.exchange; }
  // Changes whenever node kinds are rebuilt (walls, rect obstacles).
  std::uint64_t topologyVersion() const { return topology_; }
  // Padded index of interior node (i, j), as CoveredCell::node holds it.
  std::int64_t nodeIndex(int i, int j) const { return index(i, j); }
  // Solid ratio and solid velocity (physical units) at node (i, j) in the last step.
  double solidRatio(int i, int j) const;
  Vec2 solidVelocity(int i, int j) const;

  // Fields of interior node (i, j), 0 <= i < nx, 0 <= j < ny, physical units.
  NodeKind kind(int i, int j) const { return kind_[index(i, j)]; }
  double density(int i, int j) const;
  Vec2 velocity(int i, int j) const;
  double pressure(int i, int j) const;
  Vec2 position(int i, int j) const;
  // Density and velocity of the nx nodes of row j, exactly as density() and
  // velocity() give them, in one pass (pictures of large lattices).
  void rowFields(int j, double* rho, Vec2* u) const;
  // The same at the n nodes (columns[k], j) only (a view's pixels).
  void rowFields(int j, const int* columns, int n, double* rho, Vec2* u) const;
  // Nearest node to a point, or nullopt outside the lattice.
  std::optional<std::pair<int, int>> nodeAt(const Vec2& x) const;

  double mass() const;     // per unit thickness
  Vec2 momentum() const;   // per unit thickness
  double maxMach() const;  // |u|max / c over fluid nodes, now
  double lastStepMach() const { return lastMach_; }

  // Sets every fluid node to the equilibrium of the given density and velocity.
  void initialize(const std::function<void(const Vec2& x, double& rho, Vec2& u)>& field);

  // The post-collision populations f*_d (lattice units) of node (i, j), and of
  // every node, [(d * ny + j) * nx + i], 0 where no fluid is: the same
  // whichever layout the array is in (tests, checkpoints, hashes).
  double population(int direction, int i, int j) const;
  std::vector<double> populations() const;
  // Bytes held: the population array (two while keepPrevious), node kinds.
  std::size_t memoryBytes() const;
  // Whether a step writes another array and keeps the state before it, so
  // that undoStep can go back and a refused step changes nothing (the
  // Manager asks for it while elements can refuse a step after the fluid's).
  // Else the step streams in place: half the memory, no line read for
  // ownership, and a step that finds the flow unstable has still been taken.
  void keepPrevious(bool keep);
  bool keepsPrevious() const { return spare_ != nullptr; }
  const std::vector<std::unique_ptr<Node>>& kinds() const { return kinds_; }

  // The whole state, bit for bit (checkpoints): definition, obstacles, both
  // population arrays (solid nodes keep the values they had in each) and the
  // covered cells of the last step. `loadState` validates what it reads and
  // throws sf::Error "FORMAT ..." (or the definition's own error).
  void saveState(ByteWriter& out) const;
  static std::unique_ptr<Lattice> loadState(ByteReader& in);
  // Its invariants, checked afresh: finite populations at every node that
  // holds fluid, obstacle ids unique, covered cells on bulk-fluid nodes with
  // a solid ratio in (0, 1]. Empty when all hold.
  std::vector<std::string> validate() const;

 private:
  std::int64_t index(int i, int j) const {
    SF_ASSERT(i >= -1 && i <= p_.nx && j >= -1 && j <= p_.ny);  // the padding at most
    return std::int64_t(j + 1) * rowStride_ + (i + 1);
  }
  void rebuildTopology();
  // The velocity sides' nodes' velocities at time t (lattice units): their
  // profile, expressions' values and ramp.
  void imposeSides(double t);
  bool sidesVary() const;
  StepContext context() const { return contextFor(p_); }
  StepContext contextFor(const ResolvedLattice& params) const;
  // Rewrites the populations for `next` from the present parameters, keeping
  // the physical state (lattice_convert.cpp).
  void convertPopulations(const ResolvedLattice& next, double machLimit);
  // The post-collision populations of a node at rest in equilibrium at rho, u
  // (lattice units) under ctx's collision and forcing.
  static void collidedEquilibrium(const StepContext& ctx, double rho, const Vec2& u,
                                  double (&f)[9]);
  bool holdsFluid(std::int64_t node) const;
  void setNodeState(std::int64_t node, double rho, const Vec2& latticeU);
  Vec2 latticeVelocity(std::int64_t node) const;
  // Velocity (lattice units) from a node's moments: the forcing's half step out.
  Vec2 velocityFromMoments(double rho, double jx, double jy) const;
  // Density and first moment of node x's post-collision populations in the
  // array f of the given layout.
  void moments(const double* f, Layout layout, std::int64_t node, double& rho, double& jx,
               double& jy) const;
  // Throws the step's instability, naming the worst node of the state it made.
  [[noreturn]] void reportInstability(const StepStats& stats, double machLimit, const double* f,
                                      Layout layout) const;
  Slots slots() const { return {stride_, rowStride_}; }
  std::size_t populationSlots() const { return 9 * static_cast<std::size_t>(stride_); }
  // Writes the links' slots for the next step from the array's layout.
  void fill();

  ResolvedLattice p_;
  std::ptrdiff_t rowStride_ = 0, stride_ = 0;
  double* f_ = nullptr;      // the populations, 9 * stride_, in layout_ (node.hpp)
  double* spare_ = nullptr;  // the state before the last step, with keepPrevious
  Layout layout_ = Layout::collided;
  std::vector<double> coveredBuffer_;  // a step's covered cells' outputs, in place
  std::vector<NodeKind> kind_;         // per padded node
  std::vector<std::unique_ptr<Node>> kinds_;
  std::vector<RectObstacle> obstacles_;
  std::vector<CircleObstacle> circles_;
  CoveredNode covered_;
  std::uint64_t topology_ = 0;
  ThreadCount threads_;
  double lastMach_ = 0.0;
  double time_ = 0.0, timeBefore_ = 0.0;
  bool canUndo_ = false;
  ProfileLink profile_;
};

}  // namespace sf::lb
