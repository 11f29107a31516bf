// The source set: elements that clone themselves when clear.
#include "sandflow/dem/source_set.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "sandflow/core/error.hpp"
#include "sandflow/dem/narrow_phase.hpp"
#include "sandflow/geometry/vec2_bytes.hpp"

namespace sf::dem {
namespace {

bool overlapsAnything(const Bodies& b, int s) {
  const Shape& shape = *b.shape[s];
  const Box box = shape.bounds(b.x[s], b.angle[s]);
  for (int o = 0; o < b.size(); ++o) {
    if (o == s || b.ghost[o]) continue;
    const Shape& other = *b.shape[o];
    if (!box.overlaps(other.bounds(b.x[o], b.angle[o]))) continue;
    Manifold m;
    if (collide(shape, {b.x[s], b.angle[s]}, other, {b.x[o], b.angle[o]}, m)) return true;
  }
  return false;
}

}  // namespace

void SourceSet::make(Bodies& b, int s, const Vec2& acceleration, double interval, int limit) {
  const int id = b.id[s];
  if (!acceleration.allFinite())
    throw Error("VALUE ACCELERATION", "a source's acceleration must be finite");
  if (!(interval >= 0) || !std::isfinite(interval))
    throw Error("VALUE INTERVAL",
                "a source's interval must be >= 0, got " + formatNumber(interval));
  if (limit < -1)
    throw Error("VALUE LIMIT",
                "a source's limit must be >= -1 (-1: none), got " + std::to_string(limit));
  if (b.shape[s]->type() == ShapeType::wall)
    throw Error("VALUE SOURCE", "a wall cannot be a source");
  if (std::any_of(sources_.begin(), sources_.end(), [&](const Source& x) { return x.id == id; }))
    throw Error("EXISTS SOURCE", "element " + std::to_string(id) + " is already a source");
  b.ghost[s] = 1;
  b.hold[s] = holdX | holdY | holdRotation;
  b.v[s] = Vec2::Zero();
  b.w[s] = 0;
  Source src;
  src.id = id;
  src.acceleration = acceleration;
  src.interval = interval;
  src.limit = limit;
  sources_.push_back(src);
}

void SourceSet::remove(Bodies& b, int id) {
  auto it =
      std::find_if(sources_.begin(), sources_.end(), [&](const Source& x) { return x.id == id; });
  if (it == sources_.end())
    throw Error("LOOKUP SOURCE", "element " + std::to_string(id) + " is not a source");
  b.ghost[b.slot(id)] = 0;
  sources_.erase(it);
}

void SourceSet::forget(int id) {
  std::erase_if(sources_, [&](const Source& x) { return x.id == id; });
}

void SourceSet::spawn(const Bodies& b, double time, const std::function<int(ElementDef)>& add) {
  for (Source& src : sources_) {
    if (src.limit >= 0 && src.made >= src.limit) continue;
    if (time - src.last < src.interval) continue;
    const int s = b.slot(src.id);
    if (overlapsAnything(b, s)) continue;
    ElementDef d;
    d.shape = b.shape[s]->clone();
    d.material = b.material[s];
    d.x = b.x[s];
    d.angle = b.angle[s];
    d.force = b.appliedForce[s];
    d.torque = b.appliedTorque[s];
    d.acceleration = src.acceleration;
    src.clones.push_back(add(std::move(d)));
    ++src.made;
    src.last = time;
  }
}

void SourceSet::save(ByteWriter& out) const {
  out.tag("SRCS");
  out.put(std::uint64_t(sources_.size()));
  for (const Source& src : sources_) {
    out.put(std::int32_t(src.id)), putVec2(out, src.acceleration), out.put(src.interval);
    out.put(std::int32_t(src.limit)), out.put(std::int32_t(src.made)), out.put(src.last);
    out.put(src.clones);
  }
}

void SourceSet::load(ByteReader& in, const Bodies& b) {
  in.expectTag("SRCS");
  const std::size_t sources = in.count(1, "sources");
  for (std::size_t k = 0; k < sources; ++k) {
    Source src;
    src.id = in.get<std::int32_t>("source");
    if (b.slot(src.id) < 0) ByteReader::fail("it holds a source of an element it does not hold");
    src.acceleration = getVec2(in, "source"), src.interval = in.get<double>("source");
    src.limit = in.get<std::int32_t>("source"), src.made = in.get<std::int32_t>("source");
    src.last = in.get<double>("source");
    in.get(src.clones, "source clones");
    sources_.push_back(std::move(src));
  }
}

std::vector<std::string> SourceSet::validate(const Bodies& b) const {
  std::vector<std::string> problems;
  std::set<int> ids;
  for (const Source& src : sources_) {
    const std::string which = "source " + std::to_string(src.id);
    if (b.slot(src.id) < 0 || !b.ghost[b.slot(src.id)])
      problems.push_back(which + " is not a ghost element");
    if (!ids.insert(src.id).second) problems.push_back(which + " twice");
    if (src.made < 0 || (src.limit >= 0 && src.made > src.limit))
      problems.push_back(which + " made " + std::to_string(src.made) + " clones, beyond its limit");
  }
  for (int s = 0; s < b.size(); ++s)
    if (b.ghost[s] && !ids.count(b.id[s]))
      problems.push_back("element " + std::to_string(b.id[s]) + " is a ghost but no source");
  return problems;
}

}  // namespace sf::dem
