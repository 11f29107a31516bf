#pragma once
// PNG files of pictures (libpng), RGB, 8 bits per channel.
#include <ostream>

#include "sandflow/render/draw_list.hpp"

namespace sf::render {
// Throws sf::Error (IO PNG) if libpng fails or the stream does.
void writePng(const Image& image, std::ostream& out);
}  // namespace sf::render
