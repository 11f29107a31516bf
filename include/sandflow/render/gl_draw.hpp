#pragma once
// Draws a draw list into the current OpenGL context (legacy/compatibility GL,
// as Togl and OSMesa give), filling a list.width x list.height viewport.
#include "sandflow/render/draw_list.hpp"

namespace sf::render {
void drawList(const DrawList& list);
}
