#pragma once
// The two small GL drawers of the interactive view: an image shown in a rectangle of the window,
// and the lecture diagram's line segments. Both draw into whatever framebuffer is bound.
#include "gl/Object.h"
#include "view/LectureDiagram.h"

#include <glm/glm.hpp>

#include <vector>

namespace lenslab::view {

// A rectangle of the window's framebuffer, in pixels, GL origin (bottom left).
struct PixelRect {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
  bool empty() const { return width <= 0 || height <= 0; }
};

class ImageDrawer {
 public:
  ImageDrawer();  // builds the program (needs a current context)
  // Draws `texture` (a linear RGBA float texture, GL row order) filling `rect`, bilinearly filtered.
  // `gain` scales the linear values (dimming, so that lines drawn over the image stand out).
  void draw(GLuint texture, const PixelRect& rect, float gain = 1.0f) const;

 private:
  gl::Program program_;
  gl::VertexArray emptyVertexArray_;
  gl::Sampler linear_;
};

class LineDrawer {
 public:
  LineDrawer();
  // Draws the segments through `clipFromWorld` into `rect` (no depth test: the diagram stays
  // visible behind scene objects, as on the lecture's slides), two pixels wide: the core profile
  // has no wide lines, so the segments are drawn again one pixel over and up.
  void draw(const std::vector<DiagramLine>& lines, const glm::dmat4& clipFromWorld, const PixelRect& rect);

 private:
  gl::Program program_;
  gl::VertexArray vertexArray_;
  gl::Buffer vertices_;
  std::size_t capacity_ = 0;  // floats the buffer holds
};

}  // namespace lenslab::view
