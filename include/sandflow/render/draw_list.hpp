#pragma once
// A picture as plain data, in pixel coordinates (origin bottom-left, y up, as
// OpenGL has it): what the scene builder makes from the Manager and what the
// OpenGL drawing code (gl_draw.hpp) puts into the current context. Keeping the
// two apart leaves everything but the last step testable without OpenGL, and
// lets the off-screen back ends and the GUI view share one drawing routine.
#include <cstdint>
#include <vector>

namespace sf::render {

struct Rgba {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
};

struct Point {
  float x = 0, y = 0;
};

// An RGBA image stretched over a pixel rectangle: the lattice field (one texel
// per node in view, or per pixel where nodes are smaller) or a pre-rasterised
// overlay (text, the colour bar).
struct Sprite {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // rows bottom-up, 4 bytes per texel
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool smooth = false;  // bilinear when scaled (text); else nearest (one cell per node)
};

// A filled outline, drawn as a fan about `centre` (convex or star-shaped).
struct Fill {
  Point centre;
  std::vector<Point> outline;
  Rgba colour;
};

// A straight stroke `width` pixels wide with square ends.
struct Stroke {
  Point a, b;
  float width = 1;
  Rgba colour;
};

struct Rect {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// How world coordinates map to the list's pixels: world (wx0, wy0) lands on
// pixel (px0, py0), origin bottom-left. The GUI view picks with it.
struct WorldWindow {
  double wx0 = 0, wy0 = 0, px0 = 0, py0 = 0, pixelsPerUnit = 1;
};

struct DrawList {
  int width = 0, height = 0;  // pixels
  WorldWindow world;
  Rgba background{255, 255, 255, 255};
  // The world window's viewport: the field, fills and world strokes are clipped to it.
  Rect viewport;
  Rgba viewportColour{240, 240, 240, 255};  // where there is no field
  bool hasField = false;
  Sprite field;
  std::vector<Stroke> fieldStrokes;    // arrows, streamlines: under the elements (clipped)
  std::vector<Fill> fills;             // elements, in drawing order (clipped)
  std::vector<Stroke> worldStrokes;    // outlines, bonds, forces: over them (clipped)
  std::vector<Fill> panels;            // translucent backs of keys and labels over the world
  std::vector<Stroke> overlayStrokes;  // frames and ticks, over the panels
  std::vector<Sprite> overlays;        // text and colour bars (blended)
};

// An RGBA picture, rows top-down (as PNG stores them).
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
};

// Averages 2 x 2 blocks, rounding to nearest: a picture drawn at twice its
// size comes back antialiased.
Image halve(const Image& image);

}  // namespace sf::render
