// The layout of a picture -- world window, colour keys, time label -- and the
// assembly of its layers into a draw list.
#include "sandflow/render/scene_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sandflow/core/error.hpp"
#include "sandflow/core/memory.hpp"
#include "sandflow/lb/lattice.hpp"
#include "sandflow/render/text.hpp"
#include "scene_parts.hpp"

namespace sf::render {
namespace {

using detail::Key;
using detail::WorldMap;

// Sizes in pixels of a scale-1 picture.
constexpr int kFont = 13;
constexpr float kPad = 8, kBarWidth = 16, kSwatch = 12, kGap = 5, kArrowSpacing = 22;
constexpr Rgba kText{20, 20, 20, 255};
constexpr Rgba kFrame{60, 60, 60, 255};

struct Extent {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty = true;
  void add(double xa, double ya, double xb, double yb) {
    if (empty) {
      *this = {xa, ya, xb, yb, false};
      return;
    }
    x0 = std::min(x0, xa);
    y0 = std::min(y0, ya);
    x1 = std::max(x1, xb);
    y1 = std::max(y1, yb);
  }
};

Extent latticeExtent(const sim::Manager& m) {
  Extent e;
  if (!m.hasLattice()) return e;
  const auto& p = m.lattice().params();
  e.add(p.def.origin.x(), p.def.origin.y(), p.def.origin.x() + p.nx * p.h,
        p.def.origin.y() + p.ny * p.h);
  return e;
}

Extent elementExtent(const sim::Manager& m) {
  Extent e;
  const dem::Bodies& b = m.assembly().bodies();
  for (int s = 0; s < b.size(); ++s) {
    const dem::Box box =
        b.shape[std::size_t(s)]->bounds(b.x[std::size_t(s)], b.angle[std::size_t(s)]);
    e.add(box.lo.x(), box.lo.y(), box.hi.x(), box.hi.y());
  }
  return e;
}

// Labels for the ends and quarters of a range, with as many digits as it takes
// to tell them apart.
std::vector<std::string> tickLabels(double lo, double hi, int count) {
  std::vector<std::string> labels(static_cast<std::size_t>(count));
  for (int precision = 3; precision <= 12; ++precision) {
    for (int k = 0; k < count; ++k) {
      double x = lo + (hi - lo) * k / (count - 1);
      if (std::abs(x) < 1e-12 * std::max(std::abs(lo), std::abs(hi))) x = 0;  // no "-1e-17"
      char text[32];
      std::snprintf(text, sizeof text, "%.*g", precision, x);
      labels[std::size_t(k)] = text;
    }
    bool distinct = true;
    for (int k = 1; k < count; ++k)
      distinct = distinct && labels[std::size_t(k)] != labels[std::size_t(k) - 1];
    if (distinct || !(hi > lo)) break;
  }
  return labels;
}

constexpr int kTicks = 5;

float keyWidth(const Key& key, TextRenderer& text) {
  float w = text.width(key.title, kFont);
  if (key.continuous) {
    for (const std::string& label : tickLabels(key.map.lo, key.map.hi, kTicks))
      w = std::max(w, kBarWidth + kGap + text.width(label, kFont));
  } else {
    for (const auto& [name, colour] : key.entries)
      w = std::max(w, kSwatch + kGap + text.width(name, kFont));
  }
  return std::ceil(w) + 2 * kPad;
}

struct Layout {
  WorldMap world;
  Rect viewport;
  std::vector<float> keyX;  // left edge of each key column
  std::vector<float> keyWidth;
  float keyTop = 0, keyBottom = 0;
};

// The tallest a key gets over the workbench's world (scale-1 pixels).
constexpr float kViewKeyHeight = 320;

// All in scale-1 pixels; buildScene multiplies. A picture centres the world
// window, keeping its aspect, in the space the keys and the label leave; the
// workbench's view (`fill`) shows the world over the whole picture, the keys
// and the label over it: a window it was given widened about its centre to
// the picture's aspect, the automatic one (`fitted`: the scene) centred in
// the space they leave, as in a picture, so that they cover none of it.
Layout layOut(const std::array<double, 4>& region, int width, int height, bool label,
              const std::vector<Key>& keys, TextRenderer* text, bool fill, bool fitted = false) {
  Layout l;
  float keysWidth = 0;
  for (const Key& k : keys) {
    l.keyWidth.push_back(keyWidth(k, *text));
    keysWidth += l.keyWidth.back();
  }
  const float top = label ? kFont + 10.0f : 0.0f;
  const double ww = region[2] - region[0], wh = region[3] - region[1];
  float x = 0;
  if (fill) {
    // The space for the world: all of the picture, or what the keys and the label leave.
    const float ax0 = fitted ? kPad : 0, ay0 = fitted ? kPad : 0;
    const float ax1 = fitted ? std::max(ax0 + 1, float(width) - kPad - keysWidth) : float(width);
    const float ay1 = fitted ? std::max(ay0 + 1, float(height) - kPad - top) : float(height);
    const double s = std::min((ax1 - ax0) / ww, (ay1 - ay0) / wh);
    l.world = {region[0], region[1], ax0 + 0.5 * ((ax1 - ax0) - ww * s),
               ay0 + 0.5 * ((ay1 - ay0) - wh * s), s};
    l.viewport = {0, 0, float(width), float(height)};
    x = std::max(0.0f, float(width) - keysWidth);
    l.keyTop = float(height) - kPad;
    l.keyBottom = std::max(kPad, l.keyTop - kViewKeyHeight);
  } else {
    const float ax0 = kPad, ay0 = kPad;
    const float ax1 = std::max(ax0 + 1, float(width) - kPad - keysWidth);
    const float ay1 = std::max(ay0 + 1, float(height) - kPad - top);
    const double s = std::min((ax1 - ax0) / ww, (ay1 - ay0) / wh);
    const double pw = ww * s, ph = wh * s;
    const double px0 = ax0 + 0.5 * ((ax1 - ax0) - pw), py0 = ay0 + 0.5 * ((ay1 - ay0) - ph);
    l.world = {region[0], region[1], px0, py0, s};
    l.viewport = {float(px0), float(py0), float(px0 + pw), float(py0 + ph)};
    x = ax1;
    l.keyBottom = l.viewport.y0;
    l.keyTop = l.viewport.y1;
  }
  for (float w : l.keyWidth) {
    l.keyX.push_back(x);
    x += w;
  }
  return l;
}

void addFrame(const Rect& r, float width, Rgba colour, std::vector<Stroke>& out) {
  detail::addOutline({{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}}, width, colour, out);
}

void addKey(const Key& key, float x, float bottom, float top, int s, TextRenderer& text,
            DrawList& list) {
  const float f = float(s);
  const float left = (x + kPad) * f;
  const int font = kFont * s;
  const float titleBase = top * f - font * 0.8f;
  list.overlays.push_back(text.render(key.title, font, kText, left, titleBase));
  const float barTop = titleBase - font * 0.8f;
  const float barBottom = bottom * f + font * 0.4f;
  if (key.continuous) {
    Sprite bar;
    bar.width = 1;
    bar.height = std::max(2, int(barTop - barBottom));
    for (int k = 0; k < bar.height; ++k) {
      const double t = (k + 0.5) / bar.height;
      const Rgb c = mapColor(key.map.map, t);
      bar.rgba.insert(bar.rgba.end(), {c.r, c.g, c.b, 255});
    }
    bar.x0 = left;
    bar.x1 = left + kBarWidth * f;
    bar.y0 = barBottom;
    bar.y1 = barBottom + float(bar.height);
    list.overlays.push_back(std::move(bar));
    addFrame(
        {left, barBottom, left + kBarWidth * f, barBottom + float(list.overlays.back().height)}, f,
        kFrame, list.overlayStrokes);
    const auto labels = tickLabels(key.map.lo, key.map.hi, kTicks);
    const float span = float(list.overlays.back().height);
    for (int k = 0; k < kTicks; ++k) {
      const float y = barBottom + span * k / (kTicks - 1);
      list.overlayStrokes.push_back(
          {{left + kBarWidth * f, y}, {left + (kBarWidth + 3) * f, y}, f, kFrame});
      list.overlays.push_back(text.render(labels[std::size_t(k)], font, kText,
                                          left + (kBarWidth + kGap) * f, y - 0.35f * font));
    }
  } else {
    float y = barTop - kSwatch * f;
    for (const auto& [name, colour] : key.entries) {
      Sprite swatch;
      swatch.width = swatch.height = 1;
      swatch.rgba = {colour.r, colour.g, colour.b, 255};
      swatch.x0 = left;
      swatch.x1 = left + kSwatch * f;
      swatch.y0 = y;
      swatch.y1 = y + kSwatch * f;
      list.overlays.push_back(std::move(swatch));
      addFrame({left, y, left + kSwatch * f, y + kSwatch * f}, f, kFrame, list.overlayStrokes);
      list.overlays.push_back(
          text.render(name, font, kText, left + (kSwatch + kGap) * f, y + 0.15f * font));
      y -= (kSwatch + 6) * f;
    }
  }
}

std::string timeLabel(const sim::Manager& m) {
  char text[96];
  std::snprintf(text, sizeof text, "t = %.6g   step %lld", m.time(), m.stepCount());
  return text;
}

struct Keys {
  std::vector<Key> keys;
  std::optional<FieldValues> field;
  detail::ElementColouring colouring;
};

Keys keysFor(const sim::Manager& m, const ViewOptions& v, const std::vector<float>* eps,
             const detail::FieldGrid& grid) {
  Keys k;
  const Field field = shownField(v, m.hasLattice());
  if (m.hasLattice() && field == Field::nodes) {
    k.keys.push_back(detail::nodeKindKey(m.lattice(), *eps));
  } else if (m.hasLattice() && field != Field::none) {
    k.field = detail::sampleField(m.lattice(), *eps, field, v.range, grid);
    Key key;
    key.title = k.field->title;
    key.map = k.field->map;
    k.keys.push_back(std::move(key));
  }
  Key elementKey;
  k.colouring = detail::elementColouring(m, v, &elementKey);
  if (v.colorBy != ColorBy::none && !m.assembly().empty()) k.keys.push_back(std::move(elementKey));
  return k;
}

// Where the field is sampled: the lattice in view at the picture's pixels,
// laid out before the keys (whose width depends on the values) take their
// share. A view given its window fills the picture whatever the keys: there
// the texels are its pixels.
detail::FieldGrid fieldGridFor(const sim::Manager& m, const ViewOptions& v, int scale, bool fill,
                               TextRenderer& text) {
  if (!m.hasLattice()) return {};
  const bool fitted = !v.region.has_value();
  const Layout l = layOut(shownRegion(m, v), v.width, v.height, v.label, {}, &text, fill, fitted);
  WorldMap world = l.world;
  world.px0 *= scale;
  world.py0 *= scale;
  world.pixelsPerUnit *= scale;
  const float f = float(scale);
  return detail::viewGrid(
      m.lattice(), world,
      {l.viewport.x0 * f, l.viewport.y0 * f, l.viewport.x1 * f, l.viewport.y1 * f},
      fill && !fitted);
}

}  // namespace

std::array<double, 4> shownRegion(const sim::Manager& m, const ViewOptions& v) {
  if (v.region) return *v.region;
  Extent e = latticeExtent(m);
  if (e.empty) {
    e = elementExtent(m);
    if (e.empty) return {0, 0, 1, 1};
    const double pad = 0.05 * std::max({e.x1 - e.x0, e.y1 - e.y0, 1e-300});
    const double sx = e.x1 - e.x0 > 0 ? pad : std::max(pad, 1.0);
    const double sy = e.y1 - e.y0 > 0 ? pad : std::max(pad, 1.0);
    return {e.x0 - sx, e.y0 - sy, e.x1 + sx, e.y1 + sy};
  }
  return {e.x0, e.y0, e.x1, e.y1};
}

void checkOptions(const ViewOptions& v) {
  if (v.range) {
    const auto [lo, hi] = *v.range;
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo) || !std::isfinite(hi - lo))
      throw Error("VALUE RANGE", "-range {lo hi} needs finite lo < hi, got {" + formatNumber(lo) +
                                     " " + formatNumber(hi) + "}");
  }
  if (v.width < 1 || v.height < 1 || v.width > kMaxPictureSide || v.height > kMaxPictureSide)
    throw Error("VALUE SIZE", "-size {W H} must be 1 to " + std::to_string(kMaxPictureSide) +
                                  " pixels each, got {" + std::to_string(v.width) + " " +
                                  std::to_string(v.height) + "}");
  checkMemory(double(v.width) * v.height * kPictureBytesPerPixel,
              "a " + std::to_string(v.width) + " x " + std::to_string(v.height) + " picture");
  if (v.region) {
    const auto [x0, y0, x1, y1] = *v.region;
    if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1) ||
        !(x1 > x0) || !(y1 > y0) || !std::isfinite(x1 - x0) || !std::isfinite(y1 - y0))
      throw Error("VALUE REGION", "-region {x0 y0 x1 y1} needs x0 < x1 and y0 < y1, got {" +
                                      formatNumber(x0) + " " + formatNumber(y0) + " " +
                                      formatNumber(x1) + " " + formatNumber(y1) + "}");
  }
}

void checkView(const sim::Manager& m, const ViewOptions& v) {
  checkOptions(v);
  const Field field = shownField(v, m.hasLattice());
  if (field != Field::none && !m.hasLattice())
    throw Error("VALUE FIELD", std::string("-field ") + fieldNames[int(field)] +
                                   " needs a lattice, and the scene has none");
  if (v.region) {
    const auto [x0, y0, x1, y1] = *v.region;
    Extent scene = latticeExtent(m);
    const Extent el = elementExtent(m);
    if (!el.empty) scene.add(el.x0, el.y0, el.x1, el.y1);
    const double extent = scene.empty ? 0 : std::max(scene.x1 - scene.x0, scene.y1 - scene.y0);
    const double window = std::max(x1 - x0, y1 - y0);
    if (extent > 0 && (window < 1e-6 * extent || window > 1e6 * extent))
      throw Error("VALUE REGION", "-region {" + formatNumber(x0) + " " + formatNumber(y0) + " " +
                                      formatNumber(x1) + " " + formatNumber(y1) + "} is " +
                                      (window < extent ? "smaller" : "larger") +
                                      " than the scene (" + formatNumber(extent) +
                                      " across) by more than a factor of 1e6");
    if (!scene.empty && (x1 < scene.x0 || x0 > scene.x1 || y1 < scene.y0 || y0 > scene.y1)) {
      const std::string what =
          m.hasLattice() ? (el.empty ? "the lattice lies" : "the lattice and elements lie")
                         : "the elements lie";
      throw Error("VALUE REGION", "-region {" + formatNumber(x0) + " " + formatNumber(y0) + " " +
                                      formatNumber(x1) + " " + formatNumber(y1) +
                                      "} shows nothing of the scene: " + what + " within {" +
                                      formatNumber(scene.x0) + " " + formatNumber(scene.y0) + " " +
                                      formatNumber(scene.x1) + " " + formatNumber(scene.y1) + "}");
    }
  }
}

namespace {

constexpr Rgba kPanel{255, 255, 255, 200};

// The picture (`fill` false) or the workbench's frame (true; see layOut).
DrawList build(const sim::Manager& m, const ViewOptions& v, int scale, bool fill) {
  TextRenderer& text = sharedTextRenderer();
  const Field field = shownField(v, m.hasLattice());
  std::vector<float> eps;
  if (m.hasLattice() && detail::usesSolidRatios(field, v)) eps = detail::solidRatios(m.lattice());
  const detail::FieldGrid grid = fieldGridFor(m, v, scale, fill, text);
  const Keys keys = keysFor(m, v, &eps, grid);
  const Layout l = layOut(shownRegion(m, v), v.width, v.height, v.label, keys.keys, &text, fill,
                          !v.region.has_value());
  const float f = float(scale);

  DrawList list;
  list.width = v.width * scale;
  list.height = v.height * scale;
  list.viewport = {l.viewport.x0 * f, l.viewport.y0 * f, l.viewport.x1 * f, l.viewport.y1 * f};
  WorldMap world = l.world;
  world.px0 *= f;
  world.py0 *= f;
  world.pixelsPerUnit *= f;
  list.world = {world.wx0, world.wy0, world.px0, world.py0, world.pixelsPerUnit};
  // The world window the viewport shows: the region, widened in the view.
  const auto r = shownRegion(m, v);
  const double s = world.pixelsPerUnit;
  const detail::Window shown = fill ? detail::Window{world.wx0 + (list.viewport.x0 - world.px0) / s,
                                                     world.wy0 + (list.viewport.y0 - world.py0) / s,
                                                     world.wx0 + (list.viewport.x1 - world.px0) / s,
                                                     world.wy0 + (list.viewport.y1 - world.py0) / s}
                                    : detail::Window{r[0], r[1], r[2], r[3]};

  if (m.hasLattice() && field != Field::none) {
    list.hasField = true;
    list.field = detail::fieldSprite(m.lattice(), eps, field, keys.field ? &*keys.field : nullptr,
                                     grid, world);
  }
  detail::addGuideLines(v, world, list.viewport, f, list.fieldStrokes);
  if (m.hasLattice()) {
    // Arrows and streamlines in white over the dark end of viridis, else black.
    const bool dark = field == Field::velocity || field == Field::density;
    const Rgba ink = dark ? Rgba{255, 255, 255, 230} : Rgba{0, 0, 0, 230};
    if (v.streamlines)
      detail::addStreamlines(m.lattice(), eps, world, shown, kArrowSpacing * f, f, ink,
                             list.fieldStrokes);
    if (v.vectors)
      detail::addArrows(m.lattice(), eps, world, shown, kArrowSpacing * f, f, ink,
                        field == Field::velocity && v.range ? (*v.range)[1] : 0.0,
                        list.fieldStrokes);
    // Outlines only where the picture is about the cells under them.
    const bool cells = field == Field::nodes || field == Field::solid;
    detail::addObstacles(m.lattice(), v.fill && !cells, world, f, list);
  }
  detail::addElements(m, v, keys.colouring, world, f, list);

  if (!fill) addFrame(list.viewport, f, kFrame, list.overlayStrokes);
  if (v.label) {
    Sprite time = text.render(timeLabel(m), kFont * scale, kText, kPad * f,
                              float(list.height) - (kFont + 4) * f);
    if (fill)
      list.panels.push_back(detail::panel(
          {time.x0 - 4 * f, time.y0 - 2 * f, time.x1 + 4 * f, time.y1 + 2 * f}, kPanel));
    list.overlays.push_back(std::move(time));
  }
  for (std::size_t k = 0; k < keys.keys.size(); ++k) {
    if (fill)
      list.panels.push_back(detail::panel(
          {l.keyX[k] * f, l.keyBottom * f, (l.keyX[k] + l.keyWidth[k]) * f, l.keyTop * f}, kPanel));
    addKey(keys.keys[k], l.keyX[k], l.keyBottom, l.keyTop, scale, text, list);
  }
  detail::addGuideLabels(v, world, list.viewport, f, text, list);
  return list;
}

}  // namespace

DrawList buildScene(const sim::Manager& m, const ViewOptions& v, int scale) {
  checkView(m, v);
  return build(m, v, scale, false);
}

DrawList buildView(const sim::Manager& m, const ViewOptions& v, int scale) {
  checkOptions(v);
  return build(m, v, scale, true);
}

std::array<double, 2> worldToImage(const sim::Manager& m, const ViewOptions& v, double x,
                                   double y) {
  std::vector<float> eps;
  if (m.hasLattice() && detail::usesSolidRatios(shownField(v, true), v))
    eps = detail::solidRatios(m.lattice());
  const Keys keys = keysFor(m, v, &eps, fieldGridFor(m, v, 1, false, sharedTextRenderer()));
  const Layout l = layOut(shownRegion(m, v), v.width, v.height, v.label, keys.keys,
                          &sharedTextRenderer(), false);
  const WorldMap& w = l.world;
  return {w.px0 + (x - w.wx0) * w.pixelsPerUnit,
          double(v.height) - (w.py0 + (y - w.wy0) * w.pixelsPerUnit)};
}

}  // namespace sf::render
