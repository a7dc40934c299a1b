#include "scene/gltf/Container.h"

#include "core/TextFile.h"
#include "scene/gltf/Problems.h"

#include <cstdint>

namespace lenslab::gltf {
namespace fs = std::filesystem;

namespace {

std::uint32_t littleEndian32(std::string_view bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i)
    v |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  return v;
}

constexpr std::uint32_t kGlbJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kGlbBinChunk = 0x004E4942;   // "BIN\0"

}  // namespace

std::string readFile(const fs::path& file) { return readInputFile(file, "glTF file", kMaxGltfFileBytes); }

bool startsWithGlbMagic(std::string_view bytes) { return bytes.substr(0, 4) == "glTF"; }

// The GLB container (glTF 2.0, "Binary glTF Layout"): a 12-byte header (magic, version 2, total
// length), then chunks of (length, type, data) with lengths that are multiples of 4: JSON first,
// an optional BIN second, chunks of unknown type anywhere after the JSON (to be ignored).
// tinygltf-2.7: the container is checked here because tinygltf 2.7 never checks the version,
// accepts a header length shorter than the file and only warns on an unaligned JSON chunk; can go
// when tinygltf is upgraded to one that refuses these (lenslab's messages name the rule broken).
GlbChunks splitGlb(std::string_view bytes) {
  if (bytes.size() < 12) refuse("GLB header is cut off: the file has ", bytes.size(), " bytes, the header alone 12");
  if (const std::uint32_t version = littleEndian32(bytes, 4); version != 2)
    refuse("GLB version is ", version, "; lenslab reads version 2");
  if (const std::uint32_t length = littleEndian32(bytes, 8); length != bytes.size())
    refuse("GLB header gives a length of ", length, " bytes but the file has ", bytes.size());
  GlbChunks chunks;
  std::size_t at = 12;
  for (int index = 0; at < bytes.size(); ++index) {
    if (bytes.size() - at < 8) refuse("GLB chunk ", index, " is cut off in its 8-byte header");
    const std::uint32_t length = littleEndian32(bytes, at), type = littleEndian32(bytes, at + 4);
    if (length % 4 != 0) refuse("GLB chunk ", index, " has length ", length, ", not a multiple of 4");
    if (length > bytes.size() - at - 8)
      refuse("GLB chunk ", index, " (", length, " bytes) runs past the end of the file");
    const std::string_view data = bytes.substr(at + 8, length);
    if (index == 0 && type != kGlbJsonChunk) refuse("the first GLB chunk must be JSON (type 0x4E4F534A)");
    if (index > 0 && type == kGlbJsonChunk) refuse("GLB chunk ", index, " is a second JSON chunk");
    if (type == kGlbBinChunk && index != 1)
      refuse("GLB chunk ", index, " is BIN; a BIN chunk must come right after the JSON");
    if (index == 0) chunks.json = data;
    if (type == kGlbBinChunk) chunks.bin = data;
    at += 8 + length;
  }
  if (at == 12) refuse("GLB has no JSON chunk (the file is only a header)");
  return chunks;
}

// tinygltf 2.7 reads the chunk right after the JSON as BIN (refusing it when its type is another)
// and looks no further. It gets a GLB of the JSON and BIN chunks only, so that unknown chunks are
// ignored as the spec asks (empty when the file is just that already, to spare a copy of a large
// file).
// tinygltf-2.7: the GLB is rebuilt without unknown chunks, which tinygltf 2.7 refuses when one comes
// right after the JSON; can go when tinygltf is upgraded to one that skips unknown chunk types.
std::string glbForTinygltf(const GlbChunks& chunks, std::size_t fileSize) {
  auto u32 = [](std::string& out, std::size_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
  };
  const std::size_t total = 12 + 8 + chunks.json.size() + (chunks.bin ? 8 + chunks.bin->size() : 0);
  if (total == fileSize) return {};
  std::string glb = "glTF";
  u32(glb, 2);
  u32(glb, total);
  u32(glb, chunks.json.size());
  u32(glb, kGlbJsonChunk);
  glb.append(chunks.json);
  if (chunks.bin) {
    u32(glb, chunks.bin->size());
    u32(glb, kGlbBinChunk);
    glb.append(*chunks.bin);
  }
  return glb;
}

}  // namespace lenslab::gltf
