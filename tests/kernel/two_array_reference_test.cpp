// The lattice's step against the two-array step it replaced (issue 35): every
// node kind, every collision and forcing scheme, fluid alone and coupled to
// moving elements and circular walls, bit for bit.
//
// The two-array step (pull from one array, write the other; sandflow up to
// commit 4550a87) ran these scenes and gave the hashes below: of the
// post-collision populations of every node that holds fluid, read through
// Lattice::population, of the circular walls' loads and of the elements'
// motion. The in-place step must give the same bits, whichever layout its
// array is in after an odd or an even number of steps. (Hashes rather than
// arrays: the kernels are the same operations in the same order, so nothing
// short of the same bits is right; tests/kernel/reference_kernel_test.cpp
// checks the physics against an independent cellwise kernel.)
#include <gtest/gtest.h>

#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <string>

#include "coupled_helpers.hpp"
#include "lattice_helpers.hpp"
#include "sandflow/io/checkpoint.hpp"

namespace sf {
namespace {

class Fnv {
 public:
  void add(double v) {
    const auto* p = reinterpret_cast<const unsigned char*>(&v);
    for (std::size_t k = 0; k < sizeof v; ++k) h_ = (h_ ^ p[k]) * 1099511628211ull;
  }
  void add(const Vec2& v) { add(v.x()), add(v.y()); }
  std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 14695981039346656037ull;
};

bool holdsFluid(lb::NodeKind k) {
  return k == lb::NodeKind::fluid || k == lb::NodeKind::velocity || k == lb::NodeKind::pressure;
}

std::uint64_t hashOf(const sim::Manager& m) {
  Fnv f;
  const lb::Lattice& l = m.lattice();
  for (int j = 0; j < l.ny(); ++j)
    for (int i = 0; i < l.nx(); ++i)
      if (holdsFluid(l.kind(i, j)))
        for (int d = 0; d < 9; ++d) f.add(l.population(d, i, j));
  for (const lb::CircleObstacle& c : l.circles()) f.add(c.force), f.add(c.torque);
  const dem::Bodies& b = m.assembly().bodies();
  for (int s = 0; s < b.size(); ++s) {
    f.add(b.x[s]), f.add(b.v[s]), f.add(b.w[s]);
    f.add(b.fluidForce[s]), f.add(b.fluidTorque[s]);
  }
  return f.value();
}

// A 60 x 30 channel with every node kind: `open` gives it a Zou-He velocity
// inlet (left) and pressure outlet (right), else it is periodic in x; a moving
// no-slip floor, a slip ceiling (no-slip with the Zou-He sides), a no-slip and
// a slip rect, a spinning circular wall, and with `elements` three moving
// discs (covered cells, explicit or implicit coupling).
void scene(sim::Manager& m, lb::Collision c, lb::ForceScheme s, bool open, bool elements,
           bool implicit) {
  lb::LatticeDef def = test::channelDef(60, 30, 0.8, 0.1);
  def.collision = c;
  def.forceScheme = s;
  def.forcing = Vec2(2e-6, -1e-6);
  const double cs = lb::resolve(def).soundSpeed();
  def.sides[lb::bottom] = lb::SideDef{lb::SideKind::noslip, Vec2(0.003, 0)};
  if (open) {
    def.sides[lb::left] = lb::SideDef{lb::SideKind::velocity, Vec2(0.004, 0.0005)};
    def.sides[lb::right] = lb::SideDef{lb::SideKind::pressure, Vec2::Zero(), cs * cs * 0.999};
  } else {
    def.sides[lb::top] = lb::SideDef{lb::SideKind::slip};
  }
  m.setThreads(2);
  m.createLattice(def);
  m.lattice().addObstacle({-1, Vec2(12, 8), Vec2(16, 14), false});
  m.lattice().addObstacle({-1, Vec2(40, 22), Vec2(46, 26), true});
  m.lattice().addCircle({-1, Vec2(28, 15), 4.3, false, Vec2(0.01, 0.002), 0.003});
  m.lattice().initialize([](const Vec2& x, double& rho, Vec2& u) {
    // Polynomials, not libm's sine: the same bits on any machine.
    const double a = x.x() / 60, b = x.y() / 30;
    rho = 1.0 + 0.002 * a * (1 - a) * (0.5 - b);
    u = Vec2(0.004 + 0.008 * b * (1 - b), 0.004 * a * (1 - a) * (a - 0.3));
  });
  if (!elements) return;
  coupling::Settings settings;
  settings.implicit = implicit;
  m.setCouplingSettings(settings);
  const int mat = test::softMaterial(m, 1.5);
  test::addDisc(m, mat, Vec2(6, 22), 2.6, Vec2(0.01, -0.002), 0.002);
  test::addDisc(m, mat, Vec2(36, 9), 3.1, Vec2(-0.004, 0.003), -0.001);
  test::addDisc(m, mat, Vec2(52, 15), 1.7, Vec2(0.002, 0.0), 0.004);
}

struct Case {
  lb::Collision collision;
  lb::ForceScheme force;
  bool open, elements, implicit;
  std::uint64_t at40, at41;  // the two-array step's hashes after 40 and 41 steps
};

// Produced by the two-array step (see the top of the file).
constexpr Case kCases[] = {
#include "two_array_reference_hashes.inc"
};

TEST(TwoArrayReference, InPlaceStepGivesTheSameBits) {
  const bool print = std::getenv("SANDFLOW_PRINT_HASHES") != nullptr;
  for (const lb::Collision c : {lb::Collision::bgk, lb::Collision::trt})
    for (const lb::ForceScheme s : {lb::ForceScheme::nodal, lb::ForceScheme::guo})
      for (const bool open : {false, true})
        for (const int mode : {0, 1, 2}) {  // fluid alone, explicit, implicit coupling
          sim::Manager m;
          scene(m, c, s, open, mode > 0, mode == 2);
          for (int k = 0; k < 40; ++k) m.step();
          // Every node kind is there, and cells covered by moving solids.
          std::string kinds;
          for (const auto& kind : m.lattice().kinds())
            if (kind->count() > 0) kinds += std::string(kind->name()) + " ";
          EXPECT_EQ(kinds, open ? "fluid velocity pressure noslip slip solid "
                                : "fluid periodic noslip slip solid ");
          EXPECT_GT(m.coupler().coveredCells(), mode > 0 ? 60u : 40u);
          const std::uint64_t at40 = hashOf(m);
          m.step();
          const std::uint64_t at41 = hashOf(m);
          const std::string what = std::string(c == lb::Collision::bgk ? "bgk" : "trt") +
                                   (s == lb::ForceScheme::guo ? " guo" : " nodal") +
                                   (open ? " zou-he" : " periodic") + " mode " +
                                   std::to_string(mode);
          if (print) {
            std::printf("  {lb::Collision::%s, lb::ForceScheme::%s, %s, %s, %s, 0x%016" PRIx64
                        "ull, 0x%016" PRIx64 "ull},\n",
                        c == lb::Collision::bgk ? "bgk" : "trt",
                        s == lb::ForceScheme::guo ? "guo" : "nodal", open ? "true" : "false",
                        mode > 0 ? "true" : "false", mode == 2 ? "true" : "false", at40, at41);
            continue;
          }
          bool found = false;
          for (const Case& k : kCases)
            if (k.collision == c && k.force == s && k.open == open && k.elements == (mode > 0) &&
                k.implicit == (mode == 2)) {
              found = true;
              EXPECT_EQ(at40, k.at40) << what << " after 40 steps";
              EXPECT_EQ(at41, k.at41) << what << " after 41 steps";
            }
          EXPECT_TRUE(found) << what;
        }
}

// After an odd and an even number of steps the array is in one layout or the
// other: every reader gives what a lattice loaded from its checkpoint (which
// starts in the first layout) gives, and the two go on with the same bits.
TEST(TwoArrayReference, EitherLayoutReadsTheSameAndGoesOnTheSame) {
  for (const int steps : {41, 42}) {
    sim::Manager m;
    scene(m, lb::Collision::trt, lb::ForceScheme::guo, true, true, false);
    for (int k = 0; k < steps; ++k) m.step();
    ByteWriter out;
    m.lattice().saveState(out);
    const std::vector<char>& bytes = out.bytes();
    ByteReader in(bytes.data(), bytes.size(), io::kCheckpointVersion);
    const std::unique_ptr<lb::Lattice> loaded = lb::Lattice::loadState(in);
    const lb::Lattice& l = m.lattice();
    EXPECT_EQ(loaded->populations(), l.populations()) << steps;
    EXPECT_EQ(loaded->mass(), l.mass()) << steps;
    EXPECT_EQ(loaded->momentum(), l.momentum()) << steps;
    EXPECT_EQ(loaded->maxMach(), l.maxMach()) << steps;
    std::vector<double> rho[2], rowRho(std::size_t(l.nx()));
    std::vector<Vec2> j[2], rowU(std::size_t(l.nx()));
    loaded->pulledMoments(l.coveredCells(), rho[0], j[0]);
    l.pulledMoments(l.coveredCells(), rho[1], j[1]);
    EXPECT_EQ(rho[0], rho[1]) << steps;
    EXPECT_EQ(j[0], j[1]) << steps;
    for (int y = 0; y < l.ny(); ++y) {
      l.rowFields(y, rowRho.data(), rowU.data());
      for (int x = 0; x < l.nx(); ++x) {
        ASSERT_EQ(loaded->density(x, y), rowRho[std::size_t(x)]) << x << " " << y;
        ASSERT_EQ(loaded->velocity(x, y), rowU[std::size_t(x)]) << x << " " << y;
        ASSERT_EQ(loaded->pressure(x, y), l.pressure(x, y)) << x << " " << y;
      }
    }
    for (const int id : l.obstacleIds()) {
      EXPECT_EQ(loaded->obstacleInfo(id).force, l.obstacleInfo(id).force) << steps;
      EXPECT_EQ(loaded->obstacleInfo(id).torque, l.obstacleInfo(id).torque) << steps;
    }
    // And the two go on alike (a lattice alone, so both stream in place).
    for (int k = 0; k < 3; ++k) m.lattice().step(), loaded->step();
    EXPECT_EQ(loaded->populations(), m.lattice().populations()) << steps;
  }
}

}  // namespace
}  // namespace sf
