// The bond set in a checkpoint ("BOND") and its invariants.
#include <cmath>
#include <set>

#include "sandflow/dem/bond_set.hpp"
#include "sandflow/geometry/vec2_bytes.hpp"

namespace sf::dem {
namespace {

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

void BondSet::save(ByteWriter& out) const {
  out.tag("BOND");
  out.put(std::uint64_t(bonds_.size()));
  for (const Bond& bond : bonds_) putBond(out, bond);
  out.put(std::uint64_t(breaks_.size()));
  for (const BondBreak& k : breaks_) {
    out.put(k.time), putVec2(out, k.at), out.put(k.angle);
    out.put(std::int32_t(k.bond)), out.put(std::int32_t(k.idA)), out.put(std::int32_t(k.idB));
    out.put(k.tension);
  }
  out.put(std::int32_t(nextId_));
}

void BondSet::load(ByteReader& in, const Bodies& b) {
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
  nextId_ = in.get<std::int32_t>("bonds");
}

std::vector<std::string> BondSet::validate(const Bodies& b) const {
  std::vector<std::string> problems;
  auto problem = [&](const std::string& p) { problems.push_back(p); };
  std::set<int> ids;
  std::set<std::pair<int, int>> pairs;
  for (const Bond& bond : bonds_) {
    const std::string which = "bond " + std::to_string(bond.id);
    if (!ids.insert(bond.id).second) problem(which + " twice");
    if (b.slot(bond.idA) < 0 || b.slot(bond.idB) < 0)
      problem(which + " joins an element that is gone");
    if (bond.idA == bond.idB) problem(which + " joins an element to itself");
    if (!pairs.insert(std::minmax(bond.idA, bond.idB)).second)
      problem(which + " joins a pair that another bond joins");
    if (!bond.force.allFinite()) problem(which + "'s force is not finite");
    if (!bond.anchorA.allFinite() || !bond.anchorB.allFinite() || !bond.normal0.allFinite() ||
        !std::isfinite(bond.length) || !std::isfinite(bond.stiffness))
      problem(which + "'s anchors, length or stiffness are not finite");
    if (bond.id < 0 || bond.id >= nextId_) problem(which + " is not below the next id");
  }
  for (const BondBreak& k : breaks_)
    if (k.bond < 0 || k.bond >= nextId_)
      problem("a break names bond " + std::to_string(k.bond) + ", not below the next id");
  return problems;
}

}  // namespace sf::dem
