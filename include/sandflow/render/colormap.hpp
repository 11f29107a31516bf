#pragma once
// Colour maps for fields and element colouring: viridis (perceptually uniform,
// the default) and Moreland's cool-warm (diverging, for signed quantities),
// plus a colour-blind-safe palette for materials and categories.
#include <optional>
#include <string>

#include "sandflow/render/view_options.hpp"

namespace sf::render {

enum class ColorMap { viridis, coolwarm };

// The colour at t in [0, 1] (clamped), interpolated in the map's table.
Rgb mapColor(ColorMap map, double t);

// A value range under a colour map. lo == hi maps everything to the middle.
struct ScalarMap {
  ColorMap map = ColorMap::viridis;
  double lo = 0, hi = 1;
  double position(double v) const { return hi > lo ? (v - lo) / (hi - lo) : 0.5; }
  Rgb operator()(double v) const { return mapColor(map, position(v)); }
};

// The k-th colour of the Okabe-Ito palette (cycling), for materials by index.
Rgb paletteColor(int k);

// "#rrggbb" or "#rgb"; nullopt otherwise.
std::optional<Rgb> parseColor(const std::string& text);
std::string formatColor(const Rgb& c);  // "#rrggbb"

}  // namespace sf::render
