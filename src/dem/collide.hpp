#pragma once
// Narrow-phase routines, one file per pair of shapes; the table in
// narrow_phase.cpp maps shape types to them. Each returns true on overlap and
// fills the manifold with the normal pointing from its first shape to its second.
#include "sandflow/dem/narrow_phase.hpp"

namespace sf::dem {

bool collideDiscDisc(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, Manifold& m);
bool collideWallDisc(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, Manifold& m);
bool collidePolygonDisc(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                        Manifold& m);
bool collidePolygonPolygon(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                           Manifold& m);
bool collideWallPolygon(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                        Manifold& m);

bool collideSuperquadric(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                         Manifold& m);
bool collideWallSuperquadric(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                             Manifold& m);

// The area-based law shared by polygon contacts: an overlap region of area A
// whose boundaries cross along a chord of length L acts as a penetration
// A / L along the chord's normal, at the region's centroid.
bool areaContact(const std::vector<Vec2>& region, const Vec2& chordFrom, const Vec2& chordTo,
                 const Vec2& from, const Vec2& to, Manifold& m);

}  // namespace sf::dem
