#pragma once
// Vec2 values and columns in a checkpoint's payload (core/byte_stream.hpp):
// two doubles each, as they are in memory.
#include <vector>

#include "sandflow/core/byte_stream.hpp"
#include "sandflow/geometry/vec2.hpp"

namespace sf {

static_assert(sizeof(Vec2) == 2 * sizeof(double));

inline void putVec2(ByteWriter& out, const Vec2& v) {
  out.put(v.x()), out.put(v.y());
}

inline Vec2 getVec2(ByteReader& in, const char* what) {
  const double x = in.get<double>(what);
  return Vec2(x, in.get<double>(what));
}

inline void putVec2s(ByteWriter& out, const std::vector<Vec2>& vs) {
  out.put(std::uint64_t(vs.size()));
  out.putRaw(vs.data(), vs.size() * sizeof(Vec2));
}

inline void getVec2s(ByteReader& in, std::vector<Vec2>& vs, const char* what) {
  vs.resize(in.count(sizeof(Vec2), what));
  in.getRaw(vs.data(), vs.size() * sizeof(Vec2), what);
}

}  // namespace sf
