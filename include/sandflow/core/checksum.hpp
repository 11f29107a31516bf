#pragma once
// CRC-32 (zlib's) of a block of bytes of any size: checkpoints' checksum and
// the scene's state hash.
#include <cstddef>
#include <cstdint>

namespace sf {

std::uint32_t crc32Of(const char* data, std::size_t size);

}  // namespace sf
