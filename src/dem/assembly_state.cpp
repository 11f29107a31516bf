// An assembly's state in a checkpoint (Assembly::saveState / loadState): the
// materials and settings here, each part's own section from the part.
#include <cmath>

#include "sandflow/dem/assembly.hpp"

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

}  // namespace

void Assembly::saveState(ByteWriter& out) const {
  out.tag("MATS");
  out.put(std::int32_t(materials_.size()));
  for (int i = 0; i < materials_.size(); ++i) putMaterial(out, materials_[i]);

  out.tag("ELEM");
  out.put(std::int32_t(integrator)), out.put(maxOverlap_), out.put(vectorPass);
  bodies_.save(out);
  contacts_.save(out, materials_, generation_);
  bonds_.save(out);
  sources_.save(out);
  out.put(time_);
  out.put(lastStep_);
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
  const double overlap = in.get<double>("settings");
  // The limit the setting takes (it refused anything above 1 here before,
  // while sim configure took up to 2: such a scene saved a file it could not load).
  if (!(overlap > 0 && overlap <= kMaxOverlapLimit))
    ByteReader::fail("it holds a bad overlap limit");
  maxOverlap_ = overlap;
  vectorPass = in.getBool("settings");
  Bodies& b = bodies_;
  b.load(in);
  for (int s = 0; s < b.size(); ++s) {
    if (b.material[s] < 0 || b.material[s] >= materials_.size())
      ByteReader::fail("it holds an element of an unknown material");
    if (b.hold[s] > 7 || b.started[s] > 1 || b.ghost[s] > 1)
      ByteReader::fail("it holds a bad element flag");
    if (!std::isnan(b.stress[s]) && b.shape[s]->type() != ShapeType::wall)
      ByteReader::fail("it holds a plate stress on an element that is not a wall");
    checkMass(*b.shape[s], materials_[b.material[s]]);
    updateMass(s);
  }
  contacts_.load(in, b, materials_, generation_);
  bonds_.load(in, b);
  sources_.load(in, b);
  time_ = in.get<double>("time");
  // Version 2 and before: unknown, and the next step starts afresh.
  if (in.version >= 3) lastStep_ = in.get<double>("time");
  if (!(lastStep_ >= 0 && std::isfinite(lastStep_))) ByteReader::fail("it holds a bad timestep");
}

}  // namespace sf::dem
