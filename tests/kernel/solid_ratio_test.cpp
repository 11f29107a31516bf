// The solid-ratio pass (physics.md §3): exact circle-square areas, coverage of
// every shape summed back to its area, the subcell knob converging, the
// interior flags, periodic wrapping, and the row-by-row pass agreeing with the
// cell-by-cell one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <random>

#include "sandflow/coupling/coverage.hpp"
#include "sandflow/dem/polygon.hpp"
#include "sandflow/dem/superquadric.hpp"
#include "sandflow/geometry/circle_area.hpp"

namespace sf {
namespace {

using coupling::CellCover;
using coupling::CellCovers;
using coupling::Grid;

constexpr double pi = std::numbers::pi;

Grid grid(int n, double h, bool periodic = false) {
  Grid g;
  g.h = h;
  g.nx = g.ny = n;
  g.periodicX = g.periodicY = periodic;
  return g;
}

double coveredArea(const CellCovers& cells, double h) {
  double a = 0;
  for (const CellCover& c : cells) a += c.eps * h * h;
  return a;
}

// Area by brute force: m x m sample points in the rectangle.
double sampledArea(const Vec2& c, double r, const Vec2& lo, const Vec2& hi, int m) {
  int in = 0;
  for (int b = 0; b < m; ++b)
    for (int a = 0; a < m; ++a) {
      const Vec2 p =
          lo + Vec2((a + 0.5) / m * (hi.x() - lo.x()), (b + 0.5) / m * (hi.y() - lo.y()));
      in += (p - c).squaredNorm() <= r * r;
    }
  return double(in) / (m * m) * (hi.x() - lo.x()) * (hi.y() - lo.y());
}

// An independent reference: the area integrated in x over the disc's chords,
// clamp(y1, -s, s) - clamp(y0, -s, s) with s(X) = sqrt(r^2 - X^2), in closed
// form with S(X) = (X s + r^2 atan2(X, s)) / 2 (the previous implementation).
double chordArea(const Vec2& c, double r, const Vec2& lo, const Vec2& hi) {
  auto S = [r](double x) {
    const double s = std::sqrt(std::max(0.0, (r - x) * (r + x)));
    return 0.5 * (x * s + r * r * std::atan2(x, s));
  };
  auto clamped = [&](double y, double a, double b) {
    const double sign = y < 0 ? -1.0 : 1.0;
    if (std::abs(y) >= r) return sign * (S(b) - S(a));
    const double xy = std::sqrt((r - y) * (r + y));
    const double p1 = std::clamp(-xy, a, b), p2 = std::clamp(xy, a, b);
    return sign * (S(p1) - S(a)) + y * (p2 - p1) + sign * (S(b) - S(p2));
  };
  const double a = std::max(lo.x() - c.x(), -r), b = std::min(hi.x() - c.x(), r);
  if (!(a < b)) return 0.0;
  return clamped(hi.y() - c.y(), a, b) - clamped(lo.y() - c.y(), a, b);
}

TEST(CircleArea, ExactAgainstSamplingAndLimits) {
  const Vec2 c(0.3, -0.2);
  const double r = 1.1;
  EXPECT_DOUBLE_EQ(geometry::circleRectangleArea(c, r, c - Vec2(0.1, 0.1), c + Vec2(0.2, 0.3)),
                   0.3 * 0.4);  // wholly inside
  EXPECT_EQ(geometry::circleRectangleArea(c, r, Vec2(5, 5), Vec2(6, 6)), 0.0);
  EXPECT_NEAR(geometry::circleRectangleArea(c, r, Vec2(-10, -10), Vec2(10, 10)), pi * r * r, 1e-13);
  // Half and quarter discs.
  EXPECT_NEAR(geometry::circleRectangleArea(c, r, c - Vec2(2, 2), c + Vec2(0, 2)), 0.5 * pi * r * r,
              1e-13);
  EXPECT_NEAR(geometry::circleRectangleArea(c, r, c, c + Vec2(2, 2)), 0.25 * pi * r * r, 1e-13);
  // Tangent from outside: nothing.
  EXPECT_NEAR(geometry::circleRectangleArea(c, r, c + Vec2(r, -1), c + Vec2(r + 1, 1)), 0.0, 1e-15);
  // Random cells cut by the outline against 3000^2 samples (error ~1e-4 of the cell).
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int k = 0; k < 6; ++k) {
    const Vec2 lo = c + Vec2(u(rng), u(rng));
    const double h = 0.05 + 0.2 * std::abs(u(rng));
    const double exact = geometry::circleRectangleArea(c, r, lo, lo + Vec2(h, h));
    EXPECT_NEAR(exact, sampledArea(c, r, lo, lo + Vec2(h, h), 3000), 2e-4 * h * h) << k;
  }
}

// Random discs and rectangles of every relative size, and the degenerate
// placements the boundary walk must survive: corners on the circle, edges
// tangent inside and out, the disc inside but for a sliver, cells a hair
// from the centre.
TEST(CircleArea, AgreesWithTheChordIntegralEverywhere) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1), pos(0.05, 3);
  const Vec2 c(0.37, -0.81);
  double worst = 0;
  auto check = [&](double r, const Vec2& lo, const Vec2& hi) {
    const double got = geometry::circleRectangleArea(c, r, lo, hi);
    const double want = chordArea(c, r, lo, hi);
    const double scale = std::min(pi * r * r, (hi.x() - lo.x()) * (hi.y() - lo.y()));
    worst = std::max(worst, std::abs(got - want) / scale);
    ASSERT_NEAR(got, want, 1e-11 * scale)
        << "r " << r << " lo " << lo.transpose() << " hi " << hi.transpose();
  };
  for (int k = 0; k < 200000; ++k) {
    const double r = pos(rng);
    const Vec2 lo = c + 1.5 * r * Vec2(u(rng), u(rng));
    check(r, lo, lo + Vec2(pos(rng), pos(rng)) * r * (k % 2 ? 0.1 : 1.0));
  }
  for (int k = 0; k < 20000; ++k) {
    const double r = pos(rng), t = pi * u(rng), h = pos(rng) * r;
    const Vec2 on = c + r * Vec2(std::cos(t), std::sin(t));  // a point of the circle
    check(r, on, on + Vec2(h, h));                           // corners on the circle
    check(r, on - Vec2(h, h), on);
    check(r, on - Vec2(h, 0), on + Vec2(0, h));
    check(r, on - Vec2(0, h), on + Vec2(h, 0));
    check(r, c + Vec2(r, -h), c + Vec2(r + h, h));                      // tangent outside
    check(r, c - Vec2(r, r), c + Vec2(r, r + h));                       // tangent inside
    check(r, c - Vec2(2 * r, 2 * r), c + Vec2(2 * r, r * (1 - 1e-9)));  // a sliver out
    check(r, c + Vec2(1e-13, 1e-13), c + Vec2(h, h));                   // from the centre
  }
  std::printf("worst relative difference %.2e\n", worst);
}

// A row of cells measured through the band's breakpoints: each cell as the
// general circle-rectangle clip gives it (for discs up to 15 cells across,
// where the clip's own rounding is far below the tolerance), and for discs up
// to 300 cells in radius each row summing to the disc's area in the band, the
// closed form r^2 asin(d/r) + d sqrt(r^2 - d^2) evaluated in long double.
// A whole row at once gives each cell's area to the bit.
TEST(SolidRatio, DiscBandAreasEqualTheClippedAreas) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  double worstCell = 0, worstRow = 0;
  for (int t = 0; t < 300; ++t) {
    const double h = 0.01 + 0.02 * u(rng);
    const bool large = t % 6 == 0;
    const double r = h * (0.2 + (large ? 300 : 15) * u(rng));
    const Vec2 c(u(rng), u(rng));
    const int i0 = int(std::floor((c.x() - r) / h)), i1 = int(std::floor((c.x() + r) / h));
    const int j0 = int(std::floor((c.y() - r) / h)), j1 = int(std::floor((c.y() + r) / h));
    auto below = [&](double y) {  // the disc's area below height y
      const long double R = r, d = std::clamp<long double>(y - c.y(), -R, R);
      return R * R * std::asin(d / R) + d * std::sqrt(R * R - d * d);
    };
    std::vector<double> shared(std::size_t(i1 - i0 + 3));
    for (int j = j0; j <= j1; ++j) {
      const geometry::DiscBand band(c, r, j * h, (j + 1) * h);
      // The row at once (edges shared), one cell beyond each end too.
      band.areas(0.0, h, i0 - 1, i1 + 1, shared.data());
      long double row = 0;
      for (int i = i0 - 1; i <= i1 + 1; ++i) {
        const double a = band.area(i * h, (i + 1) * h);
        EXPECT_EQ(std::memcmp(&a, &shared[i - i0 + 1], sizeof a), 0) << t << " " << j << " " << i;
        row += a;
        if (large) continue;
        const Vec2 lo(i * h, j * h);
        const double e = geometry::circleRectangleArea(c, r, lo, lo + Vec2(h, h));
        worstCell = std::max(worstCell, std::abs(a - e) / (h * h));
      }
      const long double exact = below((j + 1) * h) - below(j * h);
      worstRow = std::max(worstRow, double(std::abs(row - exact) / (h * h)));
    }
  }
  std::printf("worst difference %.2e of a cell, %.2e of a cell in a row's sum\n", worstCell,
              worstRow);
  EXPECT_LT(worstCell, 1e-12);
  EXPECT_LT(worstRow, 1e-11);
}

TEST(SolidRatio, ExactCoverageSumsToTheShapeArea) {
  const double h = 0.01;
  const Grid g = grid(100, h);
  CellCovers cells;
  coupling::cover(*coupling::circleFootprint(Vec2(0.4137, 0.5521), 0.1234, false),
                  Vec2(0.4137, 0.5521), g, coupling::kExact, cells);
  EXPECT_NEAR(coveredArea(cells, h), pi * 0.1234 * 0.1234, 1e-12);

  // A rotated pentagon.
  Vec2 centroid;
  const dem::Polygon pentagon = dem::Polygon::fromVertices(
      {{0, 0}, {0.2, -0.05}, {0.3, 0.12}, {0.15, 0.25}, {-0.02, 0.15}}, centroid);
  const Vec2 at(0.5037, 0.4411);
  cells.clear();
  coupling::cover(*coupling::footprintOf(pentagon, at, 0.7), at, g, coupling::kExact, cells);
  EXPECT_NEAR(coveredArea(cells, h), pentagon.area(), 1e-12);

  // A superquadric: its sampled outline, within the outline's own area error.
  const dem::Superquadric sq(0.15, 0.08, 4, 2.5, 400);
  cells.clear();
  coupling::cover(*coupling::footprintOf(sq, at, 0.3), at, g, coupling::kExact, cells);
  EXPECT_NEAR(coveredArea(cells, h), sq.area(), 2e-4 * sq.area());
}

TEST(SolidRatio, SubcellsConvergeToTheExactRatio) {
  const double h = 0.02;
  const Grid g = grid(50, h);
  const Vec2 c(0.5011, 0.4973);
  const auto f = coupling::circleFootprint(c, 0.2037, false);
  CellCovers exact;
  coupling::cover(*f, c, g, coupling::kExact, exact);
  double previous = 1e300;
  for (int n : {1, 2, 4, 8}) {
    CellCovers cells;
    coupling::cover(*f, c, g, n, cells);
    // Same cells (the cull does not depend on n), ratios approach the exact ones.
    double err = 0;
    std::size_t k = 0;
    for (const CellCover& e : exact) {
      while (k < cells.size() && (cells[k].j < e.j || (cells[k].j == e.j && cells[k].i < e.i))) {
        err += cells[k].eps * cells[k].eps;  // covered by sampling only
        ++k;
      }
      const double got =
          k < cells.size() && cells[k].i == e.i && cells[k].j == e.j ? cells[k++].eps : 0.0;
      err += (got - e.eps) * (got - e.eps);
    }
    err = std::sqrt(err / exact.size());
    EXPECT_LT(err, previous) << n;
    previous = err;
  }
  EXPECT_LT(previous, 0.01);
}

TEST(SolidRatio, InteriorCellsHaveFullyCoveredNeighbours) {
  const double h = 0.01;
  const Grid g = grid(100, h);
  const Vec2 c(0.5, 0.5);
  CellCovers cells;
  coupling::cover(*coupling::circleFootprint(c, 0.2, false), c, g, coupling::kExact, cells);
  std::vector<double> eps(100 * 100, 0.0);
  for (const CellCover& k : cells) eps[k.j * 100 + k.i] = k.eps;
  int interior = 0;
  for (const CellCover& k : cells) {
    bool all = k.eps >= 1;
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) all = all && eps[(k.j + dj) * 100 + k.i + di] >= 1;
    EXPECT_EQ(k.interior, all) << k.i << " " << k.j;
    interior += k.interior;
    // Arms point from the centre to the cell centre.
    EXPECT_NEAR((k.arm - (Vec2((k.i + 0.5) * h, (k.j + 0.5) * h) - c)).norm(), 0, 1e-15);
  }
  // A disc of radius 20 cells: the interior is the disc shrunk by about 1.5 cells.
  EXPECT_NEAR(interior, pi * 18.5 * 18.5, 0.05 * pi * 18.5 * 18.5);
}

TEST(SolidRatio, PeriodicEdgesWrapAndWallsCut) {
  const double h = 0.01;
  const Vec2 c(0.98, 0.02);  // overlaps the right and bottom edges
  const double r = 0.1;
  CellCovers cells;
  coupling::cover(*coupling::circleFootprint(c, r, false), c, grid(100, h, true), coupling::kExact,
                  cells);
  EXPECT_NEAR(coveredArea(cells, h), pi * r * r, 1e-12);
  for (const CellCover& k : cells) {
    EXPECT_TRUE(k.i >= 0 && k.i < 100 && k.j >= 0 && k.j < 100);
    EXPECT_LE(k.arm.norm(), r + h);  // unwrapped: measured from the centre itself
  }
  cells.clear();
  coupling::cover(*coupling::circleFootprint(c, r, false), c, grid(100, h, false), coupling::kExact,
                  cells);
  // Without periodic axes only the quarter-ish inside the lattice stays.
  const double inside = geometry::circleRectangleArea(c, r, Vec2(0, 0), Vec2(1, 1));
  EXPECT_NEAR(coveredArea(cells, h), inside, 1e-12);
}

TEST(SolidRatio, ContainerCoversTheOutsideAtTheNearestImage) {
  const double h = 0.02;
  const Grid g = grid(50, h, true);
  const double r = 0.3;
  for (const Vec2& c : {Vec2(0.5, 0.5), Vec2(0.93, 0.08)}) {
    CellCovers cells;
    coupling::cover(*coupling::circleFootprint(c, r, true), c, g, coupling::kExact, cells);
    EXPECT_NEAR(coveredArea(cells, h), 1.0 - pi * r * r, 1e-12) << c.transpose();
    for (const CellCover& k : cells) EXPECT_GE(k.arm.norm(), r - h);
  }
}

// Cells that hold no bulk fluid are left out whether a chunk mask is given
// or not: the chunks only answer for cells known open, and a closed cell on
// either side of a chunk's edge (63, 64, 127, 128) still drops out.
TEST(SolidRatio, ChunkMaskLeavesOutExactlyTheClosedCells) {
  const int n = 150;
  Grid g = grid(n, 1.0, true);
  std::vector<std::uint8_t> open(std::size_t(n) * n, 1);
  for (int j = 40; j < 110; ++j)
    for (int i : {63, 64, 127, 128, 149}) open[std::size_t(j) * n + i] = 0;
  for (int i = 0; i < n; ++i) open[std::size_t(75) * n + i] = 0;  // a closed row
  std::vector<std::uint8_t> chunks(std::size_t(g.openChunksPerRow()) * n, 1);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (!open[std::size_t(j) * n + i]) chunks[g.openChunk(i, j)] = 0;
  g.open = open.data();
  const auto disc = coupling::circleFootprint(Vec2(96.3, 74.6), 40.2, false);
  const auto container = coupling::circleFootprint(Vec2(75.1, 75.3), 60.7, true);
  for (const coupling::Footprint* f : {disc.get(), container.get()}) {
    CellCovers perCell, chunked;
    g.openChunks = nullptr;
    coupling::cover(*f, Vec2(96.3, 74.6), g, coupling::kExact, perCell);
    g.openChunks = chunks.data();
    coupling::cover(*f, Vec2(96.3, 74.6), g, coupling::kExact, chunked);
    ASSERT_EQ(perCell.size(), chunked.size());
    std::size_t dropped = 0;
    for (std::size_t k = 0; k < perCell.size(); ++k) {
      EXPECT_EQ(perCell[k].i, chunked[k].i);
      EXPECT_EQ(perCell[k].j, chunked[k].j);
      EXPECT_EQ(perCell[k].eps, chunked[k].eps);
      EXPECT_TRUE(open[std::size_t(chunked[k].j) * n + chunked[k].i]);
    }
    // Closed cells were there to drop: without the mask there are more.
    g.open = nullptr;
    CellCovers all;
    coupling::cover(*f, Vec2(96.3, 74.6), g, coupling::kExact, all);
    g.open = open.data();
    for (const CellCover& c : all) dropped += !open[std::size_t(c.j) * n + c.i];
    EXPECT_GT(dropped, 100u);
    EXPECT_EQ(all.size() - dropped, chunked.size());
  }
}

// The same footprint without its bands: the pass measures it cell by cell.
class CellByCell final : public coupling::Footprint {
 public:
  explicit CellByCell(const coupling::Footprint& f) : f_(f) {
    box = f.box, slack = f.slack, everywhere = f.everywhere;
  }
  double distance(const Vec2& x) const override { return f_.distance(x); }
  bool inside(const Vec2& x) const override { return f_.inside(x); }
  double cellArea(const Vec2& lo, double h) const override { return f_.cellArea(lo, h); }

 private:
  const coupling::Footprint& f_;
};

TEST(SolidRatio, RowByRowPassEqualsTheCellByCellPass) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  Vec2 centroid;
  const dem::Polygon hexagon = dem::Polygon::fromVertices(
      {{0, 0}, {0.1, -0.03}, {0.19, 0.04}, {0.17, 0.13}, {0.06, 0.16}, {-0.03, 0.08}}, centroid);
  const dem::Polygon square =
      dem::Polygon::fromVertices({{0, 0}, {0.08, 0}, {0.08, 0.08}, {0, 0.08}}, centroid);
  // A lozenge, a rounded box and an ellipse, coarsely and finely sampled.
  const dem::Superquadric lozenge(0.09, 0.05, 1, 1.3, 16), box(0.12, 0.07, 6, 4, 64),
      ellipse(0.05, 0.14, 2, 2, 400);
  const dem::Superquadric* quadrics[] = {&lozenge, &box, &ellipse};
  int cases = 0, interior = 0, partial = 0;
  for (int t = 0; t < 400; ++t) {
    const bool periodic = t % 2;
    const double h = 0.01 + 0.02 * u(rng);
    const Grid g = grid(int(1 / h), h, periodic);
    // Anywhere, also across the edges; discs from under a cell to many cells.
    const Vec2 at(1.2 * u(rng) - 0.1, 1.2 * u(rng) - 0.1);
    const int shape = t % 4;
    const auto f = shape == 0   ? coupling::footprintOf(hexagon, at, 6.3 * u(rng))
                   : shape == 1 ? coupling::footprintOf(square, at, t % 8 == 1 ? 0.0 : 6.3 * u(rng))
                   : shape == 2 || t % 8 == 3
                       ? coupling::circleFootprint(at, h * (0.3 + 12 * u(rng)), false)
                       : coupling::footprintOf(*quadrics[t / 8 % 3], at, 6.3 * u(rng));
    for (int n : {coupling::kExact, 1, 4}) {
      CellCovers rows, cells;
      coupling::cover(*f, at, g, n, rows);
      coupling::cover(CellByCell(*f), at, g, n, cells);
      ASSERT_EQ(rows.size(), cells.size()) << t << " " << n;
      // Interior by its definition, from the row pass's own ratios (the
      // cell-by-cell pass can measure a fully held cell as 1 - 1e-13).
      std::vector<double> eps(std::size_t(g.nx) * g.ny, 0.0);
      for (const CellCover& c : rows) eps[std::size_t(c.j) * g.nx + c.i] = c.eps;
      auto full = [&](int i, int j) {
        if (periodic) i = (i + g.nx) % g.nx, j = (j + g.ny) % g.ny;
        return i >= 0 && j >= 0 && i < g.nx && j < g.ny && eps[std::size_t(j) * g.nx + i] >= 1;
      };
      for (std::size_t k = 0; k < rows.size(); ++k) {
        ASSERT_EQ(rows[k].i, cells[k].i) << t;
        ASSERT_EQ(rows[k].j, cells[k].j) << t;
        EXPECT_NEAR(rows[k].eps, cells[k].eps, 1e-12) << t << " " << k;
        EXPECT_EQ(rows[k].arm, cells[k].arm) << t << " " << k;
        bool all = true;
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di) all = all && full(rows[k].i + di, rows[k].j + dj);
        EXPECT_EQ(rows[k].interior, all) << t << " " << k;
        interior += rows[k].interior, partial += rows[k].eps < 1;
      }
      ++cases;
    }
  }
  std::printf("%d cases, %d interior and %d partial cells compared\n", cases, interior, partial);
  EXPECT_GT(interior, 10000);
  EXPECT_GT(partial, 10000);
}

// A footprint that counts what the pass asks of it: the cells it measures
// and the cells it culls by distance.
class Counting final : public coupling::Footprint {
 public:
  explicit Counting(const coupling::Footprint& f) : f_(f) {
    box = f.box, slack = f.slack, everywhere = f.everywhere;
  }
  double distance(const Vec2& x) const override { return ++distances, f_.distance(x); }
  bool inside(const Vec2& x) const override { return f_.inside(x); }
  double cellArea(const Vec2& lo, double h) const override {
    return ++measured, f_.cellArea(lo, h);
  }
  bool band(double y0, double y1, Band& out) const override { return f_.band(y0, y1, out); }
  mutable long distances = 0, measured = 0;

 private:
  const coupling::Footprint& f_;
};

// Every shape pays by its outline: a superquadric 80 cells across is covered
// row by row, its cells near the outline measured, none culled one by one.
TEST(SolidRatio, SuperquadricsAreMeasuredOnlyNearTheOutline) {
  const Grid g = grid(200, 0.01);
  const std::pair<double, double> exponents[] = {{1, 1}, {2, 2}, {2.5, 4}, {10, 10}};
  for (const auto& [m, n] : exponents) {
    const dem::Superquadric sq(0.4, 0.3, m, n, 200);
    const auto f = coupling::footprintOf(sq, Vec2(1.003, 0.987), 0.4);
    Counting counting(*f);
    CellCovers cells;
    coupling::cover(counting, Vec2(1.003, 0.987), g, coupling::kExact, cells);
    long full = 0;
    for (const CellCover& c : cells) full += c.eps >= 1;
    const long boxCells = long((f->box.hi.x() - f->box.lo.x()) / g.h + 1) *
                          long((f->box.hi.y() - f->box.lo.y()) / g.h + 1);
    std::printf("m %g n %g: %zu cells (%ld full), %ld measured, %ld culled, box %ld\n", m, n,
                cells.size(), full, counting.measured, counting.distances, boxCells);
    EXPECT_EQ(counting.distances, 0);
    EXPECT_GT(full, 2000);
    // The outline is at most about 4 x 80 cells long: a few cells each side,
    // and the slack's band (wide for a box-like shape sampled coarsely along
    // its sides: half its longest outline edge each side).
    EXPECT_LT(counting.measured, m < 5 ? 1500 : boxCells / 2);
    EXPECT_NEAR(coveredArea(cells, g.h), sq.area(), 2e-3 * sq.area());
  }
}

}  // namespace
}  // namespace sf
