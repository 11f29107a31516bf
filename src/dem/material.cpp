#include "sandflow/dem/material.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include "sandflow/core/error.hpp"

namespace sf::dem {
namespace {

// errorCode "VALUE DENSITY" for the density, like every other VALUE code; the
// message names the field (the command layer names its option).
void require(bool ok, const char* field, const std::string& rule, double value) {
  if (ok) return;
  std::string code = "VALUE ";
  for (const char* c = field; *c; ++c) code += char(std::toupper(static_cast<unsigned char>(*c)));
  throw Error(code, std::string("a material's ") + field + " must be " + rule + ", got " +
                        formatNumber(value));
}

}  // namespace

void validate(const Material& m) {
  auto finite = [](double v) { return std::isfinite(v); };
  require(finite(m.density) && m.density > 0, "density", "> 0", m.density);
  require(finite(m.kn) && m.kn > 0, "kn", "> 0", m.kn);
  require(finite(m.ks) && m.ks >= 0, "ks", ">= 0", m.ks);
  require(finite(m.friction) && m.friction >= 0, "friction", ">= 0", m.friction);
  if (m.damping < 0)
    require(finite(m.restitution) && m.restitution >= 0 && m.restitution <= 1, "restitution",
            "between 0 and 1", m.restitution);
  require(finite(m.damping), "damping", "finite", m.damping);
  require(finite(m.bondStiffness) && m.bondStiffness >= 0, "bondstiffness", ">= 0",
          m.bondStiffness);
  require(finite(m.bondStrength) && m.bondStrength >= 0, "bondstrength", ">= 0", m.bondStrength);
  require(finite(m.youngs) && m.youngs > 0, "youngs", "> 0", m.youngs);
  require(finite(m.poisson) && m.poisson > -1 && m.poisson < 0.5, "poisson", "between -1 and 0.5",
          m.poisson);
}

double dampingRatio(double e) {
  if (e <= 0) return 1.0;
  if (e >= 1) return 0.0;
  const double l = std::log(e);
  return -l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l);
}

PairLaw combine(const Material& a, const Material& b) {
  auto mix = [](double x, double y) { return x + y > 0 ? 2 * x * y / (x + y) : 0.0; };
  PairLaw law;
  law.kn = mix(a.kn, b.kn);
  law.ks = mix(a.ks, b.ks);
  law.friction = std::min(a.friction, b.friction);
  law.zeta = 0.5 * (dampingRatio(a.restitution) + dampingRatio(b.restitution));
  law.damping = (a.damping >= 0 && b.damping >= 0) ? 0.5 * (a.damping + b.damping) : -1.0;
  // The pair's target restitution: the continuous linear law's at the mean
  // ratio (equal materials keep theirs); contact_damping.hpp solves for it.
  const double z = law.zeta;
  law.restitution = a.restitution == b.restitution ? a.restitution
                    : z < 1 ? std::exp(-std::numbers::pi * z / std::sqrt(1 - z * z))
                            : 0.0;
  law.compressive =
      a.normalForce == NormalForce::compressive || b.normalForce == NormalForce::compressive;
  law.hertz = a.law == ContactLaw::hertz || b.law == ContactLaw::hertz;
  law.effectiveYoungs =
      1.0 / ((1 - a.poisson * a.poisson) / a.youngs + (1 - b.poisson * b.poisson) / b.youngs);
  const double ga = a.youngs / (2 * (1 + a.poisson)), gb = b.youngs / (2 * (1 + b.poisson));
  law.effectiveShear = 1.0 / ((2 - a.poisson) / ga + (2 - b.poisson) / gb);
  return law;
}

MaterialTable::MaterialTable() {
  materials_.push_back(Material{"default"});
}

int MaterialTable::find(const std::string& name) const {
  for (int i = 0; i < size(); ++i)
    if (materials_[i].name == name) return i;
  return -1;
}

int MaterialTable::index(const std::string& name) const {
  const int i = find(name);
  if (i < 0) throw Error("LOOKUP MATERIAL", "no material named \"" + name + "\"");
  return i;
}

int MaterialTable::add(const Material& m) {
  if (m.name.empty()) throw Error("VALUE NAME", "a material needs a name");
  if (find(m.name) >= 0) throw Error("EXISTS MATERIAL", "material \"" + m.name + "\" exists");
  validate(m);
  materials_.push_back(m);
  ++version_;
  return size() - 1;
}

void MaterialTable::replace(int i, const Material& m) {
  validate(m);
  materials_.at(i) = m;
  ++version_;
}

std::vector<std::string> MaterialTable::names() const {
  std::vector<std::string> out;
  for (const auto& m : materials_) out.push_back(m.name);
  return out;
}

}  // namespace sf::dem
