#pragma once
// Writes a set of files so that all of them appear, whole, or none does: each
// is written under a temporary name, then all are renamed. Errors name the
// final path (sf::Error "IO ...").
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace sf::io {

struct FileContent {
  std::string path;
  std::function<void(std::ostream&)> write;
};

void writeAtomically(const std::vector<FileContent>& files);

}  // namespace sf::io
