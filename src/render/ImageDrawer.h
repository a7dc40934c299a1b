#pragma once
// Shows a linear image in a rectangle of the interactive view's window (shaders/view/display.frag):
// the accumulated mean, the gather baseline, the outside view under its diagram. Draws into
// whatever framebuffer is bound.
#include "gl/DefaultFramebuffer.h"
#include "gl/Framebuffer.h"
#include "gl/FullScreenPass.h"
#include "gl/ImageTexture.h"
#include "gl/Object.h"
#include "io/ToneMap.h"

namespace lenslab {

class ImageDrawer {
 public:
  ImageDrawer();  // builds the program (needs a current context)

  // Draws the image filling `rect`, bilinearly filtered and sRGB-encoded (the window's framebuffer
  // is 8-bit and not sRGB-aware). `gain` scales the linear values (dimming, so that lines drawn
  // over the image stand out). `display`: the exposure and view transform that PNG files get
  // (io/ToneMap.h; the same GLSL), applied after the gain.
  void draw(const gl::ImageTexture& image, const gl::PixelRect& rect, float gain = 1.0f,
            const DisplayEncoding& display = {}) const;
  void draw(const gl::RenderTarget& image, const gl::PixelRect& rect, float gain = 1.0f,
            const DisplayEncoding& display = {}) const;

 private:
  void drawTexture(GLuint texture, const gl::PixelRect& rect, float gain, const DisplayEncoding& display) const;

  gl::Program program_;
  gl::FullScreenPass fullScreen_;
  gl::Sampler linear_;
};

}  // namespace lenslab
