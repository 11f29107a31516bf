// Image operations that need no OpenGL.
#include "sandflow/render/draw_list.hpp"

namespace sf::render {

Image halve(const Image& image) {
  Image out;
  out.width = image.width / 2;
  out.height = image.height / 2;
  out.rgba.resize(std::size_t(out.width) * out.height * 4);
  const std::size_t row = std::size_t(image.width) * 4;
  for (int j = 0; j < out.height; ++j) {
    const std::uint8_t* a = image.rgba.data() + std::size_t(2 * j) * row;  // pairs of rows
    const std::uint8_t* b = a + row;
    std::uint8_t* o = out.rgba.data() + std::size_t(j) * out.width * 4;
    for (int i = 0; i < out.width; ++i, a += 8, b += 8, o += 4)
      for (int c = 0; c < 4; ++c) o[c] = std::uint8_t((a[c] + a[c + 4] + b[c] + b[c + 4] + 2) / 4);
  }
  return out;
}

}  // namespace sf::render
