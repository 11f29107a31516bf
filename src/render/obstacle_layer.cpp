// The lattice's fixed obstacles drawn as shapes, filled and outlined as
// elements are: a rectangle over the cells it makes solid (what the fluid
// sees), a circle at its exact outline. The field shows their cells too, but
// only when a field is shown, and a circle's cells only after a step.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "sandflow/lb/lattice.hpp"
#include "scene_parts.hpp"

namespace sf::render::detail {
namespace {

constexpr Rgb kObstacle{150, 150, 150};
constexpr Rgba kObstacleOutline{38, 38, 38, 255};

void addShape(std::vector<Point> outline, Point centre, bool filled, float width, DrawList& list) {
  addOutline(outline, width, kObstacleOutline, list.worldStrokes);
  if (filled) list.fills.push_back({centre, std::move(outline), opaque(kObstacle)});
}

}  // namespace

void addObstacles(const lb::Lattice& lattice, bool filled, const WorldMap& world, float scale,
                  DrawList& list) {
  const auto& p = lattice.params();
  const Vec2 origin = p.def.origin;
  const double h = p.h;
  for (const lb::RectObstacle& r : lattice.rects()) {
    // Nodes whose centres lie in the rectangle are solid (topology.cpp); the
    // wall is half a spacing beyond them.
    const auto first = [&](double lo, double o, int n) {
      return std::clamp(int(std::ceil((lo - o) / h - 0.5)), 0, n);
    };
    const auto last = [&](double hi, double o, int n) {
      return std::clamp(int(std::floor((hi - o) / h - 0.5)), -1, n - 1);
    };
    const int i0 = first(r.lo.x(), origin.x(), p.nx), i1 = last(r.hi.x(), origin.x(), p.nx);
    const int j0 = first(r.lo.y(), origin.y(), p.ny), j1 = last(r.hi.y(), origin.y(), p.ny);
    Vec2 lo = r.lo, hi = r.hi;
    const bool cells = i0 <= i1 && j0 <= j1;
    if (cells) {
      lo = origin + Vec2(i0 * h, j0 * h);
      hi = origin + Vec2((i1 + 1) * h, (j1 + 1) * h);
    }
    const Point a = world(lo), b = world(hi);
    // A rectangle that holds no node does nothing: its outline only.
    addShape({{a.x, a.y}, {b.x, a.y}, {b.x, b.y}, {a.x, b.y}},
             {0.5f * (a.x + b.x), 0.5f * (a.y + b.y)}, filled && cells, scale, list);
  }
  for (const lb::CircleObstacle& c : lattice.circles()) {
    const int n = world.circleSides(c.radius);
    std::vector<Point> outline;
    for (int k = 0; k < n; ++k) {
      const double t = 2 * std::numbers::pi * k / n;
      outline.push_back(world(c.centre + c.radius * Vec2(std::cos(t), std::sin(t))));
    }
    // A container is solid outside its circle: a heavier outline, no fill.
    addShape(std::move(outline), world(c.centre), filled && !c.outside,
             c.outside ? 2.5f * scale : scale, list);
  }
}

}  // namespace sf::render::detail
