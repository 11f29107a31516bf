#pragma once
// Off-screen back ends: shared modules, one per OpenGL implementation (OSMesa,
// EGL), each holding the drawing code and its own context. They are loaded with
// dlopen so that no process links two libraries that both export the gl*
// functions (design.md); a process loads at most one.
#include <cstring>
#include <string>
#include <vector>

#include "sandflow/render/draw_list.hpp"

namespace sf::render {

struct OffscreenApi {
  int version;       // kOffscreenApiVersion
  const char* name;  // "osmesa", "egl"
  // Draws the list into a buffer of list.width x list.height pixels and reads it
  // back into `out` (rows top-down). False, with `error` set, on failure.
  bool (*render)(const DrawList& list, Image& out, std::string& error);
  // Draws the list into the context current on this thread (the workbench's
  // Togl view, made current by Togl): null where the module's OpenGL library
  // cannot draw into another library's context (OSMesa). With GLVND, the EGL
  // module's libOpenGL dispatches to a GLX context as well.
  void (*drawCurrent)(const DrawList& list);
};

inline constexpr int kOffscreenApiVersion = 3;  // 3: DrawList::panels

// An OpenGL buffer (rows bottom-up) as an image (rows top-down).
inline void imageFromBuffer(const std::vector<std::uint8_t>& buffer, int width, int height,
                            Image& out) {
  out.width = width;
  out.height = height;
  out.rgba.resize(buffer.size());
  const std::size_t row = std::size_t(width) * 4;
  for (int j = 0; j < height; ++j)
    std::memcpy(out.rgba.data() + std::size_t(j) * row,
                buffer.data() + std::size_t(height - 1 - j) * row, row);
}
inline constexpr const char* kOffscreenEntry = "sandflow_offscreen_api";

}  // namespace sf::render

// Each back-end module exports this one symbol.
extern "C" const sf::render::OffscreenApi* sandflow_offscreen_api();
