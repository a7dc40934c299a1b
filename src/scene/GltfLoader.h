#pragma once
// glTF 2.0 (.gltf and .glb) → Scene, through Debian's tinygltf 2.7 (parsing only: every index,
// offset, stride and count is checked here before a byte is read).
//
// What is kept: the default scene's node hierarchy (matrix or TRS, composed in double precision),
// triangle primitives (lists, strips and fans; indexed or not), normals (flat ones generated when
// absent, as the glTF spec asks), TEXCOORD_0 and TEXCOORD_1, TANGENT (MikkTSpace tangents made
// where a normal-mapped mesh has none), COLOR_0, base colour factor and texture with its
// sampler, normal texture and scale, KHR_texture_transform on every texture, KHR_materials_unlit, alpha mode and cutoff, double-sidedness, cameras, and the node
// animations (translation, rotation, scale; STEP, LINEAR, CUBICSPLINE), each of the file's
// animations a clip of Scene::animation. The returned scene is at rest (the nodes' own
// transforms); poseScene (scene/SceneAnimation.h) moves it to a time.
// What is left out, with a line in Scene::notes: points and lines, other PBR inputs, texture
// coordinate sets beyond 1, skins (bind pose), morph targets (base mesh) and the animation channels
// that drive their weights, channels on nodes outside the drawn scene or given by a matrix,
// unsupported extensions that the file uses but does not require.
// Only meshes, materials, textures and images that the drawn scene uses end up in the Scene, and
// only those images are decoded ("upload nothing the scene does not use").
//
// A file that is not valid glTF, or needs what lenslab cannot do (a required extension other
// than KHR_materials_unlit), is refused with an InputError of one line: the file, the problem and,
// where there is one, what would be valid. A scene without a single triangle still loads (its
// bounds are empty); callers decide what to do with it.
#include "scene/Scene.h"

#include <filesystem>

namespace lenslab {

// Reads a .gltf (JSON, buffers and images beside it or in data: URIs) or a .glb (recognised by
// its magic "glTF", whatever the extension). Throws InputError.
Scene loadGltf(const std::filesystem::path& file);

}  // namespace lenslab
