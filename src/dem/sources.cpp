// Sources of the Assembly: elements that clone themselves when clear.
#include <algorithm>
#include <cmath>

#include "sandflow/core/error.hpp"
#include "sandflow/dem/assembly.hpp"

namespace sf::dem {

void Assembly::makeSource(int id, const Vec2& acceleration, double interval, int limit) {
  const int s = slot(id);
  if (!acceleration.allFinite())
    throw Error("VALUE ACCELERATION", "a source's acceleration must be finite");
  if (!(interval >= 0) || !std::isfinite(interval))
    throw Error("VALUE INTERVAL",
                "a source's interval must be >= 0, got " + formatNumber(interval));
  if (limit < -1)
    throw Error("VALUE LIMIT",
                "a source's limit must be >= -1 (-1: none), got " + std::to_string(limit));
  if (bodies_.shape[s]->type() == ShapeType::wall)
    throw Error("VALUE SOURCE", "a wall cannot be a source");
  if (std::any_of(sources_.begin(), sources_.end(), [&](const Source& x) { return x.id == id; }))
    throw Error("EXISTS SOURCE", "element " + std::to_string(id) + " is already a source");
  bodies_.ghost[s] = 1;
  bodies_.hold[s] = holdX | holdY | holdRotation;
  bodies_.v[s] = Vec2::Zero();
  bodies_.w[s] = 0;
  updateMass(s);
  touched();
  Source src;
  src.id = id;
  src.acceleration = acceleration;
  src.interval = interval;
  src.limit = limit;
  sources_.push_back(src);
}

void Assembly::removeSource(int id) {
  auto it =
      std::find_if(sources_.begin(), sources_.end(), [&](const Source& x) { return x.id == id; });
  if (it == sources_.end())
    throw Error("LOOKUP SOURCE", "element " + std::to_string(id) + " is not a source");
  const int s = slot(id);
  bodies_.ghost[s] = 0;
  sources_.erase(it);
  touched();
}

bool Assembly::overlapsAnything(int s) const {
  const Shape& shape = *bodies_.shape[s];
  const Box box = shape.bounds(bodies_.x[s], bodies_.angle[s]);
  for (int o = 0; o < bodies_.size(); ++o) {
    if (o == s || bodies_.ghost[o]) continue;
    const Shape& other = *bodies_.shape[o];
    if (!box.overlaps(other.bounds(bodies_.x[o], bodies_.angle[o]))) continue;
    Manifold m;
    if (collide(shape, {bodies_.x[s], bodies_.angle[s]}, other, {bodies_.x[o], bodies_.angle[o]},
                m))
      return true;
  }
  return false;
}

void Assembly::spawnClones() {
  for (Source& src : sources_) {
    if (src.limit >= 0 && src.made >= src.limit) continue;
    if (time_ - src.last < src.interval) continue;
    const int s = slot(src.id);
    if (overlapsAnything(s)) continue;
    ElementDef d;
    d.shape = bodies_.shape[s]->clone();
    d.material = bodies_.material[s];
    d.x = bodies_.x[s];
    d.angle = bodies_.angle[s];
    d.force = bodies_.appliedForce[s];
    d.torque = bodies_.appliedTorque[s];
    d.acceleration = src.acceleration;
    src.clones.push_back(add(std::move(d)));
    ++src.made;
    src.last = time_;
  }
}

}  // namespace sf::dem
