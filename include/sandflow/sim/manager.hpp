#pragma once
// The Manager owns what a scene holds -- an optional lattice and the discrete
// elements -- and the clock, and runs the step with only the passes the scene
// needs: no lattice, no fluid pass; no elements, no DEM pass.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sandflow/core/profile.hpp"
#include "sandflow/coupling/coupler.hpp"
#include "sandflow/dem/assembly.hpp"
#include "sandflow/lb/lattice.hpp"
#include "sandflow/sim/step_watch.hpp"

namespace sf::sim {

class Manager {
 public:
  Manager();

  // Lattice. `create` keeps the scene unchanged when the definition is refused.
  bool hasLattice() const { return lattice_ != nullptr; }
  lb::Lattice& lattice();
  const lb::Lattice& lattice() const;
  void createLattice(lb::LatticeDef def);
  void reconfigureLattice(const lb::LatticeDef& def);
  void deleteLattice();

  // Discrete elements (always present; empty costs nothing).
  dem::Assembly& assembly() { return assembly_; }
  const dem::Assembly& assembly() const { return assembly_; }
  Vec2 gravity() const { return gravity_; }
  void setGravity(const Vec2& g);

  // Timestep: the lattice's, or fixed by the user (then tau follows), or for
  // elements alone a tenth of their critical step. 0 when nothing sets one.
  double timestep() const;
  bool timestepFixed() const { return fixedTimestep_.has_value(); }
  void setTimestep(double dt) { setStepping(dt, std::nullopt); }
  // The timestep and the element substeps per step together: the elements'
  // step dt / substeps must stay under their critical step. Refuses before
  // changing anything.
  void setStepping(std::optional<double> dt, std::optional<int> substeps);
  // A new lattice definition (of a live lattice), timestep and substeps at
  // once, as an accuracy set changes them: all are checked before any
  // changes, and the lattice converts its flow once (Lattice::reconfigure).
  void configureStep(const std::optional<lb::LatticeDef>& def, std::optional<double> dt,
                     std::optional<int> substeps);
  // The most element substeps one step may take (sim configure -substeps and
  // a checkpoint take the same).
  static constexpr int kMaxSubsteps = 1000;
  // The thread counts a step may use (sim configure -threads checks the same).
  // The one count of the scene: its lattice, coupler and elements read it.
  static constexpr int kMaxThreads = 1024;
  int threads() const { return *threads_; }
  void setThreads(int threads);

  // Fluid-solid coupling (physics.md §2, §3, §5), used whenever the lattice has
  // something on it that covers cells: elements or circular walls.
  const coupling::Settings& couplingSettings() const { return coupling_; }
  void setCouplingSettings(const coupling::Settings& settings);
  const coupling::Coupler& coupler() const { return coupler_; }
  coupling::Coupler& coupler() { return coupler_; }  // (tests: its slow reference)
  // Whether the last step had solids on the lattice (elements, circles) covering cells.
  bool solidsCoverCells() const { return coversCells_; }
  // Element steps per fluid step, each dt / n, under the fluid force of the step.
  int substeps() const { return substeps_; }
  void setSubsteps(int n) { setStepping(std::nullopt, n); }

  double time() const { return time_; }
  long long stepCount() const { return steps_; }
  // Advances one step. On instability throws sf::Error naming step and cause; the
  // state before the step is kept.
  void step();
  // Clears the scene (lattice, time, settings) but keeps the thread count.
  void reset();

  double machWarnLimit() const { return StepWatch::kMachWarnLimit; }
  double machStopLimit() const { return 0.3; }
  // Warnings raised since the last call, and all of them (the watch's).
  std::vector<Warning> takeWarnings();
  const std::vector<Warning>& warnings() const { return watch_.log(); }

  // Where the steps' time went, stage by stage, since the profile was last
  // reset (the run command resets it at each run's start and adds its
  // own stages: outputs, pictures, scripts, other). The lattice, coupler
  // and elements record into it.
  Profile& profile() { return profile_; }
  const Profile& profile() const { return profile_; }

  // The whole scene, bit for bit (checkpoints): settings, clock, warnings
  // given, the lattice and the elements. `loadState` fills a fresh Manager
  // (threads: its own); a continued run takes the same steps as one that never
  // stopped, on any thread count.
  void saveState(ByteWriter& out) const;
  void loadState(ByteReader& in);
  // The lattice's and the elements' invariants, and the clock's: what is
  // wrong, in words; empty when all hold.
  std::vector<std::string> validate() const;
  // CRC-32 of the whole state (saveState's bytes): equal hashes, equal scenes.
  std::uint32_t stateHash() const;

  // Million lattice-node updates per second of the last `run`.

 private:
  // Points the lattice's, the coupler's and the elements' thread count at
  // this one: when a part is made or replaced, when the count changes and at
  // each step (a moved Manager's coupler and elements keep the count as their
  // own until then).
  void attachParts();
  void checkDemTimestep(double step, int substeps) const;
  void coupleBeforeFluid();
  void stepElements(double dt);

  std::unique_ptr<lb::Lattice> lattice_;
  dem::Assembly assembly_;
  Vec2 gravity_ = Vec2::Zero();
  std::optional<double> fixedTimestep_;
  // On the heap, so that a moved Manager's parts (its lattice moves with it)
  // still read it; its parts hold its address (attachParts).
  std::unique_ptr<int> threads_;
  double time_ = 0.0;
  long long steps_ = 0;
  long long latticeBorn_ = -1000000000;  // steps_ when the lattice was made (checkOutrun)
  coupling::Settings coupling_;
  coupling::Coupler coupler_;
  bool coversCells_ = false;
  int substeps_ = 1;
  Profile profile_;
  StepWatch watch_;
};

}  // namespace sf::sim
