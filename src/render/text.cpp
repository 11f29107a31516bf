// FreeType rasterisation of labels into alpha-blended sprites.
#include "sandflow/render/text.hpp"

#include <fontconfig/fontconfig.h>
#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>

#include "sandflow/core/error.hpp"

namespace sf::render {
namespace {

// The path of the best match for a sans-serif font, or "" if there is none.
std::string findSansFont() {
  std::string path;
  if (!FcInit()) return path;
  FcPattern* pattern = FcNameParse(reinterpret_cast<const FcChar8*>("sans-serif"));
  FcConfigSubstitute(nullptr, pattern, FcMatchPattern);
  FcDefaultSubstitute(pattern);
  FcResult result = FcResultNoMatch;
  FcPattern* match = FcFontMatch(nullptr, pattern, &result);
  FcChar8* file = nullptr;
  if (match && FcPatternGetString(match, FC_FILE, 0, &file) == FcResultMatch)
    path = reinterpret_cast<const char*>(file);
  if (match) FcPatternDestroy(match);
  FcPatternDestroy(pattern);
  return path;
}

// Code points of a UTF-8 string (fontconfig's decoder); decoding stops at a
// malformed sequence.
std::vector<char32_t> decodeUtf8(const std::string& s) {
  std::vector<char32_t> out;
  const auto* at = reinterpret_cast<const FcChar8*>(s.data());
  int left = int(s.size());
  while (left > 0) {
    FcChar32 code = 0;
    const int used = FcUtf8ToUcs4(at, &code, left);
    if (used <= 0) break;
    out.push_back(char32_t(code));
    at += used;
    left -= used;
  }
  return out;
}

}  // namespace

struct TextRenderer::Impl {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  std::string file;
  std::mutex mutex;  // FreeType faces are not thread-safe
};

TextRenderer::TextRenderer() : impl_(std::make_unique<Impl>()) {
  impl_->file = findSansFont();
  if (impl_->file.empty())
    throw Error("RESOURCE FONT",
                "no sans-serif font found for labels (install Debian fonts-dejavu-core)");
  if (FT_Init_FreeType(&impl_->library) != 0)
    throw Error("RESOURCE FONT", "FreeType could not be initialised");
  if (FT_New_Face(impl_->library, impl_->file.c_str(), 0, &impl_->face) != 0) {
    FT_Done_FreeType(impl_->library);
    throw Error("RESOURCE FONT", "cannot open the font " + impl_->file);
  }
}

TextRenderer::~TextRenderer() {
  FT_Done_Face(impl_->face);
  FT_Done_FreeType(impl_->library);
}

const std::string& TextRenderer::fontFile() const {
  return impl_->file;
}

float TextRenderer::width(const std::string& text, int size) {
  std::lock_guard lock(impl_->mutex);
  FT_Set_Pixel_Sizes(impl_->face, 0, FT_UInt(size));
  float w = 0;
  for (char32_t cp : decodeUtf8(text))
    if (FT_Load_Char(impl_->face, cp, FT_LOAD_DEFAULT) == 0)
      w += float(impl_->face->glyph->advance.x) / 64.0f;
  return w;
}

Sprite TextRenderer::render(const std::string& text, int size, Rgba colour, float x, float y,
                            float align) {
  std::lock_guard lock(impl_->mutex);
  FT_Face face = impl_->face;
  FT_Set_Pixel_Sizes(face, 0, FT_UInt(size));
  const std::vector<char32_t> codes = decodeUtf8(text);
  // A box from descender to ascender, as wide as the advances.
  const int ascent = int(std::ceil(face->size->metrics.ascender / 64.0));
  const int descent = int(std::ceil(-face->size->metrics.descender / 64.0));
  float advance = 0;
  for (char32_t cp : codes)
    if (FT_Load_Char(face, cp, FT_LOAD_DEFAULT) == 0) advance += face->glyph->advance.x / 64.0f;
  Sprite s;
  s.width = std::max(1, int(std::ceil(advance)) + 2);
  s.height = std::max(1, ascent + descent);
  s.rgba.assign(std::size_t(s.width) * s.height * 4, 0);
  for (std::size_t k = 0; k < s.rgba.size(); k += 4) {
    s.rgba[k] = colour.r;
    s.rgba[k + 1] = colour.g;
    s.rgba[k + 2] = colour.b;
  }
  float pen = 1;
  for (char32_t cp : codes) {
    if (FT_Load_Char(face, cp, FT_LOAD_RENDER) != 0) continue;
    const FT_GlyphSlot g = face->glyph;
    const FT_Bitmap& bm = g->bitmap;
    const int left = int(std::lround(pen)) + g->bitmap_left;
    for (unsigned row = 0; row < bm.rows; ++row) {
      // Glyph rows run top-down from bitmap_top above the baseline; sprite rows bottom-up.
      const int yUp = descent + g->bitmap_top - 1 - int(row);
      if (yUp < 0 || yUp >= s.height) continue;
      for (unsigned col = 0; col < bm.width; ++col) {
        const int xx = left + int(col);
        if (xx < 0 || xx >= s.width) continue;
        const std::uint8_t cover = bm.buffer[row * std::ptrdiff_t(bm.pitch) + col];
        std::uint8_t& a = s.rgba[(std::size_t(yUp) * s.width + xx) * 4 + 3];
        a = std::max(a, std::uint8_t(cover * colour.a / 255));
      }
    }
    pen += g->advance.x / 64.0f;
  }
  s.x0 = std::round(x - align * advance) - 1;
  s.y0 = std::round(y) - float(descent);
  s.x1 = s.x0 + float(s.width);
  s.y1 = s.y0 + float(s.height);
  s.smooth = false;  // placed on whole pixels: drawn texel for pixel
  return s;
}

TextRenderer& sharedTextRenderer() {
  static TextRenderer renderer;
  return renderer;
}

}  // namespace sf::render
