#pragma once
// Where a step's time goes: one profile per scene, stages that partition the
// step (each timed by two clock reads a step, nothing per node or contact).
// The lattice, the coupler and the elements record into the profile their
// owner (the Manager) gives them; used alone, each records into its own.
#include <array>
#include <chrono>
#include <cstddef>
#include <string_view>

namespace sf {

enum class Stage : int {
  latticeBulk,      // the plain fluid nodes' fused stream and collide
  latticeCovered,   // the covered cells' collisions (Noble-Torczynski)
  latticeFill,      // boundary nodes, the stability check, the swap
  coverageMeasure,  // the solid ratios of whatever moved
  coverageSort,     // the covered pieces in node order
  coverageCells,    // the lattice's covered-cell list, with solid velocities
  fluidForces,      // the fluid's force and torque on the solids
  demPairs,         // contact pair upkeep: the skin check and pair builds
  demContacts,      // narrow phase and contact law, contact by contact
  demSums,          // element forces: body forces, contact sums, bonds
  demIntegrate,     // kicks and drift, the speed checks, plates, sources
  outputs,          // recorders due after a step: csv, record, vtk, movie frames
  pictures,         // snapshots taken during a run
  scripts,          // a run's -every scripts, less their snapshots
  tick,             // the workbench's run tick: drawing the view, events
  other,            // the rest of a run: the Manager's checks, the run loop
};
inline constexpr int kStageCount = int(Stage::other) + 1;

// Its name in `sim info` and `sim estimate` ("latticebulk", ...).
std::string_view stageName(Stage stage);

struct StageTime {
  double seconds = 0;
  long long steps = 0;  // steps it ran in (a stage may run several times in one)
  long long last = -1;  // the step it last ran in
};

class Profile {
 public:
  using Clock = std::chrono::steady_clock;

  // The owner's step count moves on: a stage's next time counts a new step.
  void beginStep() { ++step_; }
  long long stepsBegun() const { return step_; }
  void add(Stage stage, double seconds) {
    StageTime& t = stages_[std::size_t(stage)];
    t.seconds += seconds;
    if (t.last != step_) t.last = step_, ++t.steps;
  }
  // Adds the time since t0 and returns now: the next stage's start.
  Clock::time_point lap(Stage stage, Clock::time_point t0) {
    const Clock::time_point now = Clock::now();
    add(stage, std::chrono::duration<double>(now - t0).count());
    return now;
  }
  // Sets a stage outright (a remainder measured otherwise).
  void set(Stage stage, double seconds, long long steps) {
    stages_[std::size_t(stage)] = StageTime{seconds, steps, step_};
  }
  const StageTime& operator[](Stage stage) const { return stages_[std::size_t(stage)]; }
  double seconds(Stage stage) const { return (*this)[stage].seconds; }
  double totalSeconds() const;  // all stages
  void reset() { *this = Profile(); }

 private:
  std::array<StageTime, kStageCount> stages_{};
  long long step_ = 0;
};

// A kernel object's link to the profile it records into: the one attached
// (its owner's), else its own. A copy or move records into its own: it never
// shares its source's owner, which may not outlive it.
class ProfileLink {
 public:
  ProfileLink() = default;
  ProfileLink(const ProfileLink& o) : own_(o.own_) {}
  ProfileLink& operator=(const ProfileLink& o) {
    own_ = o.own_, attached_ = nullptr;
    return *this;
  }
  void attach(Profile* profile) { attached_ = profile; }
  bool owned() const { return attached_ == nullptr; }
  Profile& get() { return attached_ ? *attached_ : own_; }
  const Profile& get() const { return attached_ ? *attached_ : own_; }

 private:
  Profile own_;
  Profile* attached_ = nullptr;
};

}  // namespace sf
