#include "scene/BlendOrder.h"

#include <algorithm>
#include <utility>

namespace lenslab {

bool isBlended(const Scene& scene, const Instance& instance) {
  const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
  return mesh.material >= 0 && scene.materials[static_cast<std::size_t>(mesh.material)].alphaMode == AlphaMode::Blend;
}

bool anyBlended(const Scene& scene) {
  return std::any_of(scene.instances.begin(), scene.instances.end(),
                     [&](const Instance& i) { return isBlended(scene, i); });
}

glm::dvec3 instanceBoundsCentre(const Scene& scene, const Instance& instance) {
  Bounds model;
  for (const Vertex& v : scene.meshes[static_cast<std::size_t>(instance.mesh)].vertices)
    model.extend(glm::dvec3(v.position));
  const glm::dvec3 centre = model.empty() ? glm::dvec3(0.0) : model.center();
  return glm::dvec3(instance.worldFromModel * glm::dvec4(centre, 1.0));
}

std::vector<std::size_t> blendBackToFront(const Scene& scene, const glm::dvec3* eye, const glm::dvec3& towardViewer) {
  std::vector<std::pair<double, std::size_t>> keyed;  // (distance from the viewer, instance)
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    if (!isBlended(scene, scene.instances[i])) continue;
    const glm::dvec3 centre = instanceBoundsCentre(scene, scene.instances[i]);
    keyed.emplace_back(eye ? glm::length(centre - *eye) : -glm::dot(centre, towardViewer), i);
  }
  std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::size_t> order;
  order.reserve(keyed.size());
  for (const auto& [distance, i] : keyed) order.push_back(i);
  return order;
}

}  // namespace lenslab
