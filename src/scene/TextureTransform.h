#pragma once
// KHR_texture_transform's map of a texture's uv: uv' = translation · rotation · scale · (u, v, 1),
// as the extension's specification composes it. Pure (GLM only).
#include <glm/glm.hpp>

namespace lenslab {

// `offset` and `scale` in uv units; `rotationRadians` turns the uv counter-clockwise about the
// origin (u' = cos·u + sin·v, v' = −sin·u + cos·v: with v pointing down the image, the image
// appears turned clockwise).
glm::mat3 uvFromTexCoord(glm::vec2 offset, float rotationRadians, glm::vec2 scale);

// The same map for a uv step (a derivative): its linear part, without the offset.
inline glm::vec2 uvStepFromTexCoordStep(const glm::mat3& uvFromTexCoord, glm::vec2 step) {
  return glm::vec2(uvFromTexCoord * glm::vec3(step, 0.0f));
}

}  // namespace lenslab
