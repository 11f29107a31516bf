// Colour maps: table interpolation, the palette, colour parsing.
#include "sandflow/render/colormap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "colormap_tables.hpp"

namespace sf::render {
namespace {

unsigned char channel(double c) {
  return static_cast<unsigned char>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
}

Rgb viridisAt(double t) {
  const double x = t * 255.0;
  const int k = std::min(254, int(x));
  const double f = x - k;
  const float* a = tables::viridis[k];
  const float* b = tables::viridis[k + 1];
  return {channel(a[0] + f * (b[0] - a[0])), channel(a[1] + f * (b[1] - a[1])),
          channel(a[2] + f * (b[2] - a[2]))};
}

Rgb coolwarmAt(double t) {
  // The table's positions are evenly spaced (1/32 apart).
  const double x = t * (tables::kCoolwarmPoints - 1);
  const int k = std::min(tables::kCoolwarmPoints - 2, int(x));
  const double f = x - k;
  const float* a = tables::coolwarm[k];
  const float* b = tables::coolwarm[k + 1];
  return {channel(a[1] + f * (b[1] - a[1])), channel(a[2] + f * (b[2] - a[2])),
          channel(a[3] + f * (b[3] - a[3]))};
}

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

Rgb mapColor(ColorMap map, double t) {
  if (std::isnan(t)) return {255, 0, 255};  // magenta: never a value of either map
  t = std::clamp(t, 0.0, 1.0);
  return map == ColorMap::viridis ? viridisAt(t) : coolwarmAt(t);
}

Rgb paletteColor(int k) {
  // Okabe & Ito (2008), colour-blind safe; black left out (outlines are dark).
  static const Rgb palette[] = {{230, 159, 0}, {86, 180, 233}, {0, 158, 115},   {240, 228, 66},
                                {0, 114, 178}, {213, 94, 0},   {204, 121, 167}, {153, 153, 153}};
  const int n = int(std::size(palette));
  return palette[((k % n) + n) % n];
}

std::optional<Rgb> parseColor(const std::string& text) {
  if (text.size() != 4 && text.size() != 7) return std::nullopt;
  if (text[0] != '#') return std::nullopt;
  const bool shortForm = text.size() == 4;
  unsigned char c[3];
  for (int k = 0; k < 3; ++k) {
    const int hi = hexDigit(text[shortForm ? 1 + k : 1 + 2 * k]);
    const int lo = hexDigit(text[shortForm ? 1 + k : 2 + 2 * k]);
    if (hi < 0 || lo < 0) return std::nullopt;
    c[k] = static_cast<unsigned char>(16 * hi + lo);
  }
  return Rgb{c[0], c[1], c[2]};
}

std::string formatColor(const Rgb& c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
  return text;
}

}  // namespace sf::render
