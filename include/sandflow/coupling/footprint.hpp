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
  // Areas of the cells [x0 + i h, x0 + (i + 1) h] x [y0, y0 + h] of one row,
  // i = first..last, into out[i - first]: cellArea cell by cell, unless a shape
  // has a faster way for a whole row.
  virtual void rowAreas(double x0, double y0, double h, int first, int last, double* out) const {
    for (int i = first; i <= last; ++i) out[i - first] = cellArea(Vec2(x0 + i * h, y0), h);
  }
  // For a convex solid whose `inside` is exact: within the band y0 <= y <= y1,
  // the x-interval it touches [lo, hi] and the x-interval [fullLo, fullHi]
  // where it holds the whole band (an empty one has lo > hi). Lets the pass
  // classify a row of cells at once. False when the shape cannot say; the
  // pass then asks `distance` cell by cell.
  struct Band {
    double lo, hi, fullLo, fullHi;
  };
  virtual bool band(double y0, double y1, Band& out) const {
    (void)y0, (void)y1, (void)out;
    return false;
  }
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
