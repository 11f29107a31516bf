#include "sandflow/io/atomic_files.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "sandflow/core/error.hpp"

namespace sf::io {

void writeAtomically(const std::vector<FileContent>& files) {
  std::vector<std::string> parts;
  auto discard = [&] {
    for (const std::string& p : parts) std::remove(p.c_str());
  };
  for (const FileContent& f : files) {
    const std::string part = f.path + ".part";
    std::ofstream out(part, std::ios::binary);
    if (!out) {
      const int error = errno;
      discard();
      throw Error("IO OPEN", "cannot write \"" + f.path + "\": " + std::strerror(error));
    }
    parts.push_back(part);
    try {
      f.write(out);
    } catch (...) {  // a writer that fails leaves no part file either
      out.close();
      discard();
      throw;
    }
    if (!out.flush()) {
      discard();
      throw Error("IO WRITE", "writing \"" + f.path + "\" failed (disk full?)");
    }
  }
  for (std::size_t k = 0; k < files.size(); ++k)
    if (std::rename(parts[k].c_str(), files[k].path.c_str()) != 0) {
      const int error = errno;
      for (std::size_t r = 0; r < k; ++r) std::remove(files[r].path.c_str());
      for (std::size_t r = k; r < parts.size(); ++r) std::remove(parts[r].c_str());
      throw Error("IO WRITE", "cannot write \"" + files[k].path + "\": " + std::strerror(error));
    }
}

}  // namespace sf::io
