#pragma once
// tinygltf: the JSON (or GLB) parsed into a tinygltf::Model, with images kept encoded, and the
// one checked way into the Model's buffers. tinygltf 2.7 checks no index, offset or length: the
// rest of the loader does, before a byte is read.
#include <tiny_gltf.h>

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace lenslab::gltf {

using Bytes = std::span<const unsigned char>;

// `input` is the .gltf's JSON or a GLB of the JSON and BIN chunks only (glbForTinygltf); relative
// URIs are read from `directory`. Each file a URI names is added to `filesRead` as it is read.
tinygltf::Model parseModel(std::string_view input, bool binary, const std::filesystem::path& directory,
                           std::vector<std::filesystem::path>& filesRead);

// A bufferView's bytes, after checking that it lies inside its buffer; `what` names the referrer.
Bytes viewBytes(const tinygltf::Model& model, int viewIndex, const std::string& what);

}  // namespace lenslab::gltf
