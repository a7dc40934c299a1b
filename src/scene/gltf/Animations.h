#pragma once
// Animations: the file's animation channels read into Scene::animation, for the nodes that
// SceneBuilder placed, with notes on what is not played (morph target weights, nodes outside the
// drawn scene, nodes given by a matrix, channels overridden by a later one).
#include "scene/Scene.h"
#include "scene/gltf/Accessors.h"

#include <tiny_gltf.h>

#include <vector>

namespace lenslab::gltf {

// Fills scene.animation.clips from every animation of a Model that checkModel passed, one clip
// each, in the file's order (the first plays unless another is chosen). scene.animation.nodes holds the placed nodes; `slotOfNode` maps a
// glTF node to its index there (-1: not drawn). When no channel plays, the nodes are dropped too.
void readAnimations(const tinygltf::Model& model, const AccessorReader& reader, const std::vector<int>& slotOfNode,
                    Scene& scene);

}  // namespace lenslab::gltf
