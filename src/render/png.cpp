// PNG encoding with libpng, written to a stream (so that output goes through
// io::writeAtomically and no half-written file is ever left).
#include "sandflow/render/png.hpp"

#include <png.h>

#include <csetjmp>
#include <vector>

#include "sandflow/core/error.hpp"

namespace sf::render {
namespace {

void writeToStream(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::ostream*>(png_get_io_ptr(png));
  out->write(reinterpret_cast<const char*>(data), std::streamsize(length));
  if (!*out) png_error(png, "the file could not be written");
}

void flushStream(png_structp png) {
  static_cast<std::ostream*>(png_get_io_ptr(png))->flush();
}

}  // namespace

void writePng(const Image& image, std::ostream& out) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) throw Error("IO PNG", "libpng could not start");
  png_infop info = png_create_info_struct(png);
  // Rows as RGB (pictures are opaque), prepared before setjmp: libpng reports
  // errors by longjmp, which must not skip a destructor made after it.
  std::vector<png_byte> rgb(std::size_t(image.width) * image.height * 3);
  for (std::size_t k = 0, n = std::size_t(image.width) * image.height; k < n; ++k)
    for (int c = 0; c < 3; ++c) rgb[3 * k + std::size_t(c)] = image.rgba[4 * k + std::size_t(c)];
  std::vector<png_bytep> rows(std::size_t(image.height));
  for (int j = 0; j < image.height; ++j)
    rows[std::size_t(j)] = rgb.data() + std::size_t(j) * image.width * 3;
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, info ? &info : nullptr);
    throw Error("IO PNG", "the PNG file could not be written");
  }
  png_set_write_fn(png, &out, writeToStream, flushStream);
  png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
}

}  // namespace sf::render
