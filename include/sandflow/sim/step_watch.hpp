#pragma once
// The step's watch: the checks that warn when a scene is leaving the range
// where its numbers can be trusted (docs/stability.md), each given once and
// kept in a log that checkpoints carry. The Manager runs the step and asks
// the watch at the points each check needs; a refusal (a step that cannot be
// taken) stays with the part that refuses it.
#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "sandflow/core/byte_stream.hpp"
#include "sandflow/core/error.hpp"

namespace sf::sim {

class Manager;

// What a warning is about, as checkpoints store it (values are stable).
enum class WarningCode : std::uint8_t {
  mach = 0,           // the fluid past Mach 0.1 (once per lattice)
  solidMach = 1,      // a solid surface past Mach 0.1
  underResolved = 2,  // an element under two cells across (once per element)
  selfOverlap = 3,    // a solid meets its own periodic image
  lightElement = 4,   // too light for the explicit coupling
  bgkWallSlip = 5,    // BGK with tau past 2 along no-slip walls
  demAccuracy = 6,    // the element step over its accurate step
  cellReynolds = 7,   // the cell Reynolds number past 20
  outrun = 8,         // the fluid twice as fast as what drives it
};
inline constexpr int kWarningCodeCount = int(WarningCode::outrun) + 1;

// A warning as the kernel gives it: what it is about (the element, for those
// given once per element; else -1), its sentence, and what the user can do
// about it (the front end words the remedy).
struct Warning {
  std::string text;
  Remedy remedy = Remedy::none;
  WarningCode code = WarningCode::mach;
  int subject = -1;
};

class StepWatch {
 public:
  // Above this tau, BGK's bounce-back walls slip by over 5% of a 16-cell
  // channel's speed (docs/stability.md); TRT's magic walls do not.
  static constexpr double kBgkTauLimit = 2.0;
  // The cell Reynolds number u h / nu above which a warning is given: a
  // lid-driven cavity at 0.02 c stays under its lid's speed at 12 (tau
  // 0.505) and outruns it unseen at 60 (BGK, tau 0.501; docs/stability.md).
  static constexpr double kCellReynoldsLimit = 20.0;
  static constexpr double kMachWarnLimit = 0.1;

  // The checks, each given once (by code, and element where it says so).
  // With the lattice made or changed (and at each step: obstacles added since).
  void checkCollision(const Manager& m);
  // After the coupling has covered the lattice for the step: solids faster
  // than kMachWarnLimit, elements under two cells, solids meeting their own
  // periodic image, elements too light for the explicit coupling.
  void checkCoverage(const Manager& m);
  // Before the elements' step of `dt` (each substep's).
  void checkDemAccuracy(const Manager& m, double dt);
  // After the lattice's step: its Mach number, cell Reynolds number, and a
  // flow outrunning what drives it (`age`: steps since the lattice was made).
  void checkFluid(const Manager& m, long long age);

  // Warnings given since the last call, and all of them.
  std::vector<Warning> take();
  const std::vector<Warning>& log() const { return log_; }
  // Whether a warning of `code` (about `subject`) was given.
  bool given(WarningCode code, int subject = -1) const {
    return given_.count({std::uint8_t(code), subject}) > 0;
  }
  // A new lattice may be warned of its Mach number again.
  void forget(WarningCode code) { given_.erase({std::uint8_t(code), -1}); }
  void clear() { *this = StepWatch(); }

  // The log and what was given, in a checkpoint's SIM section. Files before
  // version 4 hold the flags and sentences of the watch that wrote them.
  void save(ByteWriter& out) const;
  void load(ByteReader& in);

 private:
  void warn(WarningCode code, const std::string& text, Remedy remedy = Remedy::none,
            int subject = -1);

  std::vector<Warning> pending_, log_;
  std::set<std::pair<std::uint8_t, int>> given_;
};

}  // namespace sf::sim
