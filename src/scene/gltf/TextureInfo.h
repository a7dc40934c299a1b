#pragma once
// A material's textureInfo (glTF "textureInfo", "normalTextureInfo", "occlusionTextureInfo"):
// its uv set and KHR_texture_transform, as a TextureRef. Internal to the loader.
#include "scene/Scene.h"

#include <tiny_gltf.h>

#include <string>

namespace lenslab::gltf {

// The uv set (the extension's texCoord overrides the textureInfo's) and the uv transform of a
// textureInfo whose texture is `texture` (an index into Scene::textures). Refuses a transform
// whose values are not finite numbers of the extension's shapes, naming `where`. The offset is
// taken, in double, to within one period of `sampler`'s wrap (1 for repeat, 2 for mirrored
// repeat): the same image, and no fraction of it lost when it becomes a float (an offset of
// 10^20 + 0.3 would be 10^20).
TextureRef textureRef(int texture, int texCoord, const tinygltf::ExtensionMap& extensions, const std::string& where,
                      const Sampler& sampler = {});

// The uv set a textureInfo samples, with the extension's override (for the checks before
// a texture is converted): the textureInfo's own texCoord where there is none.
int effectiveTexCoord(int texCoord, const tinygltf::ExtensionMap& extensions);

}  // namespace lenslab::gltf
