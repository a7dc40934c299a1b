#pragma once
// KHR_lights_punctual: the lights a node places, checked and converted into Scene::lights in the
// extension's units (lux for directional lights, candela for point and spot lights).
#include "scene/Scene.h"

#include <tiny_gltf.h>

#include <optional>

namespace lenslab::gltf {

// The light node `nodeIndex` places (its "extensions": {"KHR_lights_punctual": {"light": i}}) at
// its world placement, or nullopt where it places none. A problem with the light or the
// reference is refused naming the light index and the field.
std::optional<PunctualLight> placedLight(const tinygltf::Model& model, const tinygltf::Node& node, int nodeIndex,
                                         const glm::dmat4& worldFromNode);

}  // namespace lenslab::gltf
