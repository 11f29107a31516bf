// The plates' servo.
#include "sandflow/dem/plate_servo.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sandflow/core/error.hpp"

namespace sf::dem {

void PlateServo::set(Bodies& b, int s, double stress) {
  if (b.shape[s]->type() != ShapeType::wall)
    throw Error("VALUE STRESS", "a servo stress applies to walls only");
  if (std::isinf(stress)) throw Error("VALUE STRESS", "a servo stress must be finite");
  b.stress[s] = stress;
  if (!std::isnan(stress)) b.hold[s] = holdX | holdY | holdRotation;
}

// Servo: move each plate along its normal at a speed proportional to the
// missing load, with a gain that would close 2% of the gap per step against
// the stiffness of the contacts it has, and never faster than 1e-3 of the
// smallest element per step (an unloaded plate would otherwise slam into the
// specimen). A faster servo fights the contact dashpots: the plate's own speed
// comes back as damping force and the loop rings.
void PlateServo::servo(Bodies& b, const MaterialTable& materials, const ContactList& l,
                       std::uint64_t generation, double dt) {
  if (platesAt_ != generation) {
    plates_.clear();
    for (int s = 0; s < b.size(); ++s)
      if (!std::isnan(b.stress[s])) plates_.push_back(s);
    platesAt_ = generation;
  }
  for (int s : plates_) {
    if (std::isnan(b.stress[s])) continue;  // servo removed since
    const auto& wall = static_cast<const Wall&>(*b.shape[s]);
    const Vec2 inward(-std::sin(b.angle[s]), std::cos(b.angle[s]));
    double load = 0, stiffness = 0;
    for (std::size_t k = 0; k < l.size(); ++k) {
      if (!l.touching(k) || (l.a[k] != s && l.b[k] != s)) continue;
      const Vec2 force(l.fx[k], l.fy[k]);
      const Vec2 onWall = l.a[k] == s ? Vec2(-force) : force;
      load -= onWall.dot(inward);  // the grains push the plate back
      const int other = l.a[k] == s ? l.b[k] : l.a[k];
      stiffness += combine(materials[b.material[s]], materials[b.material[other]]).kn;
    }
    const double target = b.stress[s] * wall.length();
    const double k = std::max(stiffness, materials[b.material[s]].kn);
    double smallest = std::numeric_limits<double>::infinity();
    for (int o = 0; o < b.size(); ++o)
      if (o != s) smallest = std::min(smallest, b.extent[o]);
    const double limit = std::isfinite(smallest) ? 1e-3 * smallest / dt : 0.0;
    const double speed = std::clamp(0.02 * (target - load) / (k * dt), -limit, limit);
    b.v[s] = speed * inward;
    b.vHalf[s] = b.v[s];
    b.w[s] = b.wHalf[s] = 0;
  }
}

std::vector<std::string> PlateServo::validate(const Bodies& b) {
  std::vector<std::string> problems;
  for (int s = 0; s < b.size(); ++s) {
    if (std::isnan(b.stress[s])) continue;
    const std::string which = "element " + std::to_string(b.id[s]);
    if (!b.shape[s] || b.shape[s]->type() != ShapeType::wall)
      problems.push_back(which + " has a plate stress but is not a wall");
    if (std::isinf(b.stress[s])) problems.push_back(which + " has an infinite plate stress");
  }
  return problems;
}

}  // namespace sf::dem
