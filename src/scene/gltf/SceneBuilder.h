#pragma once
// The drawn scene: the default scene's node trees walked into a lenslab Scene (instances with
// their world transforms, cameras, and the node list and channels that poseScene moves them by),
// converting meshes, materials, textures and images on first
// use, so that only what is drawn is kept (and only those images decoded).
#include "scene/Scene.h"
#include "scene/gltf/Accessors.h"

#include <tiny_gltf.h>

#include <vector>

namespace lenslab::gltf {

// Fills `scene` (its meshes, materials, textures, images, instances, cameras, animation and notes) from a
// Model that checkModel passed; `parents` is what checkModel returned.
void buildScene(const tinygltf::Model& model, const AccessorReader& reader, const std::vector<int>& parents,
                Scene& scene);

}  // namespace lenslab::gltf
