#pragma once
// Images: the encoded bytes (a checked bufferView, or what the image callback kept of a uri),
// the format and size an image claims, and decoding to RGBA8 (only for images the scene uses).
#include "scene/Scene.h"
#include "scene/gltf/TinygltfModel.h"

#include <cstdint>
#include <string>

namespace lenslab::gltf {

// "image 3 \"name\" (file.png)", for messages.
std::string imageLabel(const tinygltf::Model& model, int index);

// The encoded image; refuses one that could not be read.
Bytes encodedImage(const tinygltf::Model& model, int index);

enum class ImageFormat { Unknown, Png, Jpeg };

struct ImageHeader {
  ImageFormat format = ImageFormat::Unknown;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
};

// The format and size an image claims, from its first bytes; refuses a PNG or JPEG that is cut
// off. Unknown formats are left to the caller.
ImageHeader inspectImage(Bytes b, const std::string& label);

// Image `index` decoded to RGBA8; refuses formats other than PNG and JPEG, and sizes beyond the limits.
TextureImage decodeImage(const tinygltf::Model& model, int index);

}  // namespace lenslab::gltf
