#include "scene/Scene.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace lenslab {

// Triangles drawn, not stored: a mesh placed twice counts twice.
std::size_t Scene::triangleCount() const {
  std::size_t count = 0;
  for (const Instance& instance : instances) {
    assert(instance.mesh >= 0 && static_cast<std::size_t>(instance.mesh) < meshes.size());
    count += meshes[static_cast<std::size_t>(instance.mesh)].indices.size() / 3;
  }
  return count;
}

// Every vertex through its instance's transform, in double precision: exact for any rotation,
// where transforming a mesh's own box would only bound it loosely.
Bounds computeBounds(const Scene& scene) {
  Bounds bounds;
  for (const Instance& instance : scene.instances) {
    assert(instance.mesh >= 0 && static_cast<std::size_t>(instance.mesh) < scene.meshes.size());
    for (const Vertex& v : scene.meshes[static_cast<std::size_t>(instance.mesh)].vertices)
      bounds.extend(glm::dvec3(instance.worldFromModel * glm::dvec4(glm::dvec3(v.position), 1.0)));
  }
  return bounds;
}

glm::dmat3 worldNormalFromModel(const glm::dmat4& worldFromModel) {
  const glm::dmat3 normal = glm::transpose(glm::inverse(glm::dmat3(worldFromModel)));
  double largest = 0.0;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) largest = std::max(largest, std::abs(normal[c][r]));
  return std::isfinite(largest) && largest > 0.0 ? normal / largest : normal;
}

}  // namespace lenslab
