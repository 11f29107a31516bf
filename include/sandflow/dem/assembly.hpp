#pragma once
// The discrete elements of a scene and the DEM step. The assembly holds the
// bodies (per-slot columns) and the materials, and parts that act on them:
// the contacts (ContactSet: broad phase, contact list, laws), the bonds
// (BondSet), the sources (SourceSet) and the plates (PlateServo); the
// integrators are stages around the force evaluation (src/dem/integrate.hpp).
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "sandflow/core/byte_stream.hpp"
#include "sandflow/core/parallel.hpp"
#include "sandflow/core/profile.hpp"
#include "sandflow/dem/bodies.hpp"
#include "sandflow/dem/bond_set.hpp"
#include "sandflow/dem/contact_set.hpp"
#include "sandflow/dem/element_def.hpp"
#include "sandflow/dem/element_edit.hpp"
#include "sandflow/dem/material.hpp"
#include "sandflow/dem/narrow_phase.hpp"
#include "sandflow/dem/plate_servo.hpp"
#include "sandflow/dem/source_set.hpp"

namespace sf::dem {
namespace detail {
struct Motion;
}

enum class Integrator { central = 0, euler = 1, verlet = 2 };
// Null-terminated: also the table of "sim configure -integrator".
inline constexpr const char* integratorNames[] = {"central", "euler", "verlet", nullptr};

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
  // The columns are read by all and written only by dem, through the calls
  // below, and by the coupling through the fluid-load ones.
  const Bodies& bodies() const { return bodies_; }
  // The fluid's force and torque on slot s for the next step, and its static
  // buoyancy (the coupling's output; slots may be set from several threads).
  void setFluidLoad(int s, const Vec2& force, double torque) {
    bodies_.fluidForce[s] = force, bodies_.fluidTorque[s] = torque;
  }
  void setBuoyancy(int s, const Vec2& buoyancy) { bodies_.buoyancy[s] = buoyancy; }
  void clearFluidLoads();
  // For tests that break an invariant on purpose (dem_validate_test).
  Bodies& bodiesForTesting() { return bodies_; }
  // Recomputes mass and inertia of a slot after its shape or material changed.
  void updateMass(int slot);
  // Throws sf::Error ("VALUE MASS") unless an element of this shape and
  // material has a finite, positive mass and inertia (a huge or tiny size, or
  // density, can overflow or underflow them).
  static void checkMass(const Shape& shape, const Material& material);
  void touched() { contacts_.invalidate(), ++generation_; }  // changed by hand

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
  // A touching contact deeper than this share of the smaller element's size
  // stops the step: (0, kMaxOverlapLimit]. Refused outside it (VALUE MAXOVERLAP).
  static constexpr double kMaxOverlapLimit = 2.0;
  double maxOverlap() const { return maxOverlap_; }
  void setMaxOverlap(double share);
  // Its own thread count, or its owner's once attached (sf::ThreadCount).
  void setThreads(int threads) { threads_.set(threads); }
  void attachThreads(const int* count) { threads_.attach(count); }
  int threads() const { return threads_.get(); }
  // false: every pair one by one, none in the vector pass (a check that both
  // give the same bits; takes effect at the next pair build).
  bool vectorPass = true;
  // true: the step as it was before the per-element gather and the fused
  // integration (the serial sums down the contact list, the checks and
  // kicks slot by slot): the slow reference the tests compare the step with.
  bool referenceStep = false;

  // The candidate pairs and contacts as of the last step (made on demand).
  const std::vector<Contact>& contacts() const { return contacts_.view(); }
  const ContactList& contactList() const { return contacts_.list(); }

  // Bonds. `bond` makes one between two elements at their closest surface
  // points (stiffness/strength < 0: from the elements' materials).
  int bond(int idA, int idB, double stiffness = -1, double strength = -1,
           double shearStrength = -1);
  // Bonds every pair among `ids` (all elements when empty) whose surfaces are
  // closer than `gap`; returns how many were made.
  int bondAll(const std::vector<int>& ids, double gap);
  void unbond(int bondId) { bonds_.remove(bondId); }
  const std::vector<Bond>& bonds() const { return bonds_.all(); }
  const Bond& bondInfo(int bondId) const { return bonds_.info(bondId); }
  const std::vector<BondBreak>& breaks() const { return bonds_.breaks(); }

  // Plates: a wall with a target stress s moves along its left normal (from ->
  // to turned a quarter counter-clockwise) so that the contact load on it is
  // s x length. NaN removes the servo (the wall keeps its last velocity).
  void setPlateStress(int id, double stress);

  // Sources.
  void makeSource(int id, const Vec2& acceleration, double interval, int limit);
  void removeSource(int id);
  const std::vector<Source>& sources() const { return sources_.all(); }
  double time() const { return time_; }
  std::size_t touchingCount() const { return contacts_.touchingCount(); }
  // Sum of the contact forces on one element (its reaction, for a wall).
  Vec2 contactForce(int slot) const { return contacts_.forceOn(slot); }
  double kineticEnergy() const;
  Vec2 momentum() const;
  // The profile its steps record into (Stage::dem*): the owner's, once
  // attached, else its own.
  void attachProfile(Profile* profile) { profile_.attach(profile); }
  const Profile& profile() const { return profile_.get(); }
  long long broadPhaseBuilds() const { return contacts_.builds(); }

  // The whole state, bit for bit (checkpoints): materials, settings, every
  // element's columns in slot order, the contact list with its history and
  // the broad phase's reference poses, bonds with their breaks, sources. A
  // continued run takes the same steps as one that never stopped. `loadState`
  // fills an empty assembly, validating what it reads (sf::Error "FORMAT ..."
  // or the kernel's own checks).
  void saveState(ByteWriter& out) const;
  void loadState(ByteReader& in);
  // The invariants the step relies on, checked afresh (tests, the fuzzer,
  // "sim check"): each part's, what is wrong, in words; empty when all hold.
  std::vector<std::string> validate() const;
  // The parts, to look at (tests check and break copies of them).
  const ContactSet& contactSet() const { return contacts_; }
  const BondSet& bondSet() const { return bonds_; }

 private:
  // The step's stages (step() lists them).
  void startForces(double dt, const Vec2& gravity);
  void computeForces(double dt, const Vec2& gravity, bool useHalfVelocity);
  void ownLoads(const Vec2& gravity);
  double gatherSums(const Vec2& gravity);
  // Every slot, or those marked in `only` (detail::accelerate's suspects).
  void checkSpeeds(double dt, const char* only) const;
  // The stiffness criticalTimestep takes for a slot's material (Hertz: at an
  // overlap of 1% of the element's size).
  double stiffestContact(int slot) const;
  TimestepLimits measureTimestepLimits(double critical) const;
  void commitStep();
  detail::Motion motion();
  bool anyUnstarted() const {  // some slot has no half-step velocity yet
    return std::memchr(bodies_.started.data(), 0, bodies_.started.size()) != nullptr;
  }

  MaterialTable materials_;
  Bodies bodies_;
  ContactSet contacts_;
  BondSet bonds_;
  SourceSet sources_;
  PlateServo plates_;
  ProfileLink profile_;
  std::uint64_t generation_ = 1;  // bumped by every change to masses, holds or the element set
  mutable std::uint64_t criticalAt_ = 0;
  mutable std::uint64_t criticalMaterials_ = 0;  // materials_.version() then
  mutable double critical_ = 0;
  mutable TimestepLimits limits_{};
  std::vector<char> scratchTouch_;  // per element: in contact this step (computeForces)
  // The step's accelerations and the slots the speed check must look at
  // (detail::accelerate).
  std::vector<Vec2> acc_;
  std::vector<double> alpha_;
  std::vector<char> suspect_;
  // The step computes its forces into these and swaps them in, so that a
  // step that fails leaves the last step's forces (Verlet kicks with them).
  std::vector<Vec2> spareForce_;
  std::vector<double> spareTorque_;
  double time_ = 0;
  double maxOverlap_ = 0.5;
  double lastStep_ = 0;  // of the last step, 0 before the first (detail::changeStep)
  ThreadCount threads_;
};

}  // namespace sf::dem
