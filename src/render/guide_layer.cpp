// Guides over the world window: a grid, the axes with coordinates along the
// edges, and a scale bar (-grid, -axes, -scalebar). Spacings and the bar's
// length are round numbers (1, 2 or 5 times a power of ten) chosen from the
// zoom, so that they stay readable at any scale.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "sandflow/render/text.hpp"
#include "scene_parts.hpp"

namespace sf::render::detail {
namespace {

// Scale-1 pixels.
constexpr float kGridPixels = 40;  // grid lines at least this far apart
constexpr float kBarPixels = 60;   // the scale bar at least this long (at most 2.5 times)
constexpr int kFont = 11;
constexpr int kMaxLines = 1000;  // per axis: a guard, the spacing keeps it near 50
constexpr Rgba kGrid{128, 128, 128, 100};
constexpr Rgba kAxis{40, 40, 40, 220};
constexpr Rgba kInk{20, 20, 20, 255};
constexpr Rgba kPanel{255, 255, 255, 190};

// The smallest of 1, 2, 5 x 10^k that is at least `least`.
double roundStep(double least) {
  const double p = std::pow(10.0, std::floor(std::log10(least)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * p >= least * (1 - 1e-9)) return m * p;
  return 10 * p;
}

// A coordinate with the digits its spacing needs: 0.35, not 0.35000000000000003.
std::string coordinate(double x, double step) {
  if (std::abs(x) < 1e-9 * step) x = 0;  // no "-0"
  const int digits = int(std::floor(std::log10(std::max(std::abs(x), step)))) -
                     int(std::floor(std::log10(step) + 1e-9)) + 1;
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", std::clamp(digits, 1, 17), x);
  return text;
}

// The world window a viewport shows.
Window shownWindow(const WorldMap& w, const Rect& viewport) {
  const double s = w.pixelsPerUnit;
  return {w.wx0 + (viewport.x0 - w.px0) / s, w.wy0 + (viewport.y0 - w.py0) / s,
          w.wx0 + (viewport.x1 - w.px0) / s, w.wy0 + (viewport.y1 - w.py0) / s};
}

// Multiples k of `step` within [lo, hi].
std::pair<long long, long long> multiples(double lo, double hi, double step) {
  long long first = (long long)std::ceil(lo / step), last = (long long)std::floor(hi / step);
  last = std::min(last, first + kMaxLines);
  return {first, last};
}

bool overlaps(const Rect& a, const Rect& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

Rect bounds(const Fill& f) {
  Rect r{f.centre.x, f.centre.y, f.centre.x, f.centre.y};
  for (const Point& p : f.outline)
    r = {std::min(r.x0, p.x), std::min(r.y0, p.y), std::max(r.x1, p.x), std::max(r.y1, p.y)};
  return r;
}

bool unobstructed(const Rect& r, const DrawList& list) {
  return std::none_of(list.panels.begin(), list.panels.end(),
                      [&](const Fill& f) { return overlaps(r, bounds(f)); });
}

// A text sprite with a translucent back, unless it would cover another panel
// or leave `inside`.
void addLabel(Sprite s, float margin, const Rect& inside, DrawList& list) {
  const Rect r{s.x0 - margin, s.y0, s.x1 + margin, s.y1};
  if (r.x0 < inside.x0 || r.x1 > inside.x1 || r.y0 < inside.y0 || r.y1 > inside.y1 ||
      !unobstructed(r, list))
    return;
  list.panels.push_back(panel(r, kPanel));
  list.overlays.push_back(std::move(s));
}

}  // namespace

Fill panel(const Rect& r, Rgba colour) {
  return {{0.5f * (r.x0 + r.x1), 0.5f * (r.y0 + r.y1)},
          {{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}},
          colour};
}

void addGuideLines(const ViewOptions& v, const WorldMap& world, const Rect& viewport, float scale,
                   std::vector<Stroke>& out) {
  if (!v.grid && !v.axes) return;
  const Window w = shownWindow(world, viewport);
  const double s = world.pixelsPerUnit;
  const auto x = [&](double wx) { return float(world.px0 + (wx - world.wx0) * s); };
  const auto y = [&](double wy) { return float(world.py0 + (wy - world.wy0) * s); };
  if (v.grid) {
    const double step = roundStep(kGridPixels * scale / s);
    const auto [i0, i1] = multiples(w.x0, w.x1, step);
    for (long long i = i0; i <= i1; ++i)
      out.push_back({{x(i * step), viewport.y0}, {x(i * step), viewport.y1}, scale, kGrid});
    const auto [j0, j1] = multiples(w.y0, w.y1, step);
    for (long long j = j0; j <= j1; ++j)
      out.push_back({{viewport.x0, y(j * step)}, {viewport.x1, y(j * step)}, scale, kGrid});
  }
  if (v.axes) {
    if (w.x0 <= 0 && 0 <= w.x1)
      out.push_back({{x(0), viewport.y0}, {x(0), viewport.y1}, 1.5f * scale, kAxis});
    if (w.y0 <= 0 && 0 <= w.y1)
      out.push_back({{viewport.x0, y(0)}, {viewport.x1, y(0)}, 1.5f * scale, kAxis});
  }
}

void addGuideLabels(const ViewOptions& v, const WorldMap& world, const Rect& viewport, float scale,
                    TextRenderer& text, DrawList& list) {
  const double s = world.pixelsPerUnit;
  const int font = int(std::lround(kFont * scale));
  const float pad = 3 * scale;
  if (v.scalebar) {
    const double length = roundStep(kBarPixels * scale / s);
    const float bar = float(length * s);
    const std::string label = coordinate(length, length);
    const float labelWidth = text.width(label, font);
    const float width = std::max(bar, labelWidth) + 4 * pad, height = 1.4f * font + 5 * pad;
    // Bottom right, else bottom left when a key is there.
    Rect r{viewport.x1 - 4 * pad - width, viewport.y0 + 4 * pad, viewport.x1 - 4 * pad,
           viewport.y0 + 4 * pad + height};
    if (!unobstructed(r, list))
      r = {viewport.x0 + 4 * pad, r.y0, viewport.x0 + 4 * pad + width, r.y1};
    list.panels.push_back(panel(r, kPanel));
    const float cx = 0.5f * (r.x0 + r.x1), by = r.y0 + 2 * pad;
    const Point a{cx - 0.5f * bar, by}, b{cx + 0.5f * bar, by};
    list.overlayStrokes.push_back({a, b, 2 * scale, kInk});
    list.overlayStrokes.push_back({a, {a.x, a.y + 2 * pad}, scale, kInk});
    list.overlayStrokes.push_back({b, {b.x, b.y + 2 * pad}, scale, kInk});
    list.overlays.push_back(text.render(label, font, kInk, cx, by + 3 * pad, 0.5f));
  }
  if (!v.axes) return;
  // Labels on every grid line, else every 2nd, 5th or 10th: as close as the
  // longest of them allows.
  const double grid = roundStep(kGridPixels * scale / s);
  const Window w = shownWindow(world, viewport);
  double step = grid;
  for (int k : {1, 2, 5, 10}) {
    step = k * grid;
    const float widest = std::max(text.width(coordinate(w.x0, step), font),
                                  text.width(coordinate(w.x1, step), font));
    if (step * s >= widest + 6 * pad) break;
  }
  const float tick = 4 * scale;
  // The bottom row of labels is kept clear of the left column's and back.
  const Rect bottomRow{viewport.x0 + 6 * font, viewport.y0, viewport.x1, viewport.y1};
  const Rect leftColumn{viewport.x0, viewport.y0 + 2 * font, viewport.x1, viewport.y1};
  const auto [i0, i1] = multiples(w.x0, w.x1, step);
  for (long long i = i0; i <= i1; ++i) {
    const float x = float(world.px0 + (i * step - world.wx0) * s);
    list.overlayStrokes.push_back({{x, viewport.y0}, {x, viewport.y0 + tick}, scale, kAxis});
    addLabel(text.render(coordinate(i * step, step), font, kInk, x, viewport.y0 + tick + pad, 0.5f),
             pad, bottomRow, list);
  }
  const auto [j0, j1] = multiples(w.y0, w.y1, step);
  for (long long j = j0; j <= j1; ++j) {
    const float y = float(world.py0 + (j * step - world.wy0) * s);
    list.overlayStrokes.push_back({{viewport.x0, y}, {viewport.x0 + tick, y}, scale, kAxis});
    addLabel(text.render(coordinate(j * step, step), font, kInk, viewport.x0 + tick + 2 * pad,
                         y - 0.35f * font),
             pad, leftColumn, list);
  }
}

}  // namespace sf::render::detail
