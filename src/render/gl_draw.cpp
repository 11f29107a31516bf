// The one OpenGL drawing routine: textured quads for the field and the
// overlays, triangle fans for elements, quads for strokes.
#include "sandflow/render/gl_draw.hpp"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>

namespace sf::render {
namespace {

void colour(const Rgba& c) {
  glColor4ub(c.r, c.g, c.b, c.a);
}

void stroke(const Stroke& s) {
  float dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
  const float len = std::sqrt(dx * dx + dy * dy);
  if (len > 0) {
    dx /= len;
    dy /= len;
  } else {
    dx = 1;
    dy = 0;
  }
  const float h = 0.5f * s.width;
  // Square ends: the quad reaches half the width beyond both end points.
  const float ax = s.a.x - h * dx, ay = s.a.y - h * dy, bx = s.b.x + h * dx, by = s.b.y + h * dy;
  const float nx = -h * dy, ny = h * dx;
  colour(s.colour);
  glVertex2f(ax + nx, ay + ny);
  glVertex2f(ax - nx, ay - ny);
  glVertex2f(bx - nx, by - ny);
  glVertex2f(bx + nx, by + ny);
}

void strokes(const std::vector<Stroke>& list) {
  glBegin(GL_QUADS);
  for (const Stroke& s : list) stroke(s);
  glEnd();
}

// Large sprites go up in tiles no larger than the implementation allows.
void sprite(const Sprite& s, bool mipmap) {
  if (s.width <= 0 || s.height <= 0) return;
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  const int tile = std::max(64, std::min(4096, int(maxSize)));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, s.width);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  const float sx = (s.x1 - s.x0) / float(s.width), sy = (s.y1 - s.y0) / float(s.height);
  for (int j0 = 0; j0 < s.height; j0 += tile)
    for (int i0 = 0; i0 < s.width; i0 += tile) {
      const int w = std::min(tile, s.width - i0), h = std::min(tile, s.height - j0);
      GLuint tex = 0;
      glGenTextures(1, &tex);
      glBindTexture(GL_TEXTURE_2D, tex);
      const bool minified = std::abs(sx) < 1 || std::abs(sy) < 1;
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, s.smooth ? GL_LINEAR : GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                      mipmap && minified ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, mipmap && minified ? GL_TRUE : GL_FALSE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      glPixelStorei(GL_UNPACK_SKIP_PIXELS, i0);
      glPixelStorei(GL_UNPACK_SKIP_ROWS, j0);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, s.rgba.data());
      const float x0 = s.x0 + sx * float(i0), x1 = s.x0 + sx * float(i0 + w);
      const float y0 = s.y0 + sy * float(j0), y1 = s.y0 + sy * float(j0 + h);
      glColor4ub(255, 255, 255, 255);
      glBegin(GL_QUADS);
      glTexCoord2f(0, 0);
      glVertex2f(x0, y0);
      glTexCoord2f(1, 0);
      glVertex2f(x1, y0);
      glTexCoord2f(1, 1);
      glVertex2f(x1, y1);
      glTexCoord2f(0, 1);
      glVertex2f(x0, y1);
      glEnd();
      glDeleteTextures(1, &tex);
    }
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glDisable(GL_TEXTURE_2D);
}

void rect(const Rect& r, const Rgba& c) {
  colour(c);
  glBegin(GL_QUADS);
  glVertex2f(r.x0, r.y0);
  glVertex2f(r.x1, r.y0);
  glVertex2f(r.x1, r.y1);
  glVertex2f(r.x0, r.y1);
  glEnd();
}

void fan(const Fill& f) {
  colour(f.colour);
  glBegin(GL_TRIANGLE_FAN);
  glVertex2f(f.centre.x, f.centre.y);
  for (const Point& p : f.outline) glVertex2f(p.x, p.y);
  if (!f.outline.empty()) glVertex2f(f.outline.front().x, f.outline.front().y);
  glEnd();
}

}  // namespace

void drawList(const DrawList& list) {
  glViewport(0, 0, list.width, list.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, list.width, 0, list.height, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glClearColor(list.background.r / 255.0f, list.background.g / 255.0f, list.background.b / 255.0f,
               1.0f);
  glClear(GL_COLOR_BUFFER_BIT);

  // The world window: clipped to its viewport.
  const Rect& v = list.viewport;
  const int sx0 = int(std::floor(v.x0)), sy0 = int(std::floor(v.y0));
  glEnable(GL_SCISSOR_TEST);
  glScissor(sx0, sy0, int(std::ceil(v.x1)) - sx0, int(std::ceil(v.y1)) - sy0);
  rect(v, list.viewportColour);
  if (list.hasField) sprite(list.field, true);
  strokes(list.fieldStrokes);
  for (const Fill& f : list.fills) fan(f);
  strokes(list.worldStrokes);
  glDisable(GL_SCISSOR_TEST);

  for (const Fill& f : list.panels) fan(f);
  strokes(list.overlayStrokes);
  for (const Sprite& s : list.overlays) sprite(s, false);
  glFinish();
}

}  // namespace sf::render
