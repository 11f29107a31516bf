#pragma once
// Reading a checkpoint's columns back: one value per element or contact.
#include <string>
#include <vector>

#include "sandflow/core/byte_stream.hpp"
#include "sandflow/geometry/vec2_bytes.hpp"

namespace sf::dem::detail {

template <class T>
void getColumn(ByteReader& in, std::vector<T>& column, std::size_t n, const char* what) {
  in.get(column, what);
  if (column.size() != n) ByteReader::fail(std::string("its column of ") + what + " is short");
}

inline void getColumn(ByteReader& in, std::vector<Vec2>& column, std::size_t n, const char* what) {
  getVec2s(in, column, what);
  if (column.size() != n) ByteReader::fail(std::string("its column of ") + what + " is short");
}

}  // namespace sf::dem::detail
