#include "scene/MaterialMaps.h"

namespace lenslab {

// The GLSL, as C++: glm's names are GLSL's.
namespace glsl {
using glm::cross;
using glm::dot;
using glm::length;
using glm::mat3;
using glm::normalize;
using glm::vec2;
using glm::vec3;
using glm::vec4;
#include "../../shaders/common/material_maps.glsl"
}  // namespace glsl

glm::vec2 slotUv(glm::vec2 uv0, glm::vec2 uv1, int texCoord, const glm::mat3& uvFromTexCoord) {
  return glsl::slotUv(uv0, uv1, texCoord, uvFromTexCoord);
}

glm::vec3 mappedNormal(glm::vec3 normal, glm::vec3 tangent, float handedness, glm::vec3 texel, float scale) {
  return glsl::mappedNormal(normal, tangent, handedness, texel, scale);
}

}  // namespace lenslab
