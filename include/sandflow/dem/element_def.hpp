#pragma once
// What a new element is made from (Assembly::add validates it).
#include <cstdint>
#include <memory>

#include "sandflow/dem/shape.hpp"

namespace sf::dem {

struct ElementDef {
  std::unique_ptr<Shape> shape;
  int material = 0;
  Vec2 x = Vec2::Zero();
  double angle = 0.0;
  Vec2 v = Vec2::Zero();
  double w = 0.0;
  std::uint8_t hold = 0;
  Vec2 force = Vec2::Zero();  // applied force and torque
  double torque = 0.0;
  Vec2 acceleration = Vec2::Zero();  // a body acceleration of its own
  int id = -1;                       // < 0: the next free id
};

}  // namespace sf::dem
