// Assembly::configure: one element changed by hand, checked whole before any
// column is written; bonds and sources made and removed by element id.
#include <cmath>

#include "sandflow/dem/assembly.hpp"

namespace sf::dem {

void Assembly::configure(int id, const ElementEdit& e) {
  const int s = slot(id);
  Bodies& b = bodies_;
  const ShapeType type = b.shape[s]->type();
  const ShapeParts parts = partsOf(type);
  const EditPart ends = e.from ? EditPart::from : EditPart::to;
  if (e.radius && !parts.radius)
    throw EditRefused(EditPart::radius, "VALUE RADIUS", "a radius applies to discs only");
  if (e.radius && !(*e.radius > 0 && std::isfinite(*e.radius)))
    throw EditRefused(EditPart::radius, "VALUE RADIUS",
                      "a disc's radius must be > 0, got " + formatNumber(*e.radius));
  if (e.stress && !parts.stress)
    throw EditRefused(EditPart::stress, "VALUE STRESS", "a servo stress applies to walls only");
  if (e.stress && std::isinf(*e.stress))
    throw EditRefused(EditPart::stress, "VALUE STRESS", "a servo stress must be finite");
  if ((e.from || e.to) && !parts.ends)
    throw EditRefused(ends, "VALUE WALL", "ends apply to walls only");
  if ((e.from || e.to) && (e.center || e.angle))
    throw EditRefused(ends, "VALUE WALL", "give a wall its ends or its centre and angle, not both");
  if (e.material && (*e.material < 0 || *e.material >= materials_.size()))
    throw Error("LOOKUP MATERIAL", "no material " + std::to_string(*e.material));
  // The new shape, if any, and its pose.
  std::unique_ptr<Shape> shape;
  Vec2 center = e.center.value_or(b.x[s]);
  double angle = e.angle.value_or(b.angle[s]);
  if (e.from || e.to) {
    const auto& w = static_cast<const Wall&>(*b.shape[s]);
    const auto [p0, q0] = w.ends(b.x[s], b.angle[s]);
    const Vec2 p = e.from.value_or(p0), q = e.to.value_or(q0);
    if (!((q - p).norm() > 0))
      throw EditRefused(ends, "VALUE WALL",
                        "wall has zero length: its two ends are the same point");
    shape = std::make_unique<Wall>((q - p).norm(), w.thickness());
    center = 0.5 * (p + q);
    angle = std::atan2((q - p).y(), (q - p).x());
  }
  if (e.radius) shape = std::make_unique<Disc>(*e.radius);
  try {
    checkMass(shape ? *shape : *b.shape[s], materials_[e.material.value_or(b.material[s])]);
  } catch (const Error& error) {  // a new radius or material gives the mass
    if (!e.radius && !e.material) throw;
    throw EditRefused(e.radius ? EditPart::radius : EditPart::material, error.code(), error.what());
  }
  // Everything is checked: apply.
  b.x[s] = center;
  b.angle[s] = angle;
  if (shape) b.shape[s] = std::move(shape);
  if (e.material) b.material[s] = *e.material;
  if (e.velocity) b.v[s] = e.velocity->head<2>(), b.w[s] = (*e.velocity)[2];
  if (e.hold) b.hold[s] = *e.hold;
  if (e.force) b.appliedForce[s] = e.force->head<2>(), b.appliedTorque[s] = (*e.force)[2];
  if (e.acceleration) b.acceleration[s] = *e.acceleration;
  if (e.stress) {
    b.stress[s] = *e.stress;
    if (!std::isnan(*e.stress)) b.hold[s] = holdX | holdY | holdRotation;
  }
  b.started[s] = 0;  // velocities or position set by hand: restart the half step
  updateMass(s);
  touched();
}

int Assembly::bond(int idA, int idB, double stiffness, double strength, double shearStrength) {
  const int a = slot(idA), b = slot(idB);
  return bonds_.make(bodies_, materials_, a, b, stiffness, strength, shearStrength);
}

int Assembly::bondAll(const std::vector<int>& ids, double gap) {
  if (!(gap >= 0) || !std::isfinite(gap))
    throw Error("VALUE GAP", "a bond gap must be finite and >= 0");
  std::vector<int> slots;
  if (ids.empty())
    for (int s = 0; s < bodies_.size(); ++s) slots.push_back(s);
  else
    for (int id : ids) slots.push_back(slot(id));  // throws on an unknown id first
  return bonds_.makeAll(bodies_, materials_, slots, gap);
}

void Assembly::makeSource(int id, const Vec2& acceleration, double interval, int limit) {
  const int s = slot(id);
  sources_.make(bodies_, s, acceleration, interval, limit);
  updateMass(s);
  touched();
}

void Assembly::removeSource(int id) {
  sources_.remove(bodies_, id);
  touched();
}

}  // namespace sf::dem
