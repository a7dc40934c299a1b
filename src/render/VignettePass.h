#pragma once
// The vignetting pass: the finished image times the lens's relative illumination at each pixel's
// place on the film (lens/LensEffects.h, Vignetting). It runs once per frame, after the resolve
// (or the lens remap, or a single view), reading one image and writing another, so that resolving
// a frame again never applies it twice.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "gl/Framebuffer.h"
#include "gl/FullScreenPass.h"
#include "gl/Object.h"

namespace lenslab {

class VignettePass {
 public:
  VignettePass();  // needs a current context

  // `in` times the gain of `camera` (the output image's: for a tile, the tile's sub-window camera,
  // so that each pixel's position is its place in the whole image) into `out`, both `size`.
  void apply(const Camera& camera, ImageSize size, const gl::RenderTarget& in, const gl::RenderTarget& out) const;

 private:
  gl::Program program_;
  gl::FullScreenPass fullScreen_;
};

}  // namespace lenslab
