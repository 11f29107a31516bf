#include "sandflow/io/find_program.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>

namespace sf::io {

std::string findProgram(const std::string& name) {
  const char* path = std::getenv("PATH");
  const std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  for (;;) {
    const std::size_t colon = dirs.find(':', start);
    std::string candidate = dirs.substr(start, colon - start);
    if (candidate.empty()) candidate += '.';
    candidate += '/';
    candidate += name;
    // A folder is "executable" too: only a regular file is a program.
    struct stat st;
    if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
        ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
    if (colon == std::string::npos) return "";
    start = colon + 1;
  }
}

}  // namespace sf::io
