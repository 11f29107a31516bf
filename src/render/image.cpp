// Image operations that need no OpenGL.
#include "sandflow/render/draw_list.hpp"

namespace sf::render {

namespace {

// The common case, 2 x 2 blocks, in one pass over pairs of rows.
Image halve(const Image& image) {
  Image out;
  out.width = image.width / 2;
  out.height = image.height / 2;
  out.rgba.resize(std::size_t(out.width) * out.height * 4);
  const std::size_t row = std::size_t(image.width) * 4;
  for (int j = 0; j < out.height; ++j) {
    const std::uint8_t* a = image.rgba.data() + std::size_t(2 * j) * row;
    const std::uint8_t* b = a + row;
    std::uint8_t* o = out.rgba.data() + std::size_t(j) * out.width * 4;
    for (int i = 0; i < out.width; ++i, a += 8, b += 8, o += 4)
      for (int c = 0; c < 4; ++c) o[c] = std::uint8_t((a[c] + a[c + 4] + b[c] + b[c + 4] + 2) / 4);
  }
  return out;
}

}  // namespace

Image downsample(const Image& image, int factor) {
  if (factor <= 1) return image;
  if (factor == 2) return halve(image);
  Image out;
  out.width = image.width / factor;
  out.height = image.height / factor;
  out.rgba.resize(std::size_t(out.width) * out.height * 4);
  const int n = factor * factor;
  for (int j = 0; j < out.height; ++j)
    for (int i = 0; i < out.width; ++i)
      for (int c = 0; c < 4; ++c) {
        int sum = 0;
        for (int dj = 0; dj < factor; ++dj)
          for (int di = 0; di < factor; ++di)
            sum += image.rgba[(std::size_t(j * factor + dj) * image.width + (i * factor + di)) * 4 +
                              std::size_t(c)];
        out.rgba[(std::size_t(j) * out.width + i) * 4 + std::size_t(c)] =
            std::uint8_t((sum + n / 2) / n);
      }
  return out;
}

}  // namespace sf::render
