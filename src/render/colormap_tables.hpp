#pragma once
// The colour-map tables behind colormap.cpp.
namespace sf::render::tables {
extern const float viridis[256][3];
inline constexpr int kCoolwarmPoints = 33;
extern const float coolwarm[kCoolwarmPoints][4];  // position in [0, 1], r, g, b
}  // namespace sf::render::tables
