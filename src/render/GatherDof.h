#pragma once
// A single-pass post-process gather depth of field from a pinhole view's colour and depth: the
// baseline real-time engines use, implemented for the error-against-time comparison only (it is
// not lenslab's depth of field, which accumulates aperture views).
#include "camera/Camera.h"
#include "core/Image.h"
#include "gl/Framebuffer.h"
#include "gl/FullScreenPass.h"
#include "gl/Object.h"

#include <memory>
#include <vector>

namespace lenslab {

class GatherDof {
 public:
  GatherDof();  // builds the program (needs a current context)

  // `pinhole`: the sharp view (colour and reverse-Z depth) from Renderer::renderPinhole. The circle
  // of confusion of each pixel comes from `camera` (cocDiameterOnWindow), computed on the CPU from
  // the read-back depth (about 0.8 ms at 480×320 here, counted in the baseline's time). Waits for
  // the GPU.
  Image apply(const Camera& camera, const gl::RenderTarget& pinhole, int tapCount);

 private:
  gl::Program program_;
  gl::FullScreenPass fullScreen_;
  gl::Texture coc_;
  std::unique_ptr<gl::RenderTarget> out_;
};

}  // namespace lenslab
