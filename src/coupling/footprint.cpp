// Footprints of discs, convex polygons and superquadrics. Polygons answer with
// their edge lines (exact inside, a lower bound outside) and clip the cell for
// the exact area; superquadrics test the implicit function per point and use
// their sampled outline (the same polygon their contacts use) for the area
// and their row bands.
#include "sandflow/coupling/footprint.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "sandflow/dem/polygon.hpp"
#include "sandflow/dem/superquadric.hpp"
#include "sandflow/geometry/circle_area.hpp"

namespace sf::coupling {
namespace {

class CircleFootprint final : public Footprint {
 public:
  CircleFootprint(const Vec2& c, double r, bool outside) : c_(c), r_(r), outside_(outside) {
    box = {c - Vec2(r, r), c + Vec2(r, r)};
    everywhere = outside;
  }
  double distance(const Vec2& x) const override {
    const double d = (x - c_).norm() - r_;
    return outside_ ? -d : d;
  }
  bool inside(const Vec2& x) const override {
    return ((x - c_).squaredNorm() <= r_ * r_) != outside_;
  }
  double cellArea(const Vec2& lo, double h) const override {
    const double a = geometry::circleRectangleArea(c_, r_, lo, lo + Vec2(h, h));
    return outside_ ? h * h - a : a;
  }
  void rowAreas(double x0, double y0, double h, int first, int last, double* out) const override {
    if (outside_) return Footprint::rowAreas(x0, y0, h, first, last, out);
    // A row's cells left and right of its full ones come in two calls: one band.
    if (!band_ || bandY0_ != y0 || bandH_ != h)
      band_.emplace(c_, r_, y0, y0 + h), bandY0_ = y0, bandH_ = h;
    band_->areas(x0, h, first, last, out);
  }
  bool band(double y0, double y1, Band& out) const override {
    if (outside_) return false;
    const double d0 = y0 - c_.y(), d1 = y1 - c_.y();
    const double nearest = d0 <= 0 && d1 >= 0 ? 0.0 : std::min(std::abs(d0), std::abs(d1));
    const double farthest = std::max(std::abs(d0), std::abs(d1));
    out = {1, 0, 1, 0};
    if (nearest >= r_) return true;
    const double wide = std::sqrt(r_ * r_ - nearest * nearest);
    out.lo = c_.x() - wide, out.hi = c_.x() + wide;
    if (farthest < r_) {
      const double narrow = std::sqrt(r_ * r_ - farthest * farthest);
      out.fullLo = c_.x() - narrow, out.fullHi = c_.x() + narrow;
    }
    return true;
  }

 private:
  Vec2 c_;
  double r_;
  bool outside_;
  mutable std::optional<geometry::DiscBand> band_;  // the last row's
  mutable double bandY0_ = 0, bandH_ = 0;
};

// A convex polygon, counter-clockwise, with its outward edge normals.
class PolygonFootprint : public Footprint {
 public:
  explicit PolygonFootprint(std::vector<Vec2> vertices) : v_(std::move(vertices)) {
    box = {v_[0], v_[0]};
    for (std::size_t i = 0; i < v_.size(); ++i) {
      box.lo = box.lo.cwiseMin(v_[i]), box.hi = box.hi.cwiseMax(v_[i]);
      const Vec2 e = v_[(i + 1) % v_.size()] - v_[i];
      n_.push_back(Vec2(e.y(), -e.x()).normalized());
    }
  }
  double distance(const Vec2& x) const override {
    double d = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < v_.size(); ++i) d = std::max(d, n_[i].dot(x - v_[i]));
    return d;
  }
  bool inside(const Vec2& x) const override { return distance(x) <= 0; }
  // The band's part of the polygon reaches as far as its vertices in the band
  // and its edges' crossings of the band's two lines; it holds the whole band
  // where the chords at both lines overlap (convexity).
  bool band(double y0, double y1, Band& out) const override {
    constexpr double inf = std::numeric_limits<double>::infinity();
    double lo = inf, hi = -inf, lo0 = inf, hi0 = -inf, lo1 = inf, hi1 = -inf;
    for (std::size_t k = 0; k < v_.size(); ++k) {
      const Vec2 &p = v_[k], &q = v_[(k + 1) % v_.size()];
      if (p.y() >= y0 && p.y() <= y1) lo = std::min(lo, p.x()), hi = std::max(hi, p.x());
      auto crossing = [&](double y, double& l, double& h) {
        if ((p.y() - y) * (q.y() - y) > 0) return;
        const double x =
            p.y() == q.y() ? p.x() : p.x() + (y - p.y()) * (q.x() - p.x()) / (q.y() - p.y());
        const double x2 = p.y() == q.y() ? q.x() : x;
        l = std::min({l, x, x2}), h = std::max({h, x, x2});
      };
      crossing(y0, lo0, hi0);
      crossing(y1, lo1, hi1);
    }
    out.lo = std::min({lo, lo0, lo1}), out.hi = std::max({hi, hi0, hi1});
    out.fullLo = std::max(lo0, lo1), out.fullHi = std::min(hi0, hi1);
    if (!(out.lo <= out.hi)) out.lo = 1, out.hi = 0;
    if (!(out.fullLo <= out.fullHi)) out.fullLo = 1, out.fullHi = 0;
    return true;
  }
  double cellArea(const Vec2& lo, double h) const override {
    const std::vector<Vec2> cell = {lo, lo + Vec2(h, 0), lo + Vec2(h, h), lo + Vec2(0, h)};
    const std::vector<Vec2> part = dem::geometry::clip(cell, v_);
    return part.size() < 3 ? 0.0 : std::abs(dem::geometry::signedArea(part));
  }

 protected:
  std::vector<Vec2> v_, n_;
};

// The outline polygon is inscribed in the curve: the curve bulges past each
// edge by at most its sagitta, bounded here by half the longest edge.
class SuperquadricFootprint final : public PolygonFootprint {
 public:
  SuperquadricFootprint(const dem::Superquadric& s, const Vec2& x, double angle)
      : PolygonFootprint(s.world(x, angle)),
        shape_(s),
        x_(x),
        cos_(std::cos(-angle)),
        sin_(std::sin(-angle)) {
    for (std::size_t i = 0; i < v_.size(); ++i)
      slack = std::max(slack, 0.5 * (v_[(i + 1) % v_.size()] - v_[i]).norm());
    box.lo -= Vec2(slack, slack), box.hi += Vec2(slack, slack);
  }
  // Into the shape's frame, as rotated(x - x_, -angle) does, with the sine
  // and cosine taken once (they were a fifth of a superquadric bed's step).
  bool inside(const Vec2& x) const override {
    const Vec2 d = x - x_;
    return shape_.implicit(Vec2(cos_ * d.x() - sin_ * d.y(), sin_ * d.x() + cos_ * d.y())) <= 0;
  }
  // Row by row from the outline polygon: the convex curve (exponents >= 1)
  // holds the inscribed polygon, so the polygon's full interval is held by
  // the curve too; and every point of the curve lies within the slack of the
  // polygon, so the polygon's touched interval in the band grown by the slack
  // on every side holds all the curve touches. Only the cells near the
  // outline are measured, as for polygons.
  // One pass over the edges for both: the grown band's vertices and its two
  // lines' crossings (touched), the row's two lines' crossings (full).
  bool band(double y0, double y1, Band& out) const override {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const double lines[4] = {y0 - slack, y1 + slack, y0, y1};
    double lo[4] = {inf, inf, inf, inf}, hi[4] = {-inf, -inf, -inf, -inf};
    double vlo = inf, vhi = -inf;
    const std::size_t count = v_.size();
    for (std::size_t k = 0; k < count; ++k) {
      const Vec2 &p = v_[k], &q = v_[k + 1 == count ? 0 : k + 1];
      if (p.y() >= lines[0] && p.y() <= lines[1])
        vlo = std::min(vlo, p.x()), vhi = std::max(vhi, p.x());
      const double ylo = std::min(p.y(), q.y()), yhi = std::max(p.y(), q.y());
      if (yhi < lines[0] || ylo > lines[1]) continue;  // meets none of the four lines
      for (int l = 0; l < 4; ++l) {
        const double y = lines[l];
        if (y < ylo || y > yhi) continue;
        // As PolygonFootprint::band has it: a level edge gives both ends.
        const double x =
            p.y() == q.y() ? p.x() : p.x() + (y - p.y()) * (q.x() - p.x()) / (q.y() - p.y());
        const double x2 = p.y() == q.y() ? q.x() : x;
        lo[l] = std::min({lo[l], x, x2}), hi[l] = std::max({hi[l], x, x2});
      }
    }
    out.lo = std::min({vlo, lo[0], lo[1]}) - slack, out.hi = std::max({vhi, hi[0], hi[1]}) + slack;
    out.fullLo = std::max(lo[2], lo[3]), out.fullHi = std::min(hi[2], hi[3]);
    if (!(out.lo <= out.hi)) out.lo = 1, out.hi = 0;
    if (!(out.fullLo <= out.fullHi)) out.fullLo = 1, out.fullHi = 0;
    return true;
  }

 private:
  const dem::Superquadric& shape_;
  Vec2 x_;
  double cos_, sin_;  // of -angle
};

}  // namespace

std::unique_ptr<Footprint> footprintOf(const dem::Shape& shape, const Vec2& x, double angle) {
  switch (shape.type()) {
    case dem::ShapeType::disc:
      return std::make_unique<CircleFootprint>(x, static_cast<const dem::Disc&>(shape).radius(),
                                               false);
    case dem::ShapeType::polygon:
      return std::make_unique<PolygonFootprint>(
          static_cast<const dem::Polygon&>(shape).world(x, angle));
    case dem::ShapeType::superquadric:
      return std::make_unique<SuperquadricFootprint>(static_cast<const dem::Superquadric&>(shape),
                                                     x, angle);
    case dem::ShapeType::wall:
      return nullptr;
  }
  return nullptr;
}

std::unique_ptr<Footprint> circleFootprint(const Vec2& centre, double radius, bool outside) {
  return std::make_unique<CircleFootprint>(centre, radius, outside);
}

}  // namespace sf::coupling
