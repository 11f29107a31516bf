// The contact list's passes: the vector pass over linear disc pairs against
// the one-by-one law, the history kept by a step that stops, and the history
// carried over when the pairs are found again.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "sandflow/core/error.hpp"
#include "sandflow/dem/assembly.hpp"

namespace sf::dem {
namespace {

// A cluster of overlapping discs of mixed sizes, moving and spinning at random,
// no gravity and no walls: every pair is a linear disc pair.
void cluster(Assembly& a, int count, unsigned seed) {
  Material m{"grain"};
  m.density = 2650;
  m.kn = m.ks = 1e5;
  m.restitution = 0.5;
  m.friction = 0.4;
  a.materials().add(m);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  const int side = int(std::ceil(std::sqrt(double(count))));
  for (int i = 0; i < count; ++i) {
    ElementDef d;
    d.shape = std::make_unique<Disc>(0.8e-3 + 0.2e-3 * u(rng));
    d.material = 1;
    d.x = Vec2((i % side) * 1.9e-3, (i / side) * 1.9e-3) + 1e-4 * Vec2(u(rng), u(rng));
    d.v = 0.05 * Vec2(u(rng) - 0.5, u(rng) - 0.5);
    d.w = 50 * (u(rng) - 0.5);
    a.add(std::move(d));
  }
}

bool sameBits(const std::vector<Vec2>& p, const std::vector<Vec2>& q) {
  return p.size() == q.size() && std::memcmp(p.data(), q.data(), p.size() * sizeof(Vec2)) == 0;
}

TEST(ContactList, VectorPassEqualsTheOneByOneLawBitForBit) {
  for (int threads : {1, 2}) {
    Assembly vec, one;
    cluster(vec, 900, 7);
    cluster(one, 900, 7);
    one.vectorPass = false;
    vec.setThreads(threads), one.setThreads(threads);
    const double dt = 2e-6;
    std::size_t touching = 0;
    for (int s = 0; s < 300; ++s) {
      vec.step(dt, Vec2::Zero());
      one.step(dt, Vec2::Zero());
      touching += vec.touchingCount();
    }
    EXPECT_GT(touching, 300u * 150u) << "the cluster should keep many contacts";
    EXPECT_TRUE(sameBits(vec.bodies().x, one.bodies().x)) << threads << " threads";
    EXPECT_TRUE(sameBits(vec.bodies().v, one.bodies().v)) << threads << " threads";
    ASSERT_EQ(vec.contacts().size(), one.contacts().size());
    for (std::size_t k = 0; k < vec.contacts().size(); ++k) {
      const Contact &p = vec.contacts()[k], &q = one.contacts()[k];
      ASSERT_EQ(p.touching, q.touching);
      ASSERT_EQ(p.force, q.force);
      ASSERT_EQ(p.shear, q.shear);
    }
  }
}

// The cluster in a box of four walls, run with 1 and 2 threads: the vector
// pass, the one-by-one pass (walls) and the sums split over threads give the
// same bits.
TEST(ContactList, ThreadCountDoesNotChangeTheResult) {
  std::vector<Vec2> x[2], v[2];
  for (int threads : {1, 2}) {
    Assembly a;
    cluster(a, 900, 11);
    a.setThreads(threads);
    const double lo = -0.9e-3, hi = 29 * 1.9e-3 + 0.9e-3;  // the outer discs touch
    const Vec2 corners[4] = {{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}};
    for (int k = 0; k < 4; ++k) {
      const Vec2 from = corners[k], to = corners[(k + 1) % 4], seg = to - from;
      ElementDef d;
      d.shape = std::make_unique<Wall>(seg.norm(), 1e-4);
      d.material = 1;
      d.x = 0.5 * (from + to);
      d.angle = std::atan2(seg.y(), seg.x());
      d.hold = holdX | holdY | holdRotation;
      a.add(std::move(d));
    }
    for (int s = 0; s < 400; ++s) a.step(2e-6, Vec2(0, -9.81));
    std::size_t walls = 0;
    for (const Contact& c : a.contacts()) walls += c.touching && !c.discs;
    EXPECT_GT(walls, 10u) << "discs should press on the walls";
    x[threads - 1] = a.bodies().x, v[threads - 1] = a.bodies().v;
  }
  EXPECT_TRUE(sameBits(x[0], x[1]));
  EXPECT_TRUE(sameBits(v[0], v[1]));
}

TEST(ContactList, StepThatStopsKeepsTheContactHistory) {
  Assembly a;
  cluster(a, 100, 3);
  for (int s = 0; s < 50; ++s) a.step(2e-6, Vec2::Zero());
  const std::vector<Contact> before = a.contacts();
  const std::vector<Vec2> x = a.bodies().x;
  a.setMaxOverlap(1e-6);  // every touching contact is now too deep
  EXPECT_THROW(a.step(2e-6, Vec2::Zero()), Error);
  ASSERT_EQ(a.contacts().size(), before.size());
  for (std::size_t k = 0; k < before.size(); ++k) {
    EXPECT_EQ(a.contacts()[k].touching, before[k].touching);
    EXPECT_EQ(a.contacts()[k].normal, before[k].normal);
    EXPECT_EQ(a.contacts()[k].shear, before[k].shear);
  }
  EXPECT_TRUE(sameBits(a.bodies().x, x));
  // And the run goes on from there as if nothing had happened.
  Assembly b;
  cluster(b, 100, 3);
  for (int s = 0; s < 51; ++s) b.step(2e-6, Vec2::Zero());
  a.setMaxOverlap(0.5);
  a.step(2e-6, Vec2::Zero());
  EXPECT_TRUE(sameBits(a.bodies().x, b.bodies().x));
}

TEST(ContactList, HistoryCarriesOverWhenThePairsAreFoundAgain) {
  // The same run with the pair list rebuilt every step (touched) and rebuilt
  // only as the skin requires: the shear springs carry over either way.
  Assembly lazy, eager;
  cluster(lazy, 400, 5);
  cluster(eager, 400, 5);
  for (int s = 0; s < 200; ++s) {
    lazy.step(2e-6, Vec2::Zero());
    eager.touched();
    eager.step(2e-6, Vec2::Zero());
  }
  EXPECT_LT(lazy.broadPhaseBuilds(), eager.broadPhaseBuilds());
  EXPECT_TRUE(sameBits(lazy.bodies().x, eager.bodies().x));
}

// A disc pressed against a held one and sliding along it, kept from rolling
// (a shear spring builds), and optionally a far disc made first, in slot 0.
struct Slider {
  Assembly a;
  int held = -1, slider = -1, far = -1;
  explicit Slider(bool withFar) {
    Material m{"grain"};
    m.density = 1;
    m.kn = m.ks = 1e3;
    m.friction = 0.5;
    a.materials().add(m);
    auto disc = [&](const Vec2& x, const Vec2& v, std::uint8_t hold, const Vec2& force) {
      ElementDef d;
      d.shape = std::make_unique<Disc>(1.0);
      d.material = 1, d.x = x, d.v = v, d.hold = hold, d.force = force;
      return a.add(std::move(d));
    };
    if (withFar) far = disc(Vec2(20, 20), Vec2::Zero(), 0, Vec2::Zero());
    held = disc(Vec2::Zero(), Vec2::Zero(), holdX | holdY | holdRotation, Vec2::Zero());
    // Pressed in by its applied force; sliding, not rolling.
    slider = disc(Vec2(1.9, 0), Vec2(0, 0.01), holdRotation, Vec2(-100, 0));
  }
  void run(int steps) {
    for (int s = 0; s < steps; ++s) a.step(2e-3, Vec2::Zero());
  }
  Vec2 shear() const {  // on the slider
    for (const Contact& c : a.contacts())
      if (c.touching) return c.idB == slider ? c.shear : Vec2(-c.shear);
    return Vec2::Zero();
  }
};

TEST(ContactList, HistorySurvivesADeletionThatSwapsAPairsSlots) {
  // Deleting the far disc moves the slider (the last slot) into slot 0, in
  // front of the held disc: the pair comes back the other way round, and
  // must keep its shear spring.
  Slider kept(true), deleted(true);
  kept.run(50), deleted.run(50);
  const Vec2 shear = deleted.shear();
  ASSERT_GT(shear.norm(), 0.2);  // a step adds 0.02
  deleted.a.remove(deleted.far);
  ASSERT_EQ(deleted.a.slot(deleted.slider), 0);
  kept.run(1), deleted.run(1);
  EXPECT_NEAR((deleted.shear() - kept.shear()).norm(), 0.0, 1e-12 * shear.norm());
  kept.run(50), deleted.run(50);
  const Bodies &k = kept.a.bodies(), &d = deleted.a.bodies();
  const int sk = k.slot(kept.slider), sd = d.slot(deleted.slider);
  EXPECT_NEAR((d.x[sd] - k.x[sk]).norm(), 0.0, 1e-12);
  EXPECT_NEAR((d.v[sd] - k.v[sk]).norm(), 0.0, 1e-12);
}

TEST(ContactList, ADeletedElementsContactsDoNotPassToItsIdsNextOwner) {
  // The slider deleted and a disc at rest made in its place, which takes
  // its id (the largest): a new contact, whose spring starts from zero as
  // that of a disc put there in a scene that never had the slider.
  Slider reused(false), fresh(false);
  reused.run(50);
  ASSERT_GT(reused.shear().norm(), 0.2);
  const Vec2 x = reused.a.bodies().x[reused.a.slot(reused.slider)];
  reused.a.remove(reused.slider);
  fresh.a.remove(fresh.slider);
  for (Slider* s : {&reused, &fresh}) {
    ElementDef d;
    d.shape = std::make_unique<Disc>(1.0);
    d.material = 1, d.x = x;
    EXPECT_EQ(s->a.add(std::move(d)), s->slider);
  }
  reused.run(1), fresh.run(1);
  EXPECT_EQ(reused.shear(), fresh.shear());
  EXPECT_LT(reused.shear().norm(), 0.1);
}

}  // namespace
}  // namespace sf::dem
