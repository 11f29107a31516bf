#include "sandflow/dem/narrow_phase.hpp"

#include "collide.hpp"

namespace sf::dem {
namespace {

using Routine = bool (*)(const Shape&, const Pose&, const Shape&, const Pose&, Manifold&);

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
    add(ShapeType::disc, ShapeType::disc, collideDiscDisc);
    add(ShapeType::wall, ShapeType::disc, collideWallDisc);
    add(ShapeType::polygon, ShapeType::disc, collidePolygonDisc);
    add(ShapeType::polygon, ShapeType::polygon, collidePolygonPolygon);
    add(ShapeType::wall, ShapeType::polygon, collideWallPolygon);
    add(ShapeType::superquadric, ShapeType::disc, collideSuperquadric);
    add(ShapeType::superquadric, ShapeType::polygon, collideSuperquadric);
    add(ShapeType::superquadric, ShapeType::superquadric, collideSuperquadric);
    add(ShapeType::wall, ShapeType::superquadric, collideWallSuperquadric);
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
