// Thread determinism above the parallel thresholds (issue 23): each scene is
// large enough that every parallel region of its step really runs on several
// threads, and 1, 2, 3 and 4 threads must give the same state, bit for bit --
// every population, every element's motion and loads, the contact list.
// Each scene first checks that it is above the thresholds it exists to cross,
// so that raising one later fails here instead of quietly testing nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "coupled_helpers.hpp"
#include "lattice_helpers.hpp"
#include "sandflow/core/error.hpp"
#include "sandflow/core/parallel.hpp"
#include "sandflow/lb/node.hpp"

namespace sf {
namespace {

// Every scene runs at least twice the thresholds it exists to cross
// (sandflow/core/parallel.hpp), so that no threshold can be raised past a
// scene without this test failing.
template <class Count>
void expectTwiceAbove(Count count, std::ptrdiff_t threshold, const char* what) {
  EXPECT_GE(std::ptrdiff_t(count), 2 * threshold) << what;
}

const std::vector<int> kThreadCounts = {1, 2, 3, 4};

// 64-bit FNV-1a over raw bytes.
class Fnv {
 public:
  void bytes(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < n; ++k) h_ = (h_ ^ p[k]) * 1099511628211ull;
  }
  void add(double v) { bytes(&v, sizeof v); }
  void add(std::int64_t v) { bytes(&v, sizeof v); }
  void add(const Vec2& v) { add(v.x()), add(v.y()); }
  template <class T>
  void add(const std::vector<T>& v) {
    for (const T& x : v) {
      if constexpr (std::is_same_v<T, Vec2> || std::is_same_v<T, double>)
        add(x);
      else
        add(std::int64_t(x));
    }
  }
  std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 14695981039346656037ull;
};

// A state's hashes, part by part (so that a mismatch says where), and of the whole.
struct StateHash {
  std::vector<std::pair<std::string, std::uint64_t>> parts;
  std::uint64_t whole = 0;
  template <class F>
  void part(const std::string& name, F&& feed) {
    Fnv f;
    feed(f);
    parts.emplace_back(name, f.value());
  }
  void finish() {
    Fnv f;
    for (const auto& [name, h] : parts) f.bytes(&h, sizeof h);
    whole = f.value();
  }
};

void hashLattice(const lb::Lattice& l, StateHash& s) {
  s.part("lattice populations", [&](Fnv& f) { f.add(l.populations()); });
  s.part("lattice covered cells", [&](Fnv& f) {
    for (const lb::CoveredCell& c : l.coveredCells()) {
      f.add(std::int64_t(c.node)), f.add(std::int64_t(c.interior));
      f.add(c.eps), f.add(c.ux), f.add(c.uy);
    }
    f.add(l.coveredExchange());
  });
  s.part("lattice obstacles", [&](Fnv& f) {
    for (int id : l.obstacleIds()) {
      const lb::ObstacleInfo o = l.obstacleInfo(id);
      f.add(std::int64_t(id)), f.add(std::int64_t(o.nodes)), f.add(o.force), f.add(o.torque);
    }
    for (const lb::CircleObstacle& c : l.circles()) {
      f.add(c.centre), f.add(c.velocity), f.add(c.spin);
      f.add(c.force), f.add(c.torque), f.add(std::int64_t(c.cells));
    }
  });
}

void hashAssembly(const dem::Assembly& a, StateHash& s) {
  const dem::Bodies& b = a.bodies();
  s.part("element ids", [&](Fnv& f) { f.add(b.id), f.add(b.started); });
  s.part("element positions", [&](Fnv& f) { f.add(b.x); });
  s.part("element velocities", [&](Fnv& f) { f.add(b.v), f.add(b.vHalf); });
  s.part("element angles", [&](Fnv& f) { f.add(b.angle); });
  s.part("element spins", [&](Fnv& f) { f.add(b.w), f.add(b.wHalf); });
  s.part("element forces", [&](Fnv& f) { f.add(b.force); });
  s.part("element torques", [&](Fnv& f) { f.add(b.torque); });
  s.part("element fluid loads",
         [&](Fnv& f) { f.add(b.fluidForce), f.add(b.fluidTorque), f.add(b.buoyancy); });
  const dem::ContactList& c = a.contactList();
  s.part("contact pairs", [&](Fnv& f) {
    f.add(std::int64_t(c.size())), f.add(std::int64_t(c.vectorCount));
    f.add(c.a), f.add(c.b), f.add(c.idA), f.add(c.idB), f.add(c.discs), f.add(c.law);
    f.add(c.dampingPart), f.add(c.minSize), f.add(c.radius);
  });
  s.part("contact history", [&](Fnv& f) {
    const dem::ContactHistory& h = c.now();
    f.add(h.touching), f.add(h.nx), f.add(h.ny), f.add(h.sx), f.add(h.sy);
  });
  s.part("contact forces", [&](Fnv& f) {
    f.add(c.fx), f.add(c.fy), f.add(c.px), f.add(c.py), f.add(c.overlap), f.add(c.ta), f.add(c.tb);
  });
}

StateHash hashManager(const sim::Manager& m) {
  StateHash s;
  s.part("clock", [&](Fnv& f) { f.add(m.time()), f.add(std::int64_t(m.stepCount())); });
  if (m.hasLattice()) hashLattice(m.lattice(), s);
  hashAssembly(m.assembly(), s);
  s.finish();
  return s;
}

// Every thread count's state against one thread's, part by part.
void expectSameStates(const std::vector<StateHash>& states) {
  ASSERT_EQ(states.size(), kThreadCounts.size());
  for (std::size_t t = 1; t < states.size(); ++t) {
    ASSERT_EQ(states[t].parts.size(), states[0].parts.size());
    for (std::size_t p = 0; p < states[0].parts.size(); ++p)
      EXPECT_EQ(states[t].parts[p].second, states[0].parts[p].second)
          << states[0].parts[p].first << " differ: " << kThreadCounts[t] << " threads vs 1";
    EXPECT_EQ(states[t].whole, states[0].whole) << kThreadCounts[t] << " threads vs 1";
  }
}

// Nodes (or links) of the lattice's kinds of this name.
std::size_t kindCount(const lb::Lattice& l, const char* kind) {
  std::size_t n = 0;
  for (const auto& k : l.kinds())
    if (std::string(k->name()) == kind) n += k->count();
  return n;
}

// --- 1. The lattice alone -------------------------------------------------

// A 1536 x 48 channel (73,728 nodes; its walls' 9,000-odd bounce-back links
// are filled in parallel too), periodic in x, the top wall moving, forced,
// with a no-slip and a free-slip obstacle, from a smooth disturbed state.
StateHash latticeState(int threads, lb::Collision collision, int steps, bool check) {
  lb::LatticeDef def = test::channelDef(1536, 48, 0.8);
  def.collision = collision;
  def.sides[lb::top] = lb::SideDef{lb::SideKind::noslip, Vec2(0.004, 0)};
  def.forcing = Vec2(2e-6, 1e-7);
  lb::Lattice lattice(lb::resolve(def));
  lattice.setThreads(threads);
  lattice.addObstacle({-1, Vec2(200, 10), Vec2(230, 30), false});
  lattice.addObstacle({-1, Vec2(600, 0), Vec2(640, 12), true});
  lattice.initialize([](const Vec2& x, double& rho, Vec2& u) {
    rho = 1.0 + 0.005 * std::sin(0.05 * x.x()) * std::cos(0.2 * x.y());
    u = Vec2(0.01 + 0.005 * std::sin(0.11 * x.y() + 0.03 * x.x()), 0.004 * std::cos(0.07 * x.x()));
  });
  if (check) {
    expectTwiceAbove(kindCount(lattice, "fluid"), parallel::kLatticeNodes, "fluid nodes");
    expectTwiceAbove(kindCount(lattice, "noslip"), parallel::kLinks, "bounce-back links");
    EXPECT_GE(kindCount(lattice, "periodic"), std::size_t(1));
    EXPECT_GE(kindCount(lattice, "slip"), std::size_t(1));
  }
  for (int s = 0; s < steps; ++s) lattice.step();
  StateHash h;
  hashLattice(lattice, h);
  h.finish();
  return h;
}

TEST(ThreadDeterminism, LatticeAboveParallelThresholds) {
  for (lb::Collision c : {lb::Collision::bgk, lb::Collision::trt}) {
    SCOPED_TRACE(c == lb::Collision::bgk ? "bgk" : "trt");
    std::vector<StateHash> states;
    for (int t : kThreadCounts) states.push_back(latticeState(t, c, 40, t == 1));
    expectSameStates(states);
  }
}

// --- 2. Fluid and elements ----------------------------------------------------

// A 256^2 lattice (65,536 nodes), periodic in x, walls below and above, forced,
// with 169 moving, spinning discs of 7 to 9 cells' radius in ten rows (neighbours
// in a row overlap a little: contacts) covering some 40,000 cells, a spinning
// circular wall among them, under gravity.
void coupledScene(sim::Manager& m, int threads, bool implicit) {
  m.setThreads(threads);
  lb::LatticeDef def = test::periodicSquare(1.0, 256, 0.01);
  def.sides[lb::bottom] = def.sides[lb::top] = lb::SideDef{lb::SideKind::noslip};
  const double h0 = 1.0 / 256, dt0 = h0 * h0 / (6 * 0.01);  // tau = 1
  def.forcing = Vec2(1e-5 * h0 / (dt0 * dt0), 0);           // 1e-5 in lattice units
  m.createLattice(def);
  coupling::Settings settings;
  settings.implicit = implicit;
  m.setCouplingSettings(settings);
  const lb::ResolvedLattice& p = m.lattice().params();
  const double h = p.h, c = p.latticeSpeed();
  m.setGravity(Vec2(0, -2e-4 * c / p.dt));
  dem::Material mat{"grain"};
  mat.density = 2.0;
  mat.kn = mat.ks = 100;
  mat.friction = 0.4;
  mat.restitution = 0.5;
  const int grain = m.assembly().materials().add(mat);
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(0, 1);
  const double pitch = 256.0 / 17;  // cells: neighbours of 7.5 cells' radius or more overlap
  for (int row = 0; row < 10; ++row)
    for (int k = 0; k < 17; ++k) {
      const Vec2 x = h * Vec2((k + 0.25 + 0.5 * (row % 2)) * pitch, 20 + 24 * row);
      const double r = h * (7 + 2 * u(rng));
      if (row == 4 && k == 8) {  // a circular wall in this place
        m.lattice().addCircle({-1, x, r, false, Vec2::Zero(), 0.02 * c / r});
        continue;
      }
      const Vec2 v = 0.02 * c * Vec2(u(rng) - 0.5, u(rng) - 0.5);
      test::addDisc(m, grain, x, r, v, 0.02 * c / r * (u(rng) - 0.5));
    }
}

StateHash coupledState(int threads, bool implicit, int steps, bool check) {
  sim::Manager m;
  coupledScene(m, threads, implicit);
  for (int s = 0; s < steps; ++s) {
    m.step();
    if (check && s == 0) {
      const int elements = m.assembly().bodies().size();
      const std::size_t cells = m.coupler().coveredCells();
      expectTwiceAbove(m.lattice().nodes(), parallel::kLatticeNodes, "fluid nodes");
      expectTwiceAbove(elements, parallel::kCoverSolids, "solids covering");
      expectTwiceAbove(elements + m.lattice().circles().size(), parallel::kLoadOwners,
                       "solids loaded");
      expectTwiceAbove(cells, parallel::kBlendCells, "covered cells blended");
      expectTwiceAbove(cells, parallel::kLatticeNodes, "covered cells collided");
      expectTwiceAbove(cells, parallel::kCellChunk, "covered cells scanned");
      EXPECT_GT(m.assembly().touchingCount(), std::size_t(0));
    }
  }
  return hashManager(m);
}

TEST(ThreadDeterminism, CoupledSceneAboveParallelThresholds) {
  std::vector<StateHash> states;
  for (int t : kThreadCounts) states.push_back(coupledState(t, false, 30, t == 1));
  expectSameStates(states);
}

TEST(ThreadDeterminism, ImplicitlyCoupledSceneAboveParallelThresholds) {
  std::vector<StateHash> states;
  for (int t : kThreadCounts) states.push_back(coupledState(t, true, 15, t == 1));
  expectSameStates(states);
}

// --- 3. Elements alone --------------------------------------------------------

// 4,160 discs in a box (80 x 52, staggered rows, neighbours overlapping a
// little: thousands of contacts from the first step), with small random
// velocities, settling under gravity.
void demBed(sim::Manager& m, int threads) {
  m.setThreads(threads);
  m.setGravity(Vec2(0, -9.81));
  dem::Assembly& a = m.assembly();
  dem::Material mat{"sand"};
  mat.kn = mat.ks = 1e5;
  mat.restitution = 0.3;
  mat.friction = 0.5;
  const int sand = a.materials().add(mat);
  const int columns = 80, rows = 52;
  const double pitch = 1.7e-3, W = (columns + 0.6) * pitch;
  auto wall = [&](Vec2 p, Vec2 q) {
    dem::ElementDef d;
    d.shape = std::make_unique<dem::Wall>((q - p).norm(), 1e-3);
    d.material = sand;
    d.x = 0.5 * (p + q);
    d.angle = std::atan2((q - p).y(), (q - p).x());
    d.hold = dem::holdX | dem::holdY | dem::holdRotation;
    a.add(std::move(d));
  };
  wall({0, 0}, {W, 0});
  wall({0, 0}, {0, 0.1});
  wall({W, 0}, {W, 0.1});
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  for (int row = 0; row < rows; ++row)
    for (int k = 0; k < columns; ++k) {
      dem::ElementDef d;
      d.shape = std::make_unique<dem::Disc>(0.7e-3 + 0.2e-3 * u(rng));
      d.material = sand;
      d.x = Vec2((k + 0.55 + 0.5 * (row % 2)) * pitch, 1e-3 + row * 0.85 * pitch);
      d.v = 0.05 * Vec2(u(rng) - 0.5, u(rng) - 0.5);
      d.w = 20 * (u(rng) - 0.5);
      a.add(std::move(d));
    }
}

StateHash demState(int threads, int steps, bool check) {
  sim::Manager m;
  demBed(m, threads);
  for (int s = 0; s < steps; ++s) {
    m.step();
    if (check && s == 0) {
      expectTwiceAbove(m.assembly().bodies().size(), parallel::kIntegrateSlots, "slots");
      expectTwiceAbove(m.assembly().contactList().size(), parallel::kContactPairs, "pairs");
      expectTwiceAbove(m.assembly().touchingCount(), parallel::kContactPairs, "contacts");
      // Disc-wall pairs beyond the vector pass, in more than one chunk of 64.
      EXPECT_GT(m.assembly().contactList().size() - m.assembly().contactList().vectorCount,
                std::size_t(64));
    }
  }
  return hashManager(m);
}

TEST(ThreadDeterminism, DemBedAboveParallelThresholds) {
  std::vector<StateHash> states;
  for (int t : kThreadCounts) states.push_back(demState(t, 40, t == 1));
  expectSameStates(states);
}

}  // namespace

// The kernel keeps the thread count in its range itself (sim configure checks
// the same constant first); a refused count leaves the one in force.
TEST(ThreadDeterminism, ThreadCountOutsideItsRangeIsRefused) {
  sim::Manager m;
  m.setThreads(2);
  for (const int bad : {0, -1, sim::Manager::kMaxThreads + 1}) {
    EXPECT_THROW(m.setThreads(bad), Error) << bad;
    EXPECT_EQ(m.threads(), 2);
  }
  m.setThreads(sim::Manager::kMaxThreads);
  EXPECT_EQ(m.threads(), sim::Manager::kMaxThreads);
}

}  // namespace sf

namespace sf {

// One count, the Manager's: its lattice, coupler and elements read it,
// whenever they were made, and after the Manager is moved (a checkpoint load).
TEST(ThreadDeterminism, PartsReadTheManagersOneCount) {
  sim::Manager m;
  m.setThreads(3);
  m.createLattice(test::periodicSquare(1.0, 16, 0.01));
  EXPECT_EQ(m.lattice().threads(), 3);
  EXPECT_EQ(m.assembly().threads(), 3);
  m.setThreads(2);
  EXPECT_EQ(m.lattice().threads(), 2);
  EXPECT_EQ(m.assembly().threads(), 2);
  // Moved out of a Manager that then goes (checkpoint load does this): the
  // lattice, which moves with it, still reads the count.
  auto source = std::make_unique<sim::Manager>(std::move(m));
  sim::Manager moved = std::move(*source);
  source.reset();
  EXPECT_EQ(moved.lattice().threads(), 2);
  EXPECT_EQ(moved.assembly().threads(), 2);
  moved.setThreads(4);
  EXPECT_EQ(moved.lattice().threads(), 4);
  EXPECT_EQ(moved.assembly().threads(), 4);
  moved.reset();
  EXPECT_EQ(moved.assembly().threads(), 4);
}

}  // namespace sf
