#pragma once
// The pieces buildScene puts together (internal to the render module).
#include <algorithm>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "sandflow/geometry/vec2.hpp"
#include "sandflow/render/scene_builder.hpp"

namespace sf::render {
class TextRenderer;
}

namespace sf::render::detail {

// World coordinates to buffer pixels: a uniform scale (the world window keeps
// its aspect ratio) about the window's lower-left corner.
struct WorldMap {
  double wx0 = 0, wy0 = 0;  // world point at the viewport's lower-left corner
  double px0 = 0, py0 = 0;  // that corner in pixels
  double pixelsPerUnit = 1;
  Point operator()(const Vec2& w) const {
    return {float(px0 + (w.x() - wx0) * pixelsPerUnit), float(py0 + (w.y() - wy0) * pixelsPerUnit)};
  }
  float length(double worldLength) const { return float(worldLength * pixelsPerUnit); }
  // Sides of a drawn circle: about 3 pixels each, which keeps the polygon
  // within 0.3 pixel of the circle, down to 8 sides (a radius of 4 pixels). A frame draws hundreds
  // of grains a few pixels across, and each side costs llvmpipe two triangles of its outline and
  // one of its fill.
  int circleSides(double radius) const {
    return int(std::clamp(2 * std::numbers::pi * length(radius) / 3, 8.0, 360.0));
  }
};

// A rectangle of the world.
struct Window {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return !(x1 > x0 && y1 > y0); }
  Window intersect(const Window& o) const {
    return {std::max(x0, o.x0), std::max(y0, o.y0), std::min(x1, o.x1), std::min(y1, o.y1)};
  }
};

// A colour key beside the view: a continuous bar, or swatches with names.
struct Key {
  std::string title;
  bool continuous = true;
  ScalarMap map;                                     // continuous
  std::vector<std::pair<std::string, Rgb>> entries;  // categorical
};

inline Rgba opaque(const Rgb& c, std::uint8_t alpha = 255) {
  return {c.r, c.g, c.b, alpha};
}

// Colours of the node kinds (and of fluid cells covered by a moving solid).
Rgb nodeKindColour(lb::NodeKind kind);
inline constexpr Rgb kCoveredColour{148, 103, 189};
inline constexpr Rgb kWallColour{89, 89, 89};  // non-fluid nodes under a scalar field

// The solid ratio of each interior node (row-major from (0, 0)), from the
// lattice's list of covered cells.
std::vector<float> solidRatios(const lb::Lattice& lattice);
// Whether a picture of `field` under `v` reads them (a pass over the whole
// lattice, which a frame of the speed alone does without).
bool usesSolidRatios(Field field, const ViewOptions& v);
Key nodeKindKey(const lb::Lattice& lattice, const std::vector<float>& eps);

// The nodes a field is sampled at, one per texel: texel column a shows node
// col[a], row b node row[b]; the texels tile the world rectangle
// {x0 y0 x1 y1} evenly, all on the lattice.
struct FieldGrid {
  std::vector<int> col, row;
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int width() const { return int(col.size()); }
  int height() const { return int(row.size()); }
};
// Every node of the lattice.
FieldGrid wholeLattice(const lb::Lattice& lattice);
// What a view shows of the lattice in `viewport` (buffer pixels): where a node
// covers a pixel or more, the nodes in view; else, with `pixels` (the mapping
// is the picture's own), one texel per pixel whose centre lies on the
// lattice, the node under that centre, or (a mapping the picture's may fall
// short of) texels of about a pixel tiling the lattice in view, each the node
// under its centre. Either way no more texels than pixels or nodes in view.
FieldGrid viewGrid(const lb::Lattice& lattice, const WorldMap& world, const Rect& viewport,
                   bool pixels);

// sampleField at a grid's nodes, with the solid ratios already at hand
// (needed for Field::solid); FieldValues' nx, ny are the grid's.
FieldValues sampleField(const lb::Lattice& lattice, const std::vector<float>& eps, Field field,
                        const std::optional<std::array<double, 2>>& range, const FieldGrid& grid);

Window latticeWindow(const lb::Lattice& lattice);

// The lattice layer: one texel per grid point (values sampled at `grid`, or
// null for Field::nodes).
Sprite fieldSprite(const lb::Lattice& lattice, const std::vector<float>& eps, Field field,
                   const FieldValues* values, const FieldGrid& grid, const WorldMap& world);
// Velocity arrows on a grid about `spacing` pixels apart, and streamlines,
// over the part of the lattice in the window `shown`; neither enters cells more
// than half covered by a solid. An arrow's length is its speed over
// `fullSpeed` (the speed of an arrow 90% of the spacing long, clamped there:
// a fixed range's top) or, when that is not positive, over the fastest
// arrow's; still fluid (below a billionth of h/dt) draws none, nor does an
// arrow shorter than a pixel.
void addArrows(const lb::Lattice& lattice, const std::vector<float>& eps, const WorldMap& world,
               const Window& shown, float spacing, float scale, Rgba colour, double fullSpeed,
               std::vector<Stroke>& out);
void addStreamlines(const lb::Lattice& lattice, const std::vector<float>& eps,
                    const WorldMap& world, const Window& shown, float spacing, float scale,
                    Rgba colour, std::vector<Stroke>& out);

// Elements, bonds, breaks and contact forces. `key` receives the colour key of
// -colorby (when there is one).
struct ElementColouring {
  ColorBy by = ColorBy::none;
  ScalarMap map;  // speed, mass
};
ElementColouring elementColouring(const sim::Manager& m, const ViewOptions& v, Key* key);
void addElements(const sim::Manager& m, const ViewOptions& v, const ElementColouring& colouring,
                 const WorldMap& world, float scale, DrawList& list);

// A stroke's square-ended outline around a closed polygon.
void addOutline(const std::vector<Point>& outline, float width, Rgba colour,
                std::vector<Stroke>& out);

// The lattice's rectangles and circles, filled (unless `filled` is false) and
// outlined as elements are.
void addObstacles(const lb::Lattice& lattice, bool filled, const WorldMap& world, float scale,
                  DrawList& list);

// -grid and -axes: lines across `viewport` (buffer pixels), under the elements.
void addGuideLines(const ViewOptions& v, const WorldMap& world, const Rect& viewport, float scale,
                   std::vector<Stroke>& out);
// -axes' coordinates along the bottom and left edges, and -scalebar, each on a
// translucent panel; a label that would cover a panel already in the list
// (the time, a colour key) is left out.
void addGuideLabels(const ViewOptions& v, const WorldMap& world, const Rect& viewport, float scale,
                    TextRenderer& text, DrawList& list);
// A rectangle as a fill (the back of a label or key).
Fill panel(const Rect& r, Rgba colour);

}  // namespace sf::render::detail
