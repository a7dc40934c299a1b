#pragma once
// The vignetting pass: the finished image times the lens's relative illumination at each pixel's
// place on the film (lens/LensEffects.h, Vignetting). It runs where no resolve of many views ends
// the frame (one view, the lens remap of one view, the two-stream resolve; a resolve multiplies
// the gain in itself), reading one image and writing another, so that resolving a frame again
// never applies it twice.
#include "gl/Framebuffer.h"
#include "gl/FullScreenPass.h"
#include "gl/Object.h"
#include "render/VignetteGain.h"

namespace lenslab {

class VignettePass {
 public:
  VignettePass();  // needs a current context

  // `in` times `gain` into `out` (both the output image's size).
  void apply(const VignetteGain& gain, const gl::RenderTarget& in, const gl::RenderTarget& out) const;

 private:
  gl::Program program_;
  gl::FullScreenPass fullScreen_;
};

}  // namespace lenslab
