#pragma once
// The one exception type of the kernel. `code` is a short machine-readable class
// ("VALUE TAU", "UNSTABLE MACH") that the Tcl layer turns into errorCode
// "SANDFLOW VALUE TAU"; `what()` is a sentence a user understands.
#include <stdexcept>
#include <string>

namespace sf {

class Error : public std::runtime_error {
 public:
  Error(std::string code, const std::string& message)
      : std::runtime_error(message), code_(std::move(code)) {}
  const std::string& code() const { return code_; }

 private:
  std::string code_;
};

// Formats a double the way a user would type it back (shortest round-trip form).
std::string formatNumber(double value);

}  // namespace sf
