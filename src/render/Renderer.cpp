#include "render/Renderer.h"

#include "camera/Projection.h"

#include <stdexcept>

namespace lenslab {

Renderer::Renderer(const Scene& scene) : gpuScene_(scene) {}

const gl::RenderTarget& Renderer::targetFor(ImageSize size) {
  if (!target_ || target_->width() != size.widthPx || target_->height() != size.heightPx)
    target_ = std::make_unique<gl::RenderTarget>(size.widthPx, size.heightPx);
  return *target_;
}

Image Renderer::render(const Camera& camera, const FramePlan& plan, ImageSize size) {
  const gl::RenderTarget& target = targetFor(size);
  for (const PlannedPass& pass : plan.passes) {
    if (pass.name == "scene") {
      scenePass_.draw(gpuScene_, clipFromWorld(camera.view), target);
    } else {
      throw std::logic_error("frame plan names a pass the renderer does not have: " + pass.name);
    }
  }
  glFinish();
  return target.readColor();
}

std::vector<float> Renderer::lastDepth() const {
  if (!target_) return {};
  return target_->readDepth();
}

}  // namespace lenslab
