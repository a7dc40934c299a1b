#include "scene/Scene.h"

namespace lenslab {

std::size_t Scene::triangleCount() const {
  std::size_t count = 0;
  for (const Instance& instance : instances)
    count += meshes[static_cast<std::size_t>(instance.mesh)].indices.size() / 3;
  return count;
}

Bounds computeBounds(const Scene& scene) {
  Bounds bounds;
  for (const Instance& instance : scene.instances)
    for (const Vertex& v : scene.meshes[static_cast<std::size_t>(instance.mesh)].vertices)
      bounds.extend(glm::dvec3(instance.worldFromModel * glm::dvec4(glm::dvec3(v.position), 1.0)));
  return bounds;
}

}  // namespace lenslab
