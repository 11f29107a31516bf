#pragma once
// From a read-only Manager and the view options to a draw list: the layout
// (world window, colour bars, labels) and everything in it. No OpenGL here.
#include <array>
#include <string>
#include <vector>

#include "sandflow/render/colormap.hpp"
#include "sandflow/render/draw_list.hpp"
#include "sandflow/render/view_options.hpp"
#include "sandflow/sim/manager.hpp"

namespace sf::render {

// A lattice field sampled per node, with the range and map it is shown under.
struct FieldValues {
  int nx = 0, ny = 0;
  std::vector<double> value;        // row-major from (0, 0); NaN where the field has no value
  std::vector<std::uint8_t> fluid;  // nodes that hold fluid
  ScalarMap map;
  std::string title;  // for the colour bar
};
// Throws sf::Error for Field::none / Field::nodes (not scalar fields).
FieldValues sampleField(const lb::Lattice& lattice, Field field,
                        const std::optional<std::array<double, 2>>& range);

// The world window a view shows: -region, else the lattice, else the elements'
// bounding box (padded 5%), else the unit square.
std::array<double, 4> shownRegion(const sim::Manager& m, const ViewOptions& v);

// Checks what can be checked without a scene: range, size, region's corners.
void checkOptions(const ViewOptions& v);
// Checks the options against the scene (a region that shows nothing of it, a
// field without a lattice, an empty range); throws sf::Error with the reason.
void checkView(const sim::Manager& m, const ViewOptions& v);

// The picture. Every pixel size is multiplied by `scale` (for supersampling):
// the list is for a (scale * width) x (scale * height) buffer.
DrawList buildScene(const sim::Manager& m, const ViewOptions& v, int scale = 1);
// The workbench's frame of the same scene: the world fills the whole picture
// (a -region widened about its centre to the picture's aspect; the automatic
// one fitted in the room the keys and the time leave), with the time and the
// colour keys over it on translucent panels. An editor's view may show
// empty space or a field the scene cannot have yet: only checkOptions applies
// (a field that needs a lattice shows nothing until there is one).
DrawList buildView(const sim::Manager& m, const ViewOptions& v, int scale = 1);

// Where a world point lands in a scale-1 picture of the view (pixel centre
// coordinates, origin top-left as in the PNG): for tests and picking.
std::array<double, 2> worldToImage(const sim::Manager& m, const ViewOptions& v, double x, double y);

}  // namespace sf::render
