#include "scene/TextureTransform.h"

#include <cmath>

namespace lenslab {

glm::mat3 uvFromTexCoord(glm::vec2 offset, float rotationRadians, glm::vec2 scale) {
  const float c = std::cos(rotationRadians), s = std::sin(rotationRadians);
  // Column-major, as GLSL's mat3(...) in the extension's specification.
  const glm::mat3 translation(1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, offset.x, offset.y, 1.0f);
  const glm::mat3 rotation(c, -s, 0.0f, s, c, 0.0f, 0.0f, 0.0f, 1.0f);
  const glm::mat3 scaling(scale.x, 0.0f, 0.0f, 0.0f, scale.y, 0.0f, 0.0f, 0.0f, 1.0f);
  return translation * rotation * scaling;
}

}  // namespace lenslab
