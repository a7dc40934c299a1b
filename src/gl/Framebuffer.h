#pragma once
// An off-screen render target: RGBA32F colour (linear light, unclamped) and DEPTH_COMPONENT32F
// depth (reverse-Z), both textures so that later passes can sample them.
#include "core/Image.h"
#include "gl/Object.h"

namespace lenslab::gl {

// Where a pass draws: a framebuffer and its size. Owned elsewhere (RenderTarget, Accumulator).
struct DrawTarget {
  GLuint framebuffer = 0;
  int width = 0;
  int height = 0;
  void bind() const;  // binds the framebuffer and sets the viewport
};

class RenderTarget {
 public:
  RenderTarget(int widthPx, int heightPx);

  void bind() const { drawTarget().bind(); }
  DrawTarget drawTarget() const { return {framebuffer_.id(), width_, height_}; }
  int width() const { return width_; }
  int height() const { return height_; }
  GLuint colorTexture() const { return color_.id(); }
  GLuint depthTexture() const { return depth_.id(); }

  // Reads the colour back, rows from the top (GL's rows start at the bottom).
  Image readColor() const;
  // Reads the reverse-Z depth (z_ndc: 1 at near, 0 at far), rows from the top.
  std::vector<float> readDepth() const;

 private:
  int width_;
  int height_;
  Texture color_;
  Texture depth_;
  Framebuffer framebuffer_;
};

}  // namespace lenslab::gl
