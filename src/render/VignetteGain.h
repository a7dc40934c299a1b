#pragma once
// The uniforms of shaders/common/vignetting.glsl: where each pixel of an output image sits on the
// film (normalised coordinates, linear in the GL pixel position) and the gain's coefficients.
// Shared by the resolve that multiplies the gain in (Accumulator::resolve) and the pass of its own
// (VignettePass) where no resolve runs last.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "gl/Object.h"

#include <glm/glm.hpp>

namespace lenslab {

struct VignetteGain {
  glm::vec2 normalisedAtOrigin{0.0f};  // the GL pixel corner (0, 0)
  glm::vec2 normalisedPerPixel{0.0f};
  glm::vec3 coefficients{0.0f};  // a1, a2, a3
};

// For `camera`'s output image of `size` (for a tile, the tile's sub-window camera, so that each
// pixel's position is its place in the whole image).
VignetteGain vignetteGainFor(const Camera& camera, ImageSize size);
// Sets the uniforms (locations 40–42) on `program`.
void setVignetteGain(GLuint program, const VignetteGain& gain);

}  // namespace lenslab
