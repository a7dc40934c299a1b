#pragma once
// glTF 2.0 (.gltf and .glb) → Scene, through Debian's tinygltf.
//
// What is kept: the default scene's node hierarchy (matrix or TRS, composed in double precision),
// triangle primitives (lists, strips and fans; indexed or not), normals (flat ones generated when
// absent, as the glTF spec asks), TEXCOORD_0, COLOR_0, base colour factor and texture with its
// sampler, KHR_materials_unlit, alpha mode and cutoff, double-sidedness, cameras.
// What is left out, with a note in Scene::notes: points and lines, other PBR inputs, skins,
// morph targets, animations. Only meshes, materials, textures and images that the drawn scene uses
// end up in the Scene ("upload nothing the scene does not use").
//
// Every index, offset and stride is checked before it is read: a malformed file is refused with
// an InputError of one line naming the file and the problem, never a crash.
#include "scene/Scene.h"

#include <filesystem>

namespace lenslab {

Scene loadGltf(const std::filesystem::path& file);

}  // namespace lenslab
