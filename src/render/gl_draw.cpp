// The one OpenGL drawing routine: textured quads for the field and the
// overlays; strokes and filled outlines as triangles, a layer at a time.
#include "sandflow/render/gl_draw.hpp"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace sf::render {
namespace {

void colour(const Rgba& c) {
  glColor4ub(c.r, c.g, c.b, c.a);
}

// Triangles with a colour at each corner, sent in one call from client
// arrays. A frame holds thousands of strokes and fills (the outline of each
// of hundreds of grains); a call per corner (glBegin, glVertex) cost more
// than the rest of the frame. GL draws them in order, as it did the calls.
class Triangles {
 public:
  void add(const Point& a, const Point& b, const Point& c, const Rgba& colour) {
    opaque_ = opaque_ && colour.a == 255;
    for (const Point* p : {&a, &b, &c}) {
      xy_.insert(xy_.end(), {p->x, p->y});
      rgba_.insert(rgba_.end(), {colour.r, colour.g, colour.b, colour.a});
    }
  }
  // Blending only where something is translucent: it costs llvmpipe more than
  // the triangles themselves, and over an opaque colour it changes nothing.
  void draw() const {
    if (xy_.empty()) return;
    if (opaque_) glDisable(GL_BLEND);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, xy_.data());
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, rgba_.data());
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(xy_.size() / 2));
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glEnable(GL_BLEND);
  }

 private:
  std::vector<float> xy_;
  std::vector<std::uint8_t> rgba_;
  bool opaque_ = true;
};

// A quad, split as GL splits one.
void stroke(const Stroke& s, Triangles& out) {
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
  const Point q0{ax + nx, ay + ny}, q1{ax - nx, ay - ny}, q2{bx - nx, by - ny},
      q3{bx + nx, by + ny};
  out.add(q0, q1, q2, s.colour);
  out.add(q0, q2, q3, s.colour);
}

void strokes(const std::vector<Stroke>& list) {
  Triangles t;
  for (const Stroke& s : list) stroke(s, t);
  t.draw();
}

// Large sprites go up in tiles no larger than the implementation allows. The
// field (`cells`) is sampled nearest both ways: its texels are nodes, or
// pixels already, and a colour is never averaged across a wall.
void sprite(const Sprite& s, bool cells) {
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
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, s.smooth ? GL_LINEAR : GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, cells ? GL_NEAREST : GL_LINEAR);
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

// The viewport's colour where the field's sprite leaves it showing: a fill
// under the whole field would cost llvmpipe a pass over every pixel of it.
void backdropAround(const Rect& v, const Sprite& s, const Rgba& c) {
  const float x0 = std::clamp(std::min(s.x0, s.x1), v.x0, v.x1);
  const float x1 = std::clamp(std::max(s.x0, s.x1), v.x0, v.x1);
  const float y0 = std::clamp(std::min(s.y0, s.y1), v.y0, v.y1);
  const float y1 = std::clamp(std::max(s.y0, s.y1), v.y0, v.y1);
  for (const Rect& r : {Rect{v.x0, v.y0, v.x1, y0}, Rect{v.x0, y1, v.x1, v.y1},
                        Rect{v.x0, y0, x0, y1}, Rect{x1, y0, v.x1, y1}})
    if (r.x1 > r.x0 && r.y1 > r.y0) rect(r, c);
}

// A fan about the centre, closed.
void fan(const Fill& f, Triangles& out) {
  const std::size_t n = f.outline.size();
  for (std::size_t k = 0; k < n && n > 1; ++k)
    out.add(f.centre, f.outline[k], f.outline[(k + 1) % n], f.colour);
}

void fans(const std::vector<Fill>& list) {
  Triangles t;
  for (const Fill& f : list) fan(f, t);
  t.draw();
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
  if (list.hasField) {  // opaque: every texel lies on the lattice
    backdropAround(v, list.field, list.viewportColour);
    glDisable(GL_BLEND);
    sprite(list.field, true);
    glEnable(GL_BLEND);
  } else {
    rect(v, list.viewportColour);
  }
  strokes(list.fieldStrokes);
  fans(list.fills);
  strokes(list.worldStrokes);
  glDisable(GL_SCISSOR_TEST);

  fans(list.panels);
  strokes(list.overlayStrokes);
  for (const Sprite& s : list.overlays) sprite(s, false);
  glFinish();
}

}  // namespace sf::render
