#pragma once
// The scene pass: every instance drawn once with the camera's clipFromWorld, into a float colour
// target with reverse-Z depth (clear to 0, GREATER). One pass is one view from one PRP.
#include "gl/Framebuffer.h"
#include "gl/Object.h"
#include "render/GpuScene.h"

#include <glm/glm.hpp>

namespace lenslab {

// Field curvature in the raster path (an approximation; the ray caster's is exact). A view from
// lens offset δ, focused at inverse distance φ, puts a point of depth Z at window position
// d·X/Z + δ·d·(φ − 1/Z): changing the focus by Δφ moves the image of every point by δ·d·Δφ. A
// curved focal surface, φ(r) = φ + κr², therefore moves each vertex by δ·d·κ·r², r being the
// vertex's normalised radius seen from the lens centre. Exact at the vertices; across a triangle
// the move is interpolated linearly (its r² is not), which is this approximation's error.
struct FocusWarp {
  glm::dmat4 eyeFromWorld;          // the lens centre's eye frame (the unmoved PRP)
  glm::dvec2 ndcShiftPerRadius2;    // 2·δ·d·κ / window size: the move in NDC at r = 1
};

class ScenePass {
 public:
  ScenePass();  // builds the program (needs a current context)
  void draw(const GpuScene& scene, const glm::dmat4& clipFromWorld, const gl::DrawTarget& target,
            const FocusWarp* warp = nullptr);

 private:
  gl::Program program_;
  gl::Program curvedProgram_;  // the field-curvature variant, built on first use
};

}  // namespace lenslab
