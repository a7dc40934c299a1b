#pragma once
// The checks that make the rest safe: every reference resolves, every view fits, every value the
// scene uses is valid, the node hierarchy is a forest. After them, the scene walk and the
// primitive conversion index the Model without checking again.
#include "scene/gltf/Accessors.h"

#include <tiny_gltf.h>

#include <vector>

namespace lenslab::gltf {

// Runs every check (refusing the file at the first problem) and returns each node's parent (-1
// for roots).
std::vector<int> checkModel(const tinygltf::Model& model, const AccessorReader& reader);

}  // namespace lenslab::gltf
