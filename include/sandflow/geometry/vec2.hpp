#pragma once
// 2D vectors are Eigen fixed-size types: no hand-written vector algebra.
#include <Eigen/Core>

namespace sf {
using Vec2 = Eigen::Vector2d;
}  // namespace sf
