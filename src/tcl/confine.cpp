// Safe mode's one rule for files: a session loaded into a safe interpreter
// (Sandflow_SafeInit) reads and writes only inside the folder that was current
// when it was loaded; every command that names a file asks here first.
#include <algorithm>
#include <filesystem>
#include <system_error>

#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

namespace fs = std::filesystem;

// The path with every symbolic link that exists resolved, so that neither
// ".." nor a link leads out unnoticed.
fs::path resolved(const fs::path& path) {
  std::error_code ec;
  fs::path full = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? fs::absolute(path).lexically_normal() : full;
}

}  // namespace

void confineToCurrentFolder(Session& s) {
  s.confinedTo = resolved(fs::current_path()).string();
}

void requireConfined(const Session& s, const std::string& path) {
  if (s.confinedTo.empty()) return;
  const fs::path full = resolved(path);
  const fs::path folder(s.confinedTo);
  // Inside: the folder's components are a proper prefix of the file's.
  const auto [inFolder, inFile] =
      std::mismatch(folder.begin(), folder.end(), full.begin(), full.end());
  if (inFolder != folder.end() || inFile == full.end())
    throw Error("SAFE PATH", "safe mode reads and writes files only in \"" + s.confinedTo +
                                 "\": \"" + path + "\" is outside it");
}

}  // namespace sf::tcl
