#include "sandflow/dem/narrow_phase.hpp"

#include <algorithm>
#include <cmath>

namespace sf::dem {
namespace {

using Routine = bool (*)(const Shape&, const Pose&, const Shape&, const Pose&, Manifold&);

bool discDisc(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, Manifold& m) {
  const double ra = static_cast<const Disc&>(a).radius(), rb = static_cast<const Disc&>(b).radius();
  const Vec2 d = pb.x - pa.x;
  const double dist2 = d.squaredNorm(), reach = ra + rb;
  if (dist2 >= reach * reach) return false;
  const double dist = std::sqrt(dist2);
  m.normal = dist > 0 ? Vec2(d / dist) : Vec2(1, 0);
  m.overlap = reach - dist;
  m.point = pa.x + m.normal * (ra - 0.5 * m.overlap);
  return true;
}

bool wallDisc(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, Manifold& m) {
  const auto [p, q] = static_cast<const Wall&>(a).ends(pa.x, pa.angle);
  const double r = static_cast<const Disc&>(b).radius();
  const Vec2 seg = q - p;
  const double len2 = seg.squaredNorm();
  const double t = len2 > 0 ? std::clamp((pb.x - p).dot(seg) / len2, 0.0, 1.0) : 0.0;
  const Vec2 closest = p + t * seg;
  const Vec2 d = pb.x - closest;
  const double dist2 = d.squaredNorm();
  if (dist2 >= r * r) return false;
  const double dist = std::sqrt(dist2);
  // A centre exactly on the line: push along the wall's left normal.
  m.normal = dist > 0 ? Vec2(d / dist) : Vec2(Vec2(-seg.y(), seg.x()).normalized());
  m.overlap = r - dist;
  m.point = closest - 0.5 * m.overlap * m.normal;
  return true;
}

struct Table {
  Routine routine[kShapeTypes][kShapeTypes] = {};
  bool swapped[kShapeTypes][kShapeTypes] = {};
  void add(ShapeType a, ShapeType b, Routine r) {
    routine[int(a)][int(b)] = r;
    if (a != b) {
      routine[int(b)][int(a)] = r;
      swapped[int(b)][int(a)] = true;
    }
  }
  Table() {
    add(ShapeType::disc, ShapeType::disc, discDisc);
    add(ShapeType::wall, ShapeType::disc, wallDisc);
  }
};

const Table& table() {
  static const Table t;
  return t;
}

}  // namespace

bool canCollide(ShapeType a, ShapeType b) {
  return table().routine[int(a)][int(b)] != nullptr;
}

bool collide(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, Manifold& m) {
  const Table& t = table();
  const int ia = int(a.type()), ib = int(b.type());
  const Routine r = t.routine[ia][ib];
  if (!r) return false;
  if (!t.swapped[ia][ib]) return r(a, pa, b, pb, m);
  if (!r(b, pb, a, pa, m)) return false;
  m.normal = -m.normal;
  return true;
}

}  // namespace sf::dem
