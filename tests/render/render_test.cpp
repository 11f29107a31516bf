// The picture pipeline without OpenGL: colour maps against the published
// tables, field sampling against exact fields, the scene builder's geometry.
#include <gtest/gtest.h>

#include <cmath>

#include "../kernel/coupled_helpers.hpp"
#include "sandflow/core/error.hpp"
#include "sandflow/lb/lattice.hpp"
#include "sandflow/render/colormap.hpp"
#include "sandflow/render/scene_builder.hpp"
#include "sandflow/render/text.hpp"

namespace sf::render {
namespace {

// Relative luminance (sRGB, linearised), for the perceptual-order check.
double luminance(const Rgb& c) {
  auto lin = [](int v) {
    const double x = v / 255.0;
    return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
  };
  return 0.2126 * lin(c.r) + 0.7152 * lin(c.g) + 0.0722 * lin(c.b);
}

TEST(ColorMap, ViridisEndsAndMiddleAreThePublishedValues) {
  // matplotlib's _viridis_data entries 0, 255 and the mean of 127 and 128.
  EXPECT_EQ(mapColor(ColorMap::viridis, 0.0), (Rgb{68, 1, 84}));
  EXPECT_EQ(mapColor(ColorMap::viridis, 1.0), (Rgb{253, 231, 37}));
  EXPECT_EQ(mapColor(ColorMap::viridis, 0.5), (Rgb{33, 144, 140}));
  EXPECT_EQ(mapColor(ColorMap::viridis, -3.0), mapColor(ColorMap::viridis, 0.0));  // clamped
  EXPECT_EQ(mapColor(ColorMap::viridis, NAN), (Rgb{255, 0, 255}));
}

TEST(ColorMap, ViridisLightnessRisesMonotonically) {
  double previous = -1;
  for (int k = 0; k <= 1000; ++k) {
    const double l = luminance(mapColor(ColorMap::viridis, k / 1000.0));
    EXPECT_GE(l, previous - 1e-3) << "at t = " << k / 1000.0;  // 8-bit rounding only
    previous = l;
  }
}

TEST(ColorMap, CoolWarmIsMorelandsDivergingMap) {
  EXPECT_EQ(mapColor(ColorMap::coolwarm, 0.0), (Rgb{59, 76, 192}));
  EXPECT_EQ(mapColor(ColorMap::coolwarm, 1.0), (Rgb{180, 4, 38}));
  EXPECT_EQ(mapColor(ColorMap::coolwarm, 0.5), (Rgb{221, 221, 221}));
  // Symmetric in lightness about the middle, darker towards both ends.
  for (double t : {0.1, 0.25, 0.4}) {
    EXPECT_NEAR(luminance(mapColor(ColorMap::coolwarm, t)),
                luminance(mapColor(ColorMap::coolwarm, 1 - t)), 0.06);
    EXPECT_LT(luminance(mapColor(ColorMap::coolwarm, t)),
              luminance(mapColor(ColorMap::coolwarm, 0.5)));
  }
}

TEST(ColorMap, ColoursParseAndPrint) {
  EXPECT_EQ(parseColor("#ff2000"), (Rgb{255, 32, 0}));
  EXPECT_EQ(parseColor("#f20"), (Rgb{255, 34, 0}));
  EXPECT_EQ(formatColor(Rgb{1, 171, 255}), "#01abff");
  for (const char* bad : {"", "red", "#12345", "#gg0000", "ff0000", "#ff00001"})
    EXPECT_FALSE(parseColor(bad)) << bad;
}

TEST(Halve, AveragesBlocks) {
  Image big{2, 2, {0, 0, 0, 255, 255, 255, 255, 255, 100, 0, 0, 255, 100, 0, 0, 255}};
  const Image small = halve(big);
  ASSERT_EQ(small.width, 1);
  ASSERT_EQ(small.height, 1);
  EXPECT_EQ(small.rgba, (std::vector<std::uint8_t>{114, 64, 64, 255}));
}

// A fully periodic lattice holding the given velocity field.
std::unique_ptr<lb::Lattice> latticeWith(int n, const std::function<Vec2(const Vec2&)>& u) {
  auto lattice = std::make_unique<lb::Lattice>(lb::resolve(test::periodicSquare(1.0, n, 0.01)));
  lattice->initialize([&](const Vec2& x, double& rho, Vec2& v) {
    rho = 1.0;
    v = u(x);
  });
  return lattice;
}

TEST(SampleField, VorticityOfASolidRotationIsTwiceTheRate) {
  // u = W x (x - c): exact for central differences (linear in x and y).
  const double w = 0.01;
  auto lattice = latticeWith(32, [&](const Vec2& x) { return spin(w, x - Vec2(0.5, 0.5)); });
  const FieldValues f = sampleField(*lattice, Field::vorticity, std::nullopt);
  // Away from the periodic seams, where the field jumps.
  for (int j = 2; j < 30; ++j)
    for (int i = 2; i < 30; ++i) EXPECT_NEAR(f.value[std::size_t(j) * 32 + i], 2 * w, 1e-12);
  EXPECT_EQ(f.map.map, ColorMap::coolwarm);
  EXPECT_DOUBLE_EQ(f.map.lo, -f.map.hi);  // symmetric about zero
}

TEST(SampleField, SpeedPressureAndDensityAreTheLatticesOwn) {
  auto lattice = latticeWith(16, [](const Vec2& x) { return Vec2(0.01 * x.y(), 0.0); });
  const FieldValues speed = sampleField(*lattice, Field::velocity, std::nullopt);
  const FieldValues pressure = sampleField(*lattice, Field::pressure, std::array{-1.0, 2.0});
  const double cs2 = std::pow(lattice->params().soundSpeed(), 2);
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) {
      const std::size_t k = std::size_t(j) * 16 + i;
      EXPECT_DOUBLE_EQ(speed.value[k], lattice->velocity(i, j).norm());
      EXPECT_DOUBLE_EQ(pressure.value[k], lattice->pressure(i, j) - cs2);
    }
  EXPECT_EQ(speed.map.lo, 0.0);
  EXPECT_NEAR(speed.map.hi, 0.01 * lattice->position(0, 15).y(), 1e-15);
  EXPECT_EQ(pressure.map.lo, -1.0);  // a given range is kept
  EXPECT_EQ(pressure.map.hi, 2.0);
}

TEST(SceneBuilder, ElementsLandWhereTheMappingSays) {
  sim::Manager m;
  m.createLattice(test::periodicSquare(1.0, 20, 0.01));
  const int mat = test::softMaterial(m, 1000);
  test::addDisc(m, mat, Vec2(0.3, 0.6), 0.1);
  ViewOptions v;
  v.width = 300;
  v.height = 200;
  const DrawList list = buildScene(m, v, 2);
  EXPECT_EQ(list.width, 600);
  EXPECT_EQ(list.height, 400);
  ASSERT_TRUE(list.hasField);
  EXPECT_EQ(list.field.width, 20);
  EXPECT_EQ(list.field.height, 20);
  ASSERT_EQ(list.fills.size(), 1u);
  // The fill's centre, in the supersampled buffer, is twice the picture's
  // pixel (y flipped: the list is bottom-up, the picture top-down).
  const auto p = worldToImage(m, v, 0.3, 0.6);
  EXPECT_NEAR(list.fills[0].centre.x, 2 * p[0], 1e-3);
  EXPECT_NEAR(list.fills[0].centre.y, 400 - 2 * p[1], 1e-3);
  // The outline is a circle of the disc's radius in pixels.
  const double r = std::hypot(list.fills[0].outline[0].x - list.fills[0].centre.x,
                              list.fills[0].outline[0].y - list.fills[0].centre.y);
  const double perUnit = (list.field.x1 - list.field.x0);  // the lattice is 1 wide
  EXPECT_NEAR(r, 0.1 * perUnit, 1e-3);
  // The world window keeps its aspect: the lattice is square on the screen.
  EXPECT_NEAR(list.field.x1 - list.field.x0, list.field.y1 - list.field.y0, 1e-3);
}

TEST(SceneBuilder, ArrowsFollowTheFlow) {
  sim::Manager m;
  m.createLattice(test::periodicSquare(1.0, 40, 0.01));
  m.lattice().initialize([](const Vec2&, double& rho, Vec2& u) {
    rho = 1;
    u = Vec2(0.0, -0.02);
  });
  ViewOptions v;
  v.vectors = true;
  const DrawList list = buildScene(m, v, 1);
  ASSERT_FALSE(list.fieldStrokes.empty());
  // Shafts (the first of each three strokes) point down, all the same length.
  const Stroke& first = list.fieldStrokes[0];
  for (std::size_t k = 0; k < list.fieldStrokes.size(); k += 3) {
    const Stroke& s = list.fieldStrokes[k];
    EXPECT_NEAR(s.b.x - s.a.x, 0.0, 1e-3);
    EXPECT_LT(s.b.y, s.a.y);
    EXPECT_NEAR(s.a.y - s.b.y, first.a.y - first.b.y, 1e-3);
  }
}

TEST(SceneBuilder, ValuesOutsideAFixedRangeTakeTheNearestEnd) {
  sim::Manager m;
  m.createLattice(test::periodicSquare(1.0, 8, 0.01));  // density 1 everywhere
  ViewOptions v;
  v.field = Field::density;
  for (const auto& [range, expected] :
       {std::pair{std::array{0.0, 1e-6}, Rgb{253, 231, 37}},  // far above: the top colour
        std::pair{std::array{5.0, 6.0}, Rgb{68, 1, 84}}}) {   // below: the bottom colour
    v.range = range;
    const DrawList list = buildScene(m, v, 1);
    for (std::size_t k = 0; k < list.field.rgba.size(); k += 4)
      ASSERT_EQ((Rgb{list.field.rgba[k], list.field.rgba[k + 1], list.field.rgba[k + 2]}),
                expected);
  }
}

TEST(SceneBuilder, ArrowsAndStreamlinesStayWithinTheWindow) {
  sim::Manager m;
  m.createLattice(test::periodicSquare(1.0, 256, 0.01));
  m.lattice().initialize([](const Vec2& x, double& rho, Vec2& u) {
    rho = 1;
    u = Vec2(0.01 * std::sin(6.283 * x.y()), 0.01 * std::cos(6.283 * x.x()));
  });
  ViewOptions v;
  v.vectors = v.streamlines = true;
  v.region = std::array{0.4, 0.4, 0.41, 0.41};  // 2.56 nodes across
  const DrawList list = buildScene(m, v, 1);
  ViewOptions arrowsOnly = v, streamlinesOnly = v;
  arrowsOnly.streamlines = false;
  streamlinesOnly.vectors = false;
  const DrawList arrows = buildScene(m, arrowsOnly, 1);
  const DrawList lines = buildScene(m, streamlinesOnly, 1);
  // Zoomed in, the arrow grid is every node: the nodes (i + 1/2)/256 for
  // i = 102, 103, 104 lie in [0.4, 0.41] on each axis, 3 x 3 arrows of three
  // strokes (shaft and two barbs); the 4 x 4 around them bound it above.
  EXPECT_GE(arrows.fieldStrokes.size(), 27u);
  EXPECT_LE(arrows.fieldStrokes.size(), 48u);
  // Streamlines stop about 44 pixels from their neighbours and are seeded in
  // any empty space, so the window (561 x 561 pixels) is covered by lines at
  // most about 44 pixels apart: at least area / 44 pixels of line (measured
  // 13,258, lines about 24 pixels apart). Half as many lines would fail.
  const Rect& window = lines.viewport;
  double length = 0;
  for (const Stroke& s : lines.fieldStrokes) length += std::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
  EXPECT_GE(length, (window.x1 - window.x0) * (window.y1 - window.y0) / 44.0);
  EXPECT_EQ(list.fieldStrokes.size(), arrows.fieldStrokes.size() + lines.fieldStrokes.size());
  EXPECT_LE(list.fieldStrokes.size(), 20000u);
  const Rect& port = list.viewport;
  const float margin = 0.6f * (port.x1 - port.x0);  // a node and an arrow's reach
  for (const Stroke& s : list.fieldStrokes) {
    EXPECT_GT(s.a.x, port.x0 - margin);
    EXPECT_LT(s.a.x, port.x1 + margin);
  }
}

TEST(SceneBuilder, RefusesWhatShowsNothing) {
  sim::Manager m;
  ViewOptions v;
  v.field = Field::velocity;
  EXPECT_THROW(checkView(m, v), Error);  // no lattice
  m.createLattice(test::periodicSquare(1.0, 10, 0.01));
  v.region = std::array{2.0, 2.0, 3.0, 3.0};
  EXPECT_THROW(checkView(m, v), Error);
  v.region = std::array{0.5, 0.5, 3.0, 3.0};  // partly over the lattice: fine
  EXPECT_NO_THROW(checkView(m, v));
  v.width = 0;
  EXPECT_THROW(checkOptions(v), Error);
}

// Each texel of a picture's field against the node under its centre: the
// colour of that node's value in `whole` (the field sampled at every node,
// under the same fixed range), within the colour table's rounding.
void expectTexelsShowTheirNodes(const sim::Manager& m, const DrawList& list,
                                const FieldValues& whole) {
  const Sprite& s = list.field;
  const WorldWindow& w = list.world;
  int wrong = 0;
  for (int b = 0; b < s.height; ++b)
    for (int a = 0; a < s.width; ++a) {
      const double px = s.x0 + (a + 0.5) * (s.x1 - s.x0) / s.width;
      const double py = s.y0 + (b + 0.5) * (s.y1 - s.y0) / s.height;
      const auto node = m.lattice().nodeAt(
          Vec2(w.wx0 + (px - w.px0) / w.pixelsPerUnit, w.wy0 + (py - w.py0) / w.pixelsPerUnit));
      ASSERT_TRUE(node) << a << " " << b;
      const auto [i, j] = *node;
      const Rgb want = whole.map(whole.value[std::size_t(j) * whole.nx + i]);
      const std::uint8_t* got = &s.rgba[4 * (std::size_t(b) * s.width + a)];
      wrong += std::abs(got[0] - want.r) > 3 || std::abs(got[1] - want.g) > 3 ||
               std::abs(got[2] - want.b) > 3 || got[3] != 255;
    }
  EXPECT_EQ(wrong, 0);
}

TEST(SceneBuilder, ALargeLatticeIsSampledAtThePicturesPixels) {
  // 1024^2 nodes in a 240 x 200 picture: a texel per pixel (the node under
  // its centre), not one per node.
  sim::Manager m;
  m.createLattice(test::periodicSquare(1.0, 1024, 0.01));
  m.lattice().initialize([](const Vec2& x, double& rho, Vec2& u) {
    rho = 1;
    u = Vec2(0.01 * std::sin(6.283 * x.y()), 0.01 * std::cos(6.283 * x.x()));
  });
  ViewOptions v;
  v.width = 240;
  v.height = 200;
  v.range = std::array{0.0, 0.015};
  const DrawList list = buildScene(m, v, 1);
  ASSERT_TRUE(list.hasField);
  EXPECT_LE(list.field.width, v.width);
  EXPECT_LE(list.field.height, v.height);
  EXPECT_GE(list.field.height, int(list.viewport.y1 - list.viewport.y0) - 1);
  expectTexelsShowTheirNodes(m, list, sampleField(m.lattice(), Field::velocity, v.range));
  // The workbench's view of a window it holds: its texels are its pixels,
  // each the node under the pixel's centre.
  v.region = std::array{0.1, 0.2, 0.9, 0.7};
  const DrawList view = buildView(m, v, 1);
  EXPECT_EQ(view.field.width, v.width);  // the window, widened to the view's shape, is all lattice
  EXPECT_EQ(view.field.height, v.height);
  EXPECT_FLOAT_EQ(view.field.x0, 0.0f);
  EXPECT_FLOAT_EQ(view.field.y1, float(v.height));
  expectTexelsShowTheirNodes(m, view, sampleField(m.lattice(), Field::velocity, v.range));
}

TEST(SceneBuilder, AZoomedFieldIsTheNodesInView) {
  // A window across the periodic seam x = 0: vorticity (central differences
  // that wrap) from the nodes in view and their neighbours only, the same as
  // from the whole lattice.
  sim::Manager m;
  m.createLattice(test::periodicSquare(1.0, 64, 0.01));
  m.lattice().initialize([](const Vec2& x, double& rho, Vec2& u) {
    rho = 1;
    u = Vec2(0.01 * std::sin(6.283 * x.y()) * x.x(), 0.01 * std::cos(6.283 * x.x()));
  });
  ViewOptions v;
  v.field = Field::vorticity;
  v.width = 300;
  v.height = 300;
  v.region = std::array{-0.05, 0.3, 0.25, 0.6};
  v.range = std::array{-0.5, 0.5};
  const DrawList list = buildScene(m, v, 2);
  // Nodes 0..15 across (x < 0.25), 19..38 up: one texel each.
  EXPECT_EQ(list.field.width, 16);
  EXPECT_EQ(list.field.height, 20);
  expectTexelsShowTheirNodes(m, list, sampleField(m.lattice(), Field::vorticity, v.range));
}

// Lattice speed h/dt of a scene.
double latticeSpeed(const sim::Manager& m) {
  return m.lattice().params().h / m.lattice().params().dt;
}

TEST(SceneBuilder, StillFluidDrawsNoArrowsAndNoStreamlines) {
  // Fluid at rest holds rounding noise (about 1e-17 of h/dt): it has no
  // direction to show.
  sim::Manager m;
  m.createLattice(test::periodicSquare(1.0, 32, 0.01));
  const double c = latticeSpeed(m);
  m.lattice().initialize([&](const Vec2&, double& rho, Vec2& u) {
    rho = 1;
    u = Vec2(2e-17 * c, 2e-17 * c);
  });
  ViewOptions v;
  v.vectors = v.streamlines = true;
  for (Field field : {Field::velocity, Field::none}) {
    v.field = field;
    EXPECT_TRUE(buildScene(m, v, 1).fieldStrokes.empty()) << fieldNames[int(field)];
  }
}

TEST(SceneBuilder, StillFluidKeysReadAsStill) {
  // At rest every field holds rounding noise: the keys' scales are those of
  // a flow at Mach 0.01, not the noise's (whose labels all read 0), and the
  // noise sits at the map's still end.
  sim::Manager m;
  m.createLattice(test::periodicSquare(1.0, 32, 0.01));
  const double c = latticeSpeed(m), h = m.lattice().params().h;
  m.lattice().initialize([&](const Vec2& x, double& rho, Vec2& u) {
    rho = 1 + 1e-16 * std::sin(40 * x.x());
    u = Vec2(2e-17 * c * std::sin(30 * x.y()), 2e-17 * c * std::cos(30 * x.x()));
  });
  const FieldValues speed = sampleField(m.lattice(), Field::velocity, std::nullopt);
  EXPECT_DOUBLE_EQ(speed.map.hi, 0.01 * c);
  const FieldValues vorticity = sampleField(m.lattice(), Field::vorticity, std::nullopt);
  EXPECT_DOUBLE_EQ(vorticity.map.hi, 0.01 * c / h);
  EXPECT_DOUBLE_EQ(vorticity.map.lo, -0.01 * c / h);
  const FieldValues pressure = sampleField(m.lattice(), Field::pressure, std::nullopt);
  EXPECT_DOUBLE_EQ(pressure.map.hi, (0.01 * c) * (0.01 * c));
  // A real flow keeps its own symmetric scale.
  m.lattice().initialize([&](const Vec2& x, double& rho, Vec2& u) {
    rho = 1;
    u = Vec2(0.02 * c * std::sin(6.283 * x.y()), 0.0);
  });
  const FieldValues flowing = sampleField(m.lattice(), Field::vorticity, std::nullopt);
  EXPECT_GT(flowing.map.hi, 0.1 * c);  // about 2 pi 0.02 c per unit length
  EXPECT_DOUBLE_EQ(flowing.map.lo, -flowing.map.hi);
}

TEST(SceneBuilder, ArrowsAreAsLongAsTheFlowIsFast) {
  // Under a fixed speed range, an arrow's length is its speed over the
  // range's top (90% of the grid spacing there, and no longer above it).
  ViewOptions v;
  v.vectors = true;
  auto shaft = [&](double speed) {
    sim::Manager m;
    m.createLattice(test::periodicSquare(1.0, 40, 0.01));
    const double c = latticeSpeed(m);
    v.range = std::array{0.0, 0.05 * c};
    m.lattice().initialize([&](const Vec2&, double& rho, Vec2& u) {
      rho = 1;
      u = Vec2(speed * c, 0.0);
    });
    const DrawList list = buildScene(m, v, 1);
    EXPECT_FALSE(list.fieldStrokes.empty()) << speed;
    if (list.fieldStrokes.empty()) return 0.0f;
    return list.fieldStrokes[0].b.x - list.fieldStrokes[0].a.x;
  };
  const float slow = shaft(0.01), fast = shaft(0.02), top = shaft(0.05), above = shaft(0.1);
  EXPECT_NEAR(fast / slow, 2.0, 1e-4);
  EXPECT_NEAR(top / slow, 5.0, 1e-4);
  EXPECT_FLOAT_EQ(above, top);
  EXPECT_GT(top, 10.0f);  // 90% of a grid spacing of about 22 pixels
}

TEST(Text, LabelsHaveInkAndWidth) {
  TextRenderer& text = sharedTextRenderer();
  EXPECT_GT(text.width("0.192", 13), 20.0f);
  EXPECT_LT(text.width("0.192", 13), 50.0f);
  const Sprite s = text.render("speed |u|", 26, Rgba{0, 0, 0, 255}, 10, 10);
  int inked = 0;
  for (std::size_t k = 3; k < s.rgba.size(); k += 4) inked += s.rgba[k] > 128;
  EXPECT_GT(inked, 100);
  EXPECT_FLOAT_EQ(s.x1 - s.x0, float(s.width));
}

}  // namespace
}  // namespace sf::render
