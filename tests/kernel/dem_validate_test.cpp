// Each part of the assembly checks its own invariants (validate): silent on a
// healthy scene after steps under every integrator, and naming what is wrong
// when one invariant is broken on purpose.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "dem_helpers.hpp"
#include "sandflow/dem/assembly.hpp"

namespace sf::dem {
namespace {

// A box of discs settling onto a floor, with a plate on top, a bonded pair
// and a source that drops clones.
struct Scene {
  Assembly a;
  int plate, bonded, source;
  explicit Scene(Integrator integrator) {
    a.integrator = integrator;
    Material m{"sand"};
    m.kn = m.ks = 1e5;
    m.restitution = 0.3;
    m.friction = 0.4;
    const int sand = a.materials().add(m);
    auto wall = [&](Vec2 p, Vec2 q) { return test::addWall(a, p, q, sand); };
    auto disc = [&](Vec2 x, double r) { return test::addDisc(a, x, r, Vec2::Zero(), sand); };
    const double W = 0.02, H = 0.04;
    wall({0, 0}, {W, 0});
    wall({0, 0}, {0, H});
    wall({W, 0}, {W, H});
    plate = wall({W, 0.75 * H}, {0, 0.75 * H});
    for (int k = 0; k < 40; ++k) disc({(k % 8 + 0.6) * 2.3e-3, (k / 8 + 0.6) * 2.3e-3}, 1e-3);
    bonded = disc({0.25 * W - 1e-3, 0.6 * H}, 1e-3);
    a.bond(bonded, disc({0.25 * W + 1e-3, 0.6 * H}, 1e-3));
    source = disc({0.75 * W, 0.7 * H}, 0.8e-3);
    a.makeSource(source, Vec2::Zero(), 0.0, 3);
    a.setPlateStress(plate, 100.0);
  }
  void run(int steps) {
    const double dt = a.criticalTimestep() / 10;
    for (int s = 0; s < steps; ++s) a.step(dt, Vec2(0, -9.81));
  }
};

bool mentions(const std::vector<std::string>& problems, const std::string& words) {
  return std::any_of(problems.begin(), problems.end(),
                     [&](const std::string& p) { return p.find(words) != std::string::npos; });
}

std::string joined(const std::vector<std::string>& problems) {
  std::string all;
  for (const std::string& p : problems) all += p + "; ";
  return all;
}

// A touching contact of the scene (one that the broken copies can spoil).
std::size_t touchingContact(const ContactSet& c) {
  const ContactList& l = c.list();
  for (std::size_t k = 0; k < l.size(); ++k)
    if (l.touching(k)) return k;
  return l.size();
}

TEST(DemValidate, HealthySceneAfterStepsUnderEveryIntegrator) {
  for (Integrator integrator : {Integrator::central, Integrator::euler, Integrator::verlet}) {
    Scene s(integrator);
    EXPECT_TRUE(s.a.validate().empty()) << joined(s.a.validate());
    s.run(3000);
    EXPECT_GT(s.a.touchingCount(), 10u);
    EXPECT_FALSE(s.a.bonds().empty());
    EXPECT_GE(s.a.sources()[0].made, 1);
    EXPECT_TRUE(s.a.validate().empty()) << joined(s.a.validate());
    // A deletion renumbers slots: the list is rebuilt by ids at the next step.
    s.a.remove(s.a.bodies().id[8]);
    EXPECT_TRUE(s.a.validate().empty()) << joined(s.a.validate());
    s.run(10);
    EXPECT_TRUE(s.a.validate().empty()) << joined(s.a.validate());
  }
}

TEST(DemValidate, BodiesCatchANanMassAndAnIdAwayFromItsSlot) {
  Scene s(Integrator::central);
  s.run(20);
  Bodies& b = s.a.bodiesForTesting();
  b.mass[5] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(mentions(s.a.validate(), "element " + std::to_string(b.id[5]) + " has mass nan"))
      << joined(s.a.validate());
  b.mass[5] = -1;
  EXPECT_TRUE(mentions(s.a.validate(), "has mass -1")) << joined(s.a.validate());
  s.a.updateMass(5);
  EXPECT_TRUE(s.a.validate().empty()) << joined(s.a.validate());
  std::swap(b.slotOf[b.id[6]], b.slotOf[b.id[7]]);
  EXPECT_TRUE(
      mentions(s.a.validate(), "element " + std::to_string(b.id[6]) + " is not found at its slot"));
  std::swap(b.slotOf[b.id[6]], b.slotOf[b.id[7]]);
  b.reach[9] *= 2;
  EXPECT_TRUE(mentions(s.a.validate(), "cached size does not follow its shape"));
  b.reach[9] /= 2;
  b.x.pop_back();
  EXPECT_EQ(s.a.validate(), std::vector<std::string>{"the element columns differ in length"});
}

TEST(DemValidate, ContactSetCatchesBrokenSlotsIdsCopiesAndNormals) {
  Scene s(Integrator::central);
  s.run(2000);
  const Bodies& b = s.a.bodiesForTesting();
  const std::size_t k = touchingContact(s.a.contactSet());
  ASSERT_LT(k, s.a.contactList().size());
  EXPECT_TRUE(s.a.contactSet().validate(b).empty());
  {  // a contact whose slots are the wrong way round
    ContactSet c = s.a.contactSet();
    std::swap(c.listForTesting().a[k], c.listForTesting().b[k]);
    EXPECT_TRUE(mentions(c.validate(b), "contact " + std::to_string(k) + " joins slots"));
  }
  {  // a contact at a slot of another element
    ContactSet c = s.a.contactSet();
    c.listForTesting().idB[k] = b.id[c.list().a[k]];
    EXPECT_TRUE(mentions(c.validate(b), "that are not at its slots"));
  }
  {  // a pair listed twice
    ContactSet c = s.a.contactSet();
    ContactList& l = c.listForTesting();
    const std::size_t j = k + 1 < l.size() ? k + 1 : k - 1;
    l.a[j] = l.a[k], l.b[j] = l.b[k], l.idA[j] = l.idA[k], l.idB[j] = l.idB[k];
    l.discs[j] = l.discs[k];
    EXPECT_TRUE(mentions(c.validate(b), "is a second copy of its pair")) << joined(c.validate(b));
  }
  {  // a column of another length
    ContactSet c = s.a.contactSet();
    c.listForTesting().fx.pop_back();
    EXPECT_EQ(c.validate(b),
              std::vector<std::string>{"the contact list's columns differ in length"});
  }
  {  // a touching contact whose normal is not a unit vector, or NaN
    ContactSet c = s.a.contactSet();
    ContactList& l = c.listForTesting();
    l.history[l.current].nx[k] *= 2;
    EXPECT_TRUE(mentions(c.validate(b), "normal is not a unit vector"));
    l.history[l.current].nx[k] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(mentions(c.validate(b), "normal is not a unit vector"));
  }
}

TEST(DemValidate, BondSetCatchesABondToAMissingElement) {
  Scene s(Integrator::central);
  s.run(20);
  EXPECT_TRUE(s.a.bondSet().validate(s.a.bodies()).empty());
  const int partner = s.a.bonds()[0].idB, bond = s.a.bonds()[0].id;
  // The same bonds, checked against the bodies without one of their elements.
  const BondSet bonds = s.a.bondSet();
  s.a.remove(partner);  // takes its bond along
  EXPECT_TRUE(s.a.validate().empty()) << joined(s.a.validate());
  EXPECT_TRUE(mentions(bonds.validate(s.a.bodies()),
                       "bond " + std::to_string(bond) + " joins an element that is gone"));
}

TEST(DemValidate, SourcesAndPlatesCatchBrokenFlags) {
  Scene s(Integrator::central);
  s.run(20);
  Bodies& b = s.a.bodiesForTesting();
  const int source = s.a.slot(s.source);
  b.ghost[source] = 0;
  EXPECT_TRUE(
      mentions(s.a.validate(), "source " + std::to_string(s.source) + " is not a ghost element"));
  b.ghost[source] = 1;
  b.ghost[0] = 1;
  EXPECT_TRUE(
      mentions(s.a.validate(), "element " + std::to_string(b.id[0]) + " is a ghost but no source"));
  b.ghost[0] = 0;
  EXPECT_TRUE(s.a.validate().empty()) << joined(s.a.validate());
  const int disc = s.a.slot(s.bonded);
  b.stress[disc] = 10;
  EXPECT_TRUE(mentions(s.a.validate(), "element " + std::to_string(s.bonded) +
                                           " has a plate stress but is not a wall"));
  b.stress[disc] = std::numeric_limits<double>::quiet_NaN();
  b.stress[s.a.slot(s.plate)] = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(mentions(s.a.validate(), "infinite plate stress"));
}

}  // namespace
}  // namespace sf::dem
