#pragma once
// The scene pass: every instance drawn once with the camera's clipFromWorld, into a float colour
// target with reverse-Z depth (clear to 0, GREATER). One pass is one view from one PRP.
//
// A narrow field of view (window under 1/kNarrowFieldSlope of the PRP's distance, about 2e-3 rad)
// is drawn by shaders/scene/narrow_field.*: positions in double, each triangle clipped in double
// to twice the image before GL's float takes over. In float alone a vertex 1e8 window widths
// off-axis has no digit left for where its triangle crosses the image (a sky stripe across a
// uniform floor at 1e-7 rad).
#include "gl/Framebuffer.h"
#include "gl/Object.h"
#include "plan/TileBudget.h"
#include "render/GpuScene.h"

#include <glm/glm.hpp>

#include <optional>

namespace lenslab {

// PRP distance over window size (about 1 / field of view) from which the scene pass clips in double.
constexpr double kNarrowFieldSlope = 1e3;

// Whether a perspective clipFromWorld has a field of view narrow enough for the double path.
bool isNarrowField(const glm::dmat4& clipFromWorld);

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
  void drawInstances(GLuint program, bool narrow, const GpuScene& scene, const glm::dmat4& clipFromWorld) const;

  gl::Program program_;
  mutable std::optional<gl::Program> narrowProgram_;  // built on first use: needs fp64 shaders
};

}  // namespace lenslab
