#pragma once
// Labels rasterised with FreeType from the system's sans-serif font (found with
// fontconfig; Debian fonts-dejavu-core), as sprites for the draw list.
#include <memory>
#include <string>

#include "sandflow/render/draw_list.hpp"

namespace sf::render {

class TextRenderer {
 public:
  // Throws sf::Error (RESOURCE FONT) when no font can be found or opened.
  TextRenderer();
  ~TextRenderer();
  TextRenderer(const TextRenderer&) = delete;
  TextRenderer& operator=(const TextRenderer&) = delete;

  // Width in pixels of a UTF-8 string at `size` pixels (the em height).
  float width(const std::string& text, int size);
  // The text as a sprite whose baseline starts at (x, y); `align` 0 puts x at
  // the left end, 0.5 at the middle, 1 at the right end.
  Sprite render(const std::string& text, int size, Rgba colour, float x, float y,
                float align = 0.0f);
  const std::string& fontFile() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One renderer per process, made on first use (opening the font costs ~1 ms).
TextRenderer& sharedTextRenderer();

}  // namespace sf::render
