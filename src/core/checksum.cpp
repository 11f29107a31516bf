#include "sandflow/core/checksum.hpp"

#include <zlib.h>

#include <algorithm>

namespace sf {

std::uint32_t crc32Of(const char* data, std::size_t size) {
  uLong c = crc32(0L, Z_NULL, 0);
  // zlib takes a uInt length: large blocks go in pieces.
  for (std::size_t at = 0; at < size;) {
    const std::size_t n = std::min<std::size_t>(size - at, 1u << 30);
    c = crc32(c, reinterpret_cast<const Bytef*>(data + at), uInt(n));
    at += n;
  }
  return std::uint32_t(c);
}

}  // namespace sf
