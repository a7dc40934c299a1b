#include "render/GatherDof.h"

#include "camera/Projection.h"
#include "gl/Shader.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

GatherDof::GatherDof() : program_(gl::buildProgram("common/fullscreen.vert", "postdof/gather.frag")) {}

Image GatherDof::apply(const Camera& camera, const gl::RenderTarget& pinhole, int tapCount) {
  const int w = pinhole.width(), h = pinhole.height();
  // Circle-of-confusion radius per pixel from the depth (read back rows from the top; the texture
  // is uploaded rows from the bottom, as GL has them).
  const std::vector<float> topDown = pinhole.readDepth();
  std::vector<float> radius(topDown.size());
  const double pxPerUnit = w / camera.view.window.width();
  float maxRadius = 0.0f;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double depth = depthFromReverseZ(camera.view, topDown[static_cast<std::size_t>(y * w + x)]);
      double r = 0.5 * pxPerUnit *
                 (std::isfinite(depth) ? cocDiameterOnWindow(camera, depth) : cocDiameterOnWindow(camera, 1e30));
      if (!std::isfinite(r)) r = 0.0;
      r = std::min(r, 256.0);
      radius[static_cast<std::size_t>((h - 1 - y) * w + x)] = static_cast<float>(r);
      maxRadius = std::max(maxRadius, static_cast<float>(r));
    }
  if (!out_ || out_->width() != w || out_->height() != h) {
    out_ = std::make_unique<gl::RenderTarget>(w, h);
    coc_ = gl::Texture::create();
    glTextureStorage2D(coc_.id(), 1, GL_R32F, w, h);
  }
  glTextureSubImage2D(coc_.id(), 0, 0, 0, w, h, GL_RED, GL_FLOAT, radius.data());
  out_->bind();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glProgramUniform1i(program_.id(), 0, tapCount);
  glProgramUniform1f(program_.id(), 1, maxRadius);
  glBindTextureUnit(0, pinhole.colorTexture());
  glBindTextureUnit(1, coc_.id());
  glBindSampler(0, 0);
  glBindSampler(1, 0);
  fullScreen_.draw(program_);
  glFinish();
  return out_->readColor();
}

}  // namespace lenslab
