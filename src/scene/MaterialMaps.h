#pragma once
// Texture coordinates and normal maps as both renderers compute them: the C++ side of
// shaders/common/material_maps.glsl (one definition; see that file for the formulas). Pure.
#include <glm/glm.hpp>

namespace lenslab {

// The uv a texture reference samples: TEXCOORD_`texCoord` through `uvFromTexCoord`.
glm::vec2 slotUv(glm::vec2 uv0, glm::vec2 uv1, int texCoord, const glm::mat3& uvFromTexCoord);

// The normal-mapped shading normal (world): `normal`, `tangent` interpolated vertex normal and
// tangent xyz, `handedness` the tangent's w × the sign of worldFromModel's determinant, `texel`
// the normal map's linear RGB, `scale` normalTexture.scale.
glm::vec3 mappedNormal(glm::vec3 normal, glm::vec3 tangent, float handedness, glm::vec3 texel, float scale);

}  // namespace lenslab
