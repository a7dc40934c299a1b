#pragma once
// What the glTF loader refuses rather than risk its stack or memory, and the extensions it
// implements. Internal to the loader (src/scene/gltf and src/scene/GltfLoader.cpp).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace lenslab::gltf {

// tinygltf 2.7 turns "extras" and "extensions" into Values recursively: a file nested a few
// hundred thousand levels deep overflows the stack. Real files nest fewer than 20 levels.
// (A workaround for tinygltf 2.7, tagged where it is applied: checkNestingDepth in JsonCheck.cpp.)
constexpr int kMaxJsonDepth = 512;
// An accessor without a bufferView is zeros plus its sparse values: nothing in the file bounds
// its count, so a typo could ask for gigabytes. This many components (128 MiB as doubles).
constexpr std::size_t kMaxUnbackedComponents = std::size_t{1} << 24;
// Decoded images: per side, GL_MAX_TEXTURE_SIZE of common GPUs; in all, so that tinygltf 2.7
// (which sizes its copy of the pixels in int) cannot overflow on 16-bit RGBA. kMaxImagePixels is
// a workaround for tinygltf 2.7, tagged where it is applied: decodeImage in Images.cpp.
constexpr std::uint32_t kMaxImageSide = 16384;
constexpr std::uint64_t kMaxImagePixels = std::uint64_t{1} << 27;

// The extensions lenslab implements, so the only ones a file may require.
inline const std::vector<std::string> kSupportedExtensions = {"KHR_materials_unlit", "KHR_materials_emissive_strength",
                                                              "KHR_lights_punctual", "KHR_texture_transform"};

}  // namespace lenslab::gltf
