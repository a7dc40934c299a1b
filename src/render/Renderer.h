#pragma once
// Runs a frame plan on the current GL context and returns the linear image.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "core/Image.h"
#include "gl/Framebuffer.h"
#include "plan/FramePlan.h"
#include "render/GpuScene.h"
#include "render/ScenePass.h"

#include <memory>

namespace lenslab {

class Renderer {
 public:
  // Uploads the scene and builds the programs; `scene` must outlive the renderer.
  explicit Renderer(const Scene& scene);

  // Renders and waits for the GPU (glFinish), so wall time around it is honest.
  Image render(const Camera& camera, const FramePlan& plan, ImageSize size);

  // Depth of the last render (reverse-Z z_ndc, rows from the top).
  std::vector<float> lastDepth() const;

 private:
  const gl::RenderTarget& targetFor(ImageSize size);

  GpuScene gpuScene_;
  ScenePass scenePass_;
  std::unique_ptr<gl::RenderTarget> target_;
};

}  // namespace lenslab
