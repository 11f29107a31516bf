#pragma once
// An element's shape in a checkpoint: its type and the numbers that make it,
// read back into the same shape bit for bit, through the shape's own checks.
#include <memory>

#include "sandflow/core/byte_stream.hpp"
#include "sandflow/dem/shape.hpp"

namespace sf::dem {

void saveShape(ByteWriter& out, const Shape& shape);
std::unique_ptr<Shape> loadShape(ByteReader& in);

}  // namespace sf::dem
