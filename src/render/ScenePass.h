#pragma once
// The scene pass: every instance drawn once with the camera's clipFromWorld, into a float colour
// target with reverse-Z depth (clear to 0, GREATER). One pass is one view from one PRP.
#include "gl/Framebuffer.h"
#include "gl/Object.h"
#include "plan/TileBudget.h"
#include "render/GpuScene.h"

#include <glm/glm.hpp>

namespace lenslab {

class ScenePass {
 public:
  ScenePass();  // builds the program (needs a current context)
  // `lodBias` is added to the textures' level of detail: −½·log2 N when this view is one of N
  // sub-pixel-jittered views of a pixel (scene.frag says why).
  // `boxes`: when given, only those rectangles of the target are cleared and drawn (per-tile
  // budgets: later views only where tiles still need them), one scissored pass each.
  void draw(const GpuScene& scene, const glm::dmat4& clipFromWorld, const gl::DrawTarget& target,
            float lodBias = 0.0f, const std::vector<PixelBox>* boxes = nullptr) const;

 private:
  void drawInstances(const GpuScene& scene, const glm::dmat4& clipFromWorld) const;

  gl::Program program_;
};

}  // namespace lenslab
