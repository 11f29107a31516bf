#pragma once
// The discrete elements of a scene: bodies, materials, contacts, and the DEM
// step (contact detection, contact forces, integration).
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "sandflow/core/byte_stream.hpp"
#include "sandflow/dem/bodies.hpp"
#include "sandflow/dem/bond.hpp"
#include "sandflow/dem/contact_damping.hpp"
#include "sandflow/dem/contact_list.hpp"
#include "sandflow/dem/dess.hpp"
#include "sandflow/dem/element_edit.hpp"
#include "sandflow/dem/material.hpp"
#include "sandflow/dem/narrow_phase.hpp"

namespace sf::dem {

enum class Integrator { central = 0, euler = 1, verlet = 2 };
// Null-terminated: also the table of "sim configure -integrator".
inline constexpr const char* integratorNames[] = {"central", "euler", "verlet", nullptr};

struct ElementDef {
  std::unique_ptr<Shape> shape;
  int material = 0;
  Vec2 x = Vec2::Zero();
  double angle = 0.0;
  Vec2 v = Vec2::Zero();
  double w = 0.0;
  std::uint8_t hold = 0;
  Vec2 force = Vec2::Zero();  // applied force and torque
  double torque = 0.0;
  Vec2 acceleration = Vec2::Zero();  // a body acceleration of its own
  int id = -1;                       // < 0: the next free id
};

// A candidate pair from the broad phase and, while it touches, its contact: a
// copy made from the contact list (contact_list.hpp) for those who look.
struct Contact {
  int a, b;                   // slots, a < b
  int idA, idB;               // element ids (stable across deletions)
  Vec2 shear = Vec2::Zero();  // tangential spring force on b (history)
  bool touching = false;
  bool discs = false;
  double dampingPart = 0;  // the normal damping's cached part (see ContactList)
  Vec2 normal = Vec2::Zero(), point = Vec2::Zero();
  double overlap = 0.0;
  Vec2 force = Vec2::Zero();  // total contact force on b (on a: the opposite)
};

// A source (physics.md §4): a held element that touches nothing and clones
// itself whenever nothing overlaps it; each clone is free, starts at rest,
// inherits the applied force and gets the source's body acceleration.
struct Source {
  int id;               // the template element
  Vec2 acceleration;    // given to each clone
  double interval = 0;  // least time between clones
  int limit = -1;       // clones to make (< 0: no limit)
  int made = 0;
  double last = -1e300;  // time of the last clone
  std::vector<int> clones;
};

// Seconds spent, summed over steps: pair upkeep (skin check and pair builds),
// contact forces (all of computeForces) and, within them, the pass over the
// contacts (narrow phase and law) and the sums onto the elements; integration
// with its checks.
struct StepTimes {
  double sort = 0, narrow = 0, integrate = 0;
  double contactPass = 0, sums = 0;
};

class Assembly {
 public:
  MaterialTable& materials() { return materials_; }
  const MaterialTable& materials() const { return materials_; }

  int add(ElementDef def);  // validated; returns the id
  void remove(int id);
  // Changes element `id` by hand: checks the whole edit, then applies it;
  // throws sf::Error and changes nothing when a part is refused.
  void configure(int id, const ElementEdit& edit);
  int nextId() const;
  int slot(int id) const;  // throws if no such element
  bool empty() const { return bodies_.size() == 0; }
  Bodies& bodies() { return bodies_; }
  const Bodies& bodies() const { return bodies_; }
  // Recomputes mass and inertia of a slot after its shape or material changed.
  void updateMass(int slot);
  // Throws sf::Error ("VALUE MASS") unless an element of this shape and
  // material has a finite, positive mass and inertia (a huge or tiny size, or
  // density, can overflow or underflow them).
  static void checkMass(const Shape& shape, const Material& material);
  void touched() { dess_.reset(), pairsValid_ = false, ++generation_; }  // changed by hand

  // One step. Throws sf::Error ("UNSTABLE ...") before changing anything when a
  // contact overlaps beyond `maxOverlap` of the smaller element or a force is
  // not finite.
  void step(double dt, const Vec2& gravity);

  // 2 sqrt(m/k) for the lightest free element and the stiffest material in use.
  // Kept until an element or a material changes (updateMass, touched, or the
  // material table): the Manager asks before every step.
  double criticalTimestep() const;
  double measureCriticalTimestep() const;  // the same, computed afresh
  // The steps a scene's contacts bear (docs/stability.md, DEM timestep), all
  // for the stiffest material in use and m* the lightest contact's effective
  // mass: m/2 of the lightest free element when two free elements can meet
  // (m when only one can, against walls and held elements).
  struct TimestepLimits {
    double critical;  // criticalTimestep()
    // 2 sqrt(m*/k) (sqrt(1 + zeta^2) - zeta), zeta the largest damping ratio
    // in use: above it a lasting contact grows without bound.
    double stable;
    // 0.5 sqrt(m*/k): below it a contact spans 6 steps or more and rebounds
    // at its set restitution (contact_damping.hpp); above it an impact's
    // rebound depends on where in a step it begins, and can gain energy.
    double accurate;
    double effectiveMass, stiffness, zeta;  // m*, k and zeta of the limits
  };
  TimestepLimits timestepLimits() const;  // kept like criticalTimestep
  Integrator integrator = Integrator::central;
  double maxOverlap = 0.5;
  int threads = 1;
  // false: every pair one by one, none in the vector pass (a check that both
  // give the same bits; takes effect at the next pair build).
  bool vectorPass = true;

  // The candidate pairs and contacts as of the last step (made on demand).
  const std::vector<Contact>& contacts() const;
  const ContactList& contactList() const { return list_; }

  // Bonds. `bond` makes one between two elements at their closest surface
  // points (stiffness/strength < 0: from the elements' materials).
  int bond(int idA, int idB, double stiffness = -1, double strength = -1,
           double shearStrength = -1);
  // Bonds every pair among `ids` (all elements when empty) whose surfaces are
  // closer than `gap`; returns how many were made.
  int bondAll(const std::vector<int>& ids, double gap);
  void unbond(int bondId);
  const std::vector<Bond>& bonds() const { return bonds_; }
  const Bond& bondInfo(int bondId) const;
  const std::vector<BondBreak>& breaks() const { return breaks_; }

  // Plates: a wall with a target stress s moves along its left normal (from ->
  // to turned a quarter counter-clockwise) so that the contact load on it is
  // s x length. NaN removes the servo (the wall keeps its last velocity).
  void setPlateStress(int id, double stress);

  // Sources.
  void makeSource(int id, const Vec2& acceleration, double interval, int limit);
  void removeSource(int id);
  const std::vector<Source>& sources() const { return sources_; }
  double time() const { return time_; }
  std::size_t touchingCount() const;
  // Sum of the contact forces on one element (its reaction, for a wall).
  Vec2 contactForce(int slot) const;
  double kineticEnergy() const;
  Vec2 momentum() const;
  const StepTimes& times() const { return times_; }
  long long broadPhaseBuilds() const { return builds_; }

  // The whole state, bit for bit (checkpoints): materials, settings, every
  // element's columns in slot order, the contact list with its history and
  // the broad phase's reference poses, bonds with their breaks, sources. A
  // continued run takes the same steps as one that never stopped. `loadState`
  // fills an empty assembly, validating what it reads (sf::Error "FORMAT ..."
  // or the kernel's own checks).
  void saveState(ByteWriter& out) const;
  void loadState(ByteReader& in);
  // The invariants the step relies on, checked afresh (tests, the fuzzer,
  // "sim check"): what is wrong, in words; empty when all hold.
  std::vector<std::string> validate() const;

 private:
  void computeForces(double dt, const Vec2& gravity, bool commit);
  // Fills contact k's cached law, damping part, size and radius.
  void prepareContact(ContactList& l, std::size_t k) const;
  // Contact k's damping part at the step dampingDt_ (see ContactList), and
  // every contact's damping part and normal-force mode for the step dt, done
  // again only after a pair build or a change of step (law_columns.cpp).
  double dampingPart(const ContactList& l, std::size_t k) const;
  void prepareDamping(double dt);
  // Whether the pair-law table or the contacts' caches are out of date (the
  // pair list is then built again).
  bool lawsStale() const;
  void buildLaws();
  void spawnClones();
  void servoPlates(double dt);
  void checkSpeeds(double dt) const;
  double curvatureRadius(int slot) const;
  // The stiffness criticalTimestep takes for a slot's material (Hertz: at an
  // overlap of 1% of the element's size).
  double stiffestContact(int slot) const;
  TimestepLimits measureTimestepLimits(double critical) const;
  double effectiveRadius(int a, int b) const;
  bool overlapsAnything(int slot) const;
  void bondForces(double dt, const std::vector<Vec2>& v, const std::vector<double>& w);
  // Closest surface points of two elements (a's, b's), for bonding; false when
  // farther apart than `gap`.
  bool closestPoints(int slotA, int slotB, double gap, Vec2& pa, Vec2& pb) const;
  void updatePairs();
  void integrate(double dt);
  bool anyUnstarted() const {  // some slot has no half-step velocity yet
    return std::memchr(bodies_.started.data(), 0, bodies_.started.size()) != nullptr;
  }

  MaterialTable materials_;
  Bodies bodies_;
  Dess dess_;
  ContactList list_;
  struct PairBuild {  // updatePairs' buffers, kept from build to build
    struct Kept {
      int a, b;
      bool discs;
      bool swapped;        // that pair had a and b the other way round
      std::ptrdiff_t old;  // the same pair in the old list, if it touched (else -1)
    };
    std::vector<Box> boxes;
    std::vector<std::pair<int, int>> pairs;
    std::vector<Kept> kept[2];  // linear disc pairs, the others
    ContactList spare;          // the list before last, reused for the next one
  } build_;
  mutable std::vector<Contact> view_;  // contacts(), made from list_
  mutable bool viewValid_ = false;
  std::vector<Vec2> builtAt_;
  std::vector<double> builtAngle_;
  bool pairsValid_ = false;
  bool slotsMoved_ = false;  // a deletion renumbered slots since the last pair build
  double skin_ = 0.0;
  long long builds_ = 0;
  StepTimes times_;
  std::vector<Bond> bonds_;
  std::vector<BondBreak> breaks_;
  // A step's bonds and breaks, until the step is sure to succeed.
  std::vector<Bond> pendingBonds_;
  std::vector<BondBreak> pendingBreaks_;
  bool bondsPending_ = false;
  std::vector<Source> sources_;
  std::vector<int> plates_;  // slots with a servo, found again when generation_ changes
  std::uint64_t platesAt_ = 0;
  std::vector<PairLaw> laws_;                        // material pairs, i * materials + j
  std::vector<double> lawKn_, lawKs_, lawFriction_;  // the same in columns
  // The damping solved for each restitution and step (contact_damping.hpp),
  // and the step, pair build, masses and materials the contacts' damping
  // parts hold for (dampingDt_ 0: none yet).
  mutable DampingRatios dampingRatios_;
  double dampingDt_ = 0;
  long long dampingBuild_ = -1;
  std::uint64_t dampingGeneration_ = 0, dampingMaterials_ = 0;
  std::uint64_t generation_ = 1;  // bumped by every change to masses, holds or the element set
  mutable std::uint64_t criticalAt_ = 0;
  mutable std::uint64_t criticalMaterials_ = 0;  // materials_.version() then
  // The contacts' caches (prepareContact) hold for these.
  std::uint64_t lawsAt_ = 0, lawsMaterials_ = 0;
  mutable double critical_ = 0;
  mutable TimestepLimits limits_{};
  std::vector<char> scratchTouch_;  // per element: in contact this step (computeForces)
  // The step computes its forces into these and swaps them in, so that a
  // step that fails leaves the last step's forces (Verlet kicks with them).
  std::vector<Vec2> spareForce_;
  std::vector<double> spareTorque_;
  int nextBondId_ = 0;
  double time_ = 0;
};

}  // namespace sf::dem
