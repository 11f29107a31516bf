#pragma once
// What a picture of the scene shows: the state behind `view configure` and the
// options of `snapshot` (commands.md, Output).
#include <array>
#include <map>
#include <optional>
#include <string>

namespace sf::render {

enum class Field { none = 0, nodes, solid, density, pressure, velocity, vorticity };
inline constexpr const char* fieldNames[] = {"none",     "nodes",    "solid",     "density",
                                             "pressure", "velocity", "vorticity", nullptr};

enum class ColorBy { none = 0, speed, mass, bond };
inline constexpr const char* colorByNames[] = {"none", "speed", "mass", "bond", nullptr};

struct Rgb {
  unsigned char r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

struct ViewOptions {
  // nullopt: the velocity magnitude when there is a lattice, else none.
  std::optional<Field> field;
  bool vectors = false;      // velocity arrows on a sub-sampled grid
  bool streamlines = false;  // streamlines of the velocity field
  // nullopt: the range of the values shown (symmetric about zero for the
  // diverging fields: vorticity and the pressure deviation).
  std::optional<std::array<double, 2>> range;
  ColorBy colorBy = ColorBy::none;  // none: each material its own colour
  std::map<std::string, Rgb> materialColors;
  bool fill = true;       // elements filled (else outlines only: the cells show through)
  bool bonds = true;      // intact bonds as lines, breaks marked
  bool forces = false;    // contact force chains, width proportional to force
  bool label = true;      // time and step in the top corner
  bool grid = false;      // lines at a round spacing across the world window
  bool axes = false;      // the lines x = 0 and y = 0, coordinates along the edges
  bool scalebar = false;  // a bar of a round length in the bottom-right corner
  int width = 800, height = 600;
  // nullopt: the lattice, or the elements' bounding box without a lattice.
  std::optional<std::array<double, 4>> region;  // x0 y0 x1 y1
};

// The field a view shows for a scene with or without a lattice.
inline Field shownField(const ViewOptions& v, bool hasLattice) {
  if (v.field) return *v.field;
  return hasLattice ? Field::velocity : Field::none;
}

// Largest picture side: the off-screen buffers' limit with 2x supersampling.
inline constexpr int kMaxPictureSide = 8192;
// Peak memory per pixel of a picture while it is taken: drawn 2 x 2
// supersampled, the GL colour and depth buffers, the read-back and its image
// (16 bytes each per pixel of the picture), then the halved image.
inline constexpr double kPictureBytesPerPixel = 4 * 16 + 4;

}  // namespace sf::render
