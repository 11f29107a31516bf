#pragma once
// What a solid covers of the plane, in world coordinates, for one step: the
// three questions the solid-ratio pass (physics.md §3) asks of a shape.
#include <memory>
#include <vector>

#include "sandflow/dem/shape.hpp"

namespace sf::coupling {

class Footprint {
 public:
  virtual ~Footprint() = default;
  // Signed distance from x to an outline (< 0 inside) that the true outline
  // encloses and lies at most `slack` beyond, so the true signed distance is in
  // [distance - slack, distance]: the cull never misses a cell the outline
  // crosses. Exact (slack 0) for discs and convex polygons.
  virtual double distance(const Vec2& x) const = 0;
  double slack = 0.0;
  virtual bool inside(const Vec2& x) const = 0;
  // Area of the solid inside the square [lo, lo + h]^2.
  virtual double cellArea(const Vec2& lo, double h) const = 0;
  // Where the solid may be; `everywhere` for a container that is solid outside.
  dem::Box box;
  bool everywhere = false;
};

// The footprint of an element at its pose; nullptr for shapes that cover no
// area (walls).
std::unique_ptr<Footprint> footprintOf(const dem::Shape& shape, const Vec2& x, double angle);
// A disc, or with `outside` everything but the disc (a container).
std::unique_ptr<Footprint> circleFootprint(const Vec2& centre, double radius, bool outside);

}  // namespace sf::coupling
