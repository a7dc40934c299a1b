#pragma once
// The default framebuffer: a window's (GLFW's), which the interactive view draws into and reads
// back for "Save window" and scripted screenshots. The headless contexts have none worth using.
#include "core/Image.h"

#include <glm/glm.hpp>

namespace lenslab::gl {

// A rectangle of the window's framebuffer, in pixels, GL origin (bottom left).
struct PixelRect {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
  bool empty() const { return width <= 0 || height <= 0; }
};

// Binds the default framebuffer for drawing over all of it (viewport = the whole, no scissor).
void bindDefaultFramebuffer(int widthPx, int heightPx);
// Binds it as above and clears its colour to `color` (display values: the window is not sRGB-aware).
void clearDefaultFramebuffer(int widthPx, int heightPx, const glm::vec4& color);
// The back buffer (what the next swap shows) as it is stored: display-encoded (sRGB) values in
// [0, 1], alpha 1, rows from the top. The caller decodes them to linear light.
Image readDefaultFramebuffer(int widthPx, int heightPx);

}  // namespace lenslab::gl
