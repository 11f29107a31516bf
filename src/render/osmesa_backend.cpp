// The OSMesa back end: Mesa's software rasteriser into a buffer we own; needs
// no display and no X. One context for the life of the process, made current
// on a buffer of each picture's size.
#include <GL/osmesa.h>

#include "sandflow/render/gl_draw.hpp"
#include "sandflow/render/offscreen_api.hpp"

namespace sf::render {
namespace {

OSMesaContext context = nullptr;

bool renderOsmesa(const DrawList& list, Image& out, std::string& error) {
  if (!context) {
    // Compatibility profile, no depth buffer: the pictures are 2D, in drawing order.
    context = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
    if (!context) {
      error = "OSMesa could not create a context";
      return false;
    }
  }
  GLint maxWidth = 0, maxHeight = 0;
  OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &maxWidth);
  OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &maxHeight);
  if (list.width < 1 || list.height < 1 || list.width > maxWidth || list.height > maxHeight) {
    error = "OSMesa draws at most " + std::to_string(maxWidth) + " x " + std::to_string(maxHeight) +
            " pixels, asked for " + std::to_string(list.width) + " x " +
            std::to_string(list.height);
    return false;
  }
  std::vector<std::uint8_t> buffer(std::size_t(list.width) * list.height * 4);
  if (!OSMesaMakeCurrent(context, buffer.data(), GL_UNSIGNED_BYTE, list.width, list.height)) {
    error = "OSMesa could not use a " + std::to_string(list.width) + " x " +
            std::to_string(list.height) + " buffer";
    return false;
  }
  drawList(list);
  imageFromBuffer(buffer, list.width, list.height, out);
  return true;
}

const OffscreenApi api{kOffscreenApiVersion, "osmesa", renderOsmesa, nullptr};

}  // namespace
}  // namespace sf::render

extern "C" __attribute__((visibility("default"))) const sf::render::OffscreenApi*
sandflow_offscreen_api() {
  return &sf::render::api;
}
