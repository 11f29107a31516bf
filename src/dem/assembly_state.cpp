// An assembly's state in a checkpoint (Assembly::saveState / loadState).
#include <cmath>

#include "sandflow/dem/assembly.hpp"
#include "sandflow/geometry/vec2_bytes.hpp"
#include "shape_state.hpp"

namespace sf::dem {
namespace {

// The law and, in the next byte, the normal-force mode (0, signed, in files
// written before there was one).
void putMaterial(ByteWriter& out, const Material& m) {
  out.put(m.name), out.put(std::int32_t(m.law) | std::int32_t(m.normalForce) << 8);
  for (double v : {m.density, m.kn, m.ks, m.friction, m.restitution, m.damping, m.bondStiffness,
                   m.bondStrength, m.youngs, m.poisson})
    out.put(v);
}

Material getMaterial(ByteReader& in) {
  Material m;
  in.get(m.name, "material name");
  const auto law = in.get<std::int32_t>("material");
  if ((law & 0xff) > 1 || (law >> 8) < 0 || (law >> 8) > 1)
    ByteReader::fail("it holds an unknown contact law");
  m.law = ContactLaw(law & 0xff);
  m.normalForce = NormalForce(law >> 8);
  for (double* v : {&m.density, &m.kn, &m.ks, &m.friction, &m.restitution, &m.damping,
                    &m.bondStiffness, &m.bondStrength, &m.youngs, &m.poisson})
    *v = in.get<double>("material");
  return m;
}

// A column read back must hold one value per element.
template <class T>
void getColumn(ByteReader& in, std::vector<T>& column, std::size_t n, const char* what) {
  in.get(column, what);
  if (column.size() != n) ByteReader::fail(std::string("its column of ") + what + " is short");
}

void getColumn(ByteReader& in, std::vector<Vec2>& column, std::size_t n, const char* what) {
  getVec2s(in, column, what);
  if (column.size() != n) ByteReader::fail(std::string("its column of ") + what + " is short");
}

bool allFinite(const std::vector<double>& column) {
  for (double v : column)
    if (!std::isfinite(v)) return false;
  return true;
}

bool allFinite(const std::vector<Vec2>& column) {
  for (const Vec2& v : column)
    if (!v.allFinite()) return false;
  return true;
}

void putBond(ByteWriter& out, const Bond& b) {
  out.put(std::int32_t(b.id)), out.put(std::int32_t(b.idA)), out.put(std::int32_t(b.idB));
  putVec2(out, b.anchorA), putVec2(out, b.anchorB), out.put(b.length), putVec2(out, b.normal0);
  for (double v : {b.angleA0, b.angleB0, b.damping, b.stiffness, b.strength, b.shearStrength})
    out.put(v);
  putVec2(out, b.force);
}

Bond getBond(ByteReader& in) {
  Bond b;
  b.id = in.get<std::int32_t>("bond"), b.idA = in.get<std::int32_t>("bond");
  b.idB = in.get<std::int32_t>("bond");
  b.anchorA = getVec2(in, "bond"), b.anchorB = getVec2(in, "bond");
  b.length = in.get<double>("bond"), b.normal0 = getVec2(in, "bond");
  for (double* v :
       {&b.angleA0, &b.angleB0, &b.damping, &b.stiffness, &b.strength, &b.shearStrength})
    *v = in.get<double>("bond");
  b.force = getVec2(in, "bond");
  return b;
}

}  // namespace

void Assembly::saveState(ByteWriter& out) const {
  out.tag("MATS");
  out.put(std::int32_t(materials_.size()));
  for (int i = 0; i < materials_.size(); ++i) putMaterial(out, materials_[i]);

  out.tag("ELEM");
  out.put(std::int32_t(integrator)), out.put(maxOverlap), out.put(vectorPass);
  const Bodies& b = bodies_;
  out.put(b.id);
  for (int s = 0; s < b.size(); ++s) saveShape(out, *b.shape[s]);
  out.put(b.material);
  for (const auto* c : {&b.x, &b.v, &b.vHalf, &b.force, &b.appliedForce, &b.acceleration,
                        &b.fluidForce, &b.buoyancy})
    putVec2s(out, *c);
  for (const auto* c :
       {&b.angle, &b.w, &b.wHalf, &b.torque, &b.appliedTorque, &b.fluidTorque, &b.stress})
    out.put(*c);
  out.put(b.hold), out.put(b.started), out.put(b.ghost);

  out.tag("CONT");
  const ContactList& l = list_;
  const ContactHistory& h = l.now();
  out.put(l.a), out.put(l.b), out.put(l.idA), out.put(l.idB), out.put(l.discs);
  out.put(std::uint64_t(l.vectorCount));
  out.put(h.touching);
  for (const auto* c :
       {&h.nx, &h.ny, &h.sx, &h.sy, &l.fx, &l.fy, &l.px, &l.py, &l.overlap, &l.ta, &l.tb})
    out.put(*c);
  // The broad phase as it stands: the next step rebuilds when this one would.
  out.put(pairsValid_ && !lawsStale()), out.put(slotsMoved_), out.put(skin_);
  putVec2s(out, builtAt_);
  out.put(builtAngle_);

  out.tag("BOND");
  out.put(std::uint64_t(bonds_.size()));
  for (const Bond& bond : bonds_) putBond(out, bond);
  out.put(std::uint64_t(breaks_.size()));
  for (const BondBreak& k : breaks_) {
    out.put(k.time), putVec2(out, k.at), out.put(k.angle);
    out.put(std::int32_t(k.bond)), out.put(std::int32_t(k.idA)), out.put(std::int32_t(k.idB));
    out.put(k.tension);
  }
  out.put(std::int32_t(nextBondId_));

  out.tag("SRCS");
  out.put(std::uint64_t(sources_.size()));
  for (const Source& src : sources_) {
    out.put(std::int32_t(src.id)), putVec2(out, src.acceleration), out.put(src.interval);
    out.put(std::int32_t(src.limit)), out.put(std::int32_t(src.made)), out.put(src.last);
    out.put(src.clones);
  }
  out.put(time_);
}

void Assembly::loadState(ByteReader& in) {
  if (!empty() || !bonds_.empty() || !sources_.empty())
    throw Error("STATE ASSEMBLY", "a checkpoint loads into an empty assembly only");
  in.expectTag("MATS");
  const auto materials = in.get<std::int32_t>("materials");
  if (materials < 1 || std::size_t(materials) > in.left())
    ByteReader::fail("it holds " + std::to_string(materials) + " materials");
  materials_.replace(0, getMaterial(in));  // the table starts with one
  for (int i = 1; i < materials; ++i) materials_.add(getMaterial(in));

  in.expectTag("ELEM");
  const auto integ = in.get<std::int32_t>("integrator");
  if (integ < 0 || integ > 2) ByteReader::fail("it holds an unknown integrator");
  integrator = Integrator(integ);
  maxOverlap = in.get<double>("settings");
  if (!(maxOverlap > 0 && maxOverlap <= 1)) ByteReader::fail("it holds a bad overlap limit");
  vectorPass = in.getBool("settings");
  std::vector<int> ids;
  in.get(ids, "element ids");
  const std::size_t n = ids.size();
  for (std::size_t s = 0; s < n; ++s) {
    if (ids[s] < 0 || bodies_.slot(ids[s]) >= 0)
      ByteReader::fail("it holds element id " + std::to_string(ids[s]) + " twice or negative");
    bodies_.push(ids[s]);
  }
  Bodies& b = bodies_;
  for (std::size_t s = 0; s < n; ++s) b.shape[s] = loadShape(in);
  getColumn(in, b.material, n, "materials");
  for (auto* c : {&b.x, &b.v, &b.vHalf, &b.force, &b.appliedForce, &b.acceleration, &b.fluidForce,
                  &b.buoyancy}) {
    getColumn(in, *c, n, "element vectors");
    if (!allFinite(*c)) ByteReader::fail("it holds an element value that is not finite");
  }
  for (auto* c : {&b.angle, &b.w, &b.wHalf, &b.torque, &b.appliedTorque, &b.fluidTorque}) {
    getColumn(in, *c, n, "element values");
    if (!allFinite(*c)) ByteReader::fail("it holds an element value that is not finite");
  }
  getColumn(in, b.stress, n, "plate stresses");  // NaN: no servo
  for (double v : b.stress)
    if (std::isinf(v)) ByteReader::fail("it holds an infinite plate stress");
  getColumn(in, b.hold, n, "holds");
  getColumn(in, b.started, n, "element flags");
  getColumn(in, b.ghost, n, "element flags");
  for (std::size_t s = 0; s < n; ++s) {
    if (b.material[s] < 0 || b.material[s] >= materials_.size())
      ByteReader::fail("it holds an element of an unknown material");
    if (b.hold[s] > 7 || b.started[s] > 1 || b.ghost[s] > 1)
      ByteReader::fail("it holds a bad element flag");
    if (!std::isnan(b.stress[s]) && b.shape[s]->type() != ShapeType::wall)
      ByteReader::fail("it holds a plate stress on an element that is not a wall");
    checkMass(*b.shape[s], materials_[b.material[s]]);
    updateMass(int(s));
  }

  in.expectTag("CONT");
  ContactList& l = list_;
  std::vector<int> a, bb, idA, idB;
  std::vector<std::uint8_t> discs;
  in.get(a, "contacts"), in.get(bb, "contacts"), in.get(idA, "contacts"), in.get(idB, "contacts");
  in.get(discs, "contacts");
  const std::size_t nc = a.size();
  l.resize(nc);
  l.a = std::move(a), l.b = std::move(bb), l.idA = std::move(idA), l.idB = std::move(idB);
  l.discs = std::move(discs);
  l.current = 0;
  l.vectorCount = std::size_t(in.get<std::uint64_t>("contacts"));
  ContactHistory& h = l.history[0];
  getColumn(in, h.touching, nc, "contacts");
  for (auto* c : {&h.nx, &h.ny, &h.sx, &h.sy, &l.fx, &l.fy, &l.px, &l.py, &l.overlap, &l.ta, &l.tb})
    getColumn(in, *c, nc, "contacts");
  if (l.a.size() != nc || l.b.size() != nc || l.idA.size() != nc || l.idB.size() != nc ||
      l.discs.size() != nc || l.vectorCount > nc)
    ByteReader::fail("its contact list is inconsistent");
  pairsValid_ = in.getBool("broad phase");
  slotsMoved_ = in.getBool("broad phase");
  skin_ = in.get<double>("broad phase");
  getVec2s(in, builtAt_, "broad phase");
  in.get(builtAngle_, "broad phase");
  if (pairsValid_ && (builtAt_.size() != n || builtAngle_.size() != n))
    ByteReader::fail("its broad phase does not match its elements");
  // Saved after "element delete" and before the next step, the list holds
  // the slots of the last pair build (builtAt_'s, one per element then) and
  // may name deleted elements; the next step builds it again, carrying the
  // history over by ids (the pair build of the run that never stopped). Only
  // its shape can be checked, and nothing may use it before that build.
  if (slotsMoved_ && pairsValid_) ByteReader::fail("its broad phase does not match its elements");
  buildLaws();
  for (std::size_t k = 0; k < nc; ++k) {
    const int i = l.a[k], j = l.b[k];
    if (h.touching[k] < 0 || h.touching[k] > 1 || l.discs[k] > 1)
      ByteReader::fail("its contact list does not match its elements");
    if (slotsMoved_) {
      if (i < 0 || i >= j || std::size_t(j) >= builtAt_.size() || l.idA[k] < 0 || l.idB[k] < 0 ||
          l.idA[k] == l.idB[k])
        ByteReader::fail("its contact list does not match its elements");
      continue;
    }
    if (i < 0 || i >= j || std::size_t(j) >= n || l.idA[k] != b.id[i] || l.idB[k] != b.id[j])
      ByteReader::fail("its contact list does not match its elements");
    const bool bothDiscs =
        b.shape[i]->type() == ShapeType::disc && b.shape[j]->type() == ShapeType::disc;
    if (l.discs[k] != bothDiscs || !canCollide(b.shape[i]->type(), b.shape[j]->type()))
      ByteReader::fail("its contact list does not match its elements");
    prepareContact(l, k);
    if (k < l.vectorCount && (!bothDiscs || laws_[l.law[k]].hertz))
      ByteReader::fail("its contact list does not match its elements");
  }
  lawsAt_ = generation_;

  in.expectTag("BOND");
  const std::size_t bonds = in.count(1, "bonds");
  for (std::size_t k = 0; k < bonds; ++k) {
    Bond bond = getBond(in);
    if (b.slot(bond.idA) < 0 || b.slot(bond.idB) < 0 || bond.id < 0)
      ByteReader::fail("it holds a bond of an element it does not hold");
    bonds_.push_back(bond);
  }
  const std::size_t breaks = in.count(1, "bond breaks");
  for (std::size_t k = 0; k < breaks; ++k) {
    BondBreak r;
    r.time = in.get<double>("bond breaks"), r.at = getVec2(in, "bond breaks");
    r.angle = in.get<double>("bond breaks");
    r.bond = in.get<std::int32_t>("bond breaks"), r.idA = in.get<std::int32_t>("bond breaks");
    r.idB = in.get<std::int32_t>("bond breaks"), r.tension = in.getBool("bond breaks");
    breaks_.push_back(r);
  }
  nextBondId_ = in.get<std::int32_t>("bonds");

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
  time_ = in.get<double>("time");
  viewValid_ = false;
}

}  // namespace sf::dem
