#pragma once
// What coupler.cpp and implicit_coupling.cpp share.
#include "sandflow/dem/bodies.hpp"
#include "sandflow/geometry/vec2.hpp"
#include "sandflow/lb/lattice.hpp"

namespace sf::coupling::detail {

// Static buoyancy of slot s on the immersed area: the element's own area when
// the lattice holds all of it, `submerged` cells' area when it sticks out.
Vec2 buoyancyOf(const dem::Bodies& b, int s, double submerged, const lb::Lattice& lattice,
                const Vec2& gravity);

}  // namespace sf::coupling::detail
