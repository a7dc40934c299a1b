#pragma once
// An RGBA32F texture that keeps an image drawn more than once (the interactive view's gather
// baseline and its outside view, both redrawn every frame but recomputed only on a change).
#include "core/Image.h"
#include "gl/Framebuffer.h"
#include "gl/Object.h"

namespace lenslab::gl {

class ImageTexture {
 public:
  ImageTexture() = default;                 // empty: no texture
  ImageTexture(int widthPx, int heightPx);  // needs a current context

  explicit operator bool() const { return static_cast<bool>(texture_); }
  int width() const { return width_; }
  int height() const { return height_; }
  GLuint id() const { return texture_.id(); }

  // `image` must have the texture's size; its rows run from the top, GL's from the bottom.
  void upload(const Image& image);
  // Copies the colour of `source` (the texture's size) on the GPU.
  void copyColor(const RenderTarget& source);

 private:
  Texture texture_;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace lenslab::gl
