#pragma once
// Draws world-space line segments (the interactive view's lecture diagram) into a rectangle of
// the bound framebuffer (shaders/view/lines.*).
#include "camera/ImageSize.h"
#include "core/Image.h"
#include "gl/DefaultFramebuffer.h"
#include "gl/Object.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace lenslab {

struct LineSegment {
  glm::dvec3 from;  // world
  glm::dvec3 to;
  glm::vec3 color;  // display (sRGB-encoded) colour
};

class LineDrawer {
 public:
  LineDrawer();  // builds the program (needs a current context)

  // Draws the segments through `clipFromWorld` into `rect` (no depth test: the diagram stays
  // visible behind scene objects, as on the lecture's slides), two pixels wide: the core profile
  // has no wide lines, so the segments are drawn again one pixel over and up.
  void draw(const std::vector<LineSegment>& lines, const glm::dmat4& clipFromWorld, const gl::PixelRect& rect);
  // The segments alone, off screen, on transparent black: alpha 1 where a line is drawn and 0
  // elsewhere, rows from the top (what a headless picture lays over its scene).
  Image drawOffscreen(const std::vector<LineSegment>& lines, const glm::dmat4& clipFromWorld, ImageSize size);

 private:
  gl::Program program_;
  gl::VertexArray vertexArray_;
  gl::Buffer vertices_;
  std::size_t capacity_ = 0;  // floats the buffer holds
};

}  // namespace lenslab
