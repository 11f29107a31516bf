#pragma once
// A change to one element, every part optional. Assembly::configure checks
// all of it, then applies all of it, or throws sf::Error and changes nothing.
#include <Eigen/Core>
#include <cstdint>
#include <optional>

#include "sandflow/core/error.hpp"
#include "sandflow/dem/shape.hpp"
#include "sandflow/geometry/vec2.hpp"

namespace sf::dem {

struct ElementEdit {
  std::optional<Vec2> center;
  std::optional<double> angle;
  std::optional<Vec2> from, to;                    // a wall's ends (instead of centre and angle)
  std::optional<double> radius;                    // a disc's
  std::optional<int> material;                     // index in the material table
  std::optional<Eigen::Vector3d> velocity, force;  // {vx vy w}, {fx fy torque}
  std::optional<Vec2> acceleration;
  std::optional<std::uint8_t> hold;
  std::optional<double> stress;  // a wall's servo stress; NaN removes the servo
};

// The parts of an edit that only some shapes take (Assembly::configure
// refuses them on the others; the property panel offers them only there).
struct ShapeParts {
  bool radius = false;  // discs
  bool ends = false;    // walls: from, to
  bool stress = false;  // walls: a servo stress
};
constexpr ShapeParts partsOf(ShapeType type) {
  return {.radius = type == ShapeType::disc,
          .ends = type == ShapeType::wall,
          .stress = type == ShapeType::wall};
}

// The part of an edit a refusal is about, so that a front end can name its
// own word for it (the command layer: the option) without reading the code.
enum class EditPart : std::uint8_t { from, to, radius, material, stress };
class EditRefused : public Error {
 public:
  EditRefused(EditPart part, std::string code, const std::string& message)
      : Error(std::move(code), message), part_(part) {}
  EditPart part() const { return part_; }

 private:
  EditPart part_;
};

}  // namespace sf::dem
