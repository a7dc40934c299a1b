#include "scene/Scene.h"

#include <cassert>

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

}  // namespace lenslab
