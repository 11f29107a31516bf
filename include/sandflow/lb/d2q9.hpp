#pragma once
// The D2Q9 velocity set in the thesis's numbering (physics.md §1): 0 rest, then
// counter-clockwise from +x. Odd directions are axis-aligned, even ones diagonal.
#include <array>

namespace sf::lb::d2q9 {

inline constexpr int Q = 9;
inline constexpr std::array<int, Q> ex = {0, 1, 1, 0, -1, -1, -1, 0, 1};
inline constexpr std::array<int, Q> ey = {0, 0, 1, 1, 1, 0, -1, -1, -1};
inline constexpr std::array<double, Q> w = {4.0 / 9, 1.0 / 9,  1.0 / 36, 1.0 / 9, 1.0 / 36,
                                            1.0 / 9, 1.0 / 36, 1.0 / 9,  1.0 / 36};
// Opposite direction: 1<->5, 2<->6, 3<->7, 4<->8.
inline constexpr std::array<int, Q> opposite = {0, 5, 6, 7, 8, 1, 2, 3, 4};

// Direction i rotated counter-clockwise by `quarterTurns` x 90 degrees.
constexpr int rotate(int i, int quarterTurns) {
  return i == 0 ? 0 : ((i - 1 + 2 * quarterTurns) % 8 + 8) % 8 + 1;
}

// Direction with the given lattice components, or -1.
constexpr int direction(int dx, int dy) {
  for (int i = 0; i < Q; ++i)
    if (ex[i] == dx && ey[i] == dy) return i;
  return -1;
}

}  // namespace sf::lb::d2q9
