#pragma once
// The one exception type of the kernel. `code` is a short machine-readable class
// ("VALUE TAU", "UNSTABLE MACH") that the Tcl layer turns into errorCode
// "SANDFLOW VALUE TAU"; `what()` is a sentence a user understands.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace sf {

// What a user can do about an error or a warning, named by the kernel without
// knowing the command language: the front end words it (the Tcl layer appends
// `use "lattice create"` and the like, tcl/remedy.cpp). Stored in checkpoints
// with the warnings: append, never renumber.
enum class Remedy : std::uint8_t {
  none,
  createLattice,        // there is no lattice
  deleteLattice,        // a lattice exists already
  viscosityOrTimestep,  // a lattice needs one of them
  setTimestep,          // the scene has no timestep of its own
  implicitCoupling,     // grains too light for the explicit coupling
  trtCollision,         // BGK's bounce-back walls slip at high tau
  elementSubsteps,      // the element step is over the critical one: split the step
};
inline constexpr int kRemedyCount = int(Remedy::elementSubsteps) + 1;  // the last, plus one

// A remedy with the whole number it calls for, where it calls for one (the
// element substeps per step that bring each under the critical step).
struct Advice {
  Remedy remedy = Remedy::none;
  long long count = 0;
  Advice(Remedy r = Remedy::none, long long n = 0) : remedy(r), count(n) {}  // NOLINT: implicit
  friend bool operator==(const Advice&, const Advice&) = default;
};

class Error : public std::runtime_error {
 public:
  Error(std::string code, const std::string& message, Advice remedy = {})
      : std::runtime_error(message), code_(std::move(code)), remedy_(remedy) {}
  const std::string& code() const { return code_; }
  // What a re-wrapped error passes on whole (Error(code, more + what(), remedy())).
  const Advice& remedy() const { return remedy_; }

 private:
  std::string code_;
  Advice remedy_;
};

// Formats a double the way a user would type it back (shortest round-trip form).
std::string formatNumber(double value);

}  // namespace sf
