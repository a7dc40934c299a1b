#pragma once
// The file and the GLB container: reading the bytes, and splitting (and checking) a binary glTF
// into its JSON and BIN chunks before tinygltf sees it.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace lenslab::gltf {

// The whole file (core/TextFile.h: readInputFile): a regular file of at most 4 GiB, else InputError.
std::string readFile(const std::filesystem::path& file);

// A GLB is recognised by its magic "glTF", whatever the file's extension.
bool startsWithGlbMagic(std::string_view bytes);

struct GlbChunks {
  std::string_view json;
  std::optional<std::string_view> bin;
};

// The JSON and (optional) BIN chunks of a GLB, views into `bytes`; refuses a malformed container.
GlbChunks splitGlb(std::string_view bytes);

// The GLB that tinygltf is given: the JSON and BIN chunks only; empty when the file is that already.
std::string glbForTinygltf(const GlbChunks& chunks, std::size_t fileSize);

}  // namespace lenslab::gltf
