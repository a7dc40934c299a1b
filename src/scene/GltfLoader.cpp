#include "scene/GltfLoader.h"

#include "core/Error.h"
#include "core/Text.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

using Bytes = std::span<const unsigned char>;

// ---- limits: what lenslab refuses rather than risk its stack or memory ----

// tinygltf 2.7 turns "extras" and "extensions" into Values recursively: a file nested a few
// hundred thousand levels deep overflows the stack. Real files nest fewer than 20 levels.
constexpr int kMaxJsonDepth = 512;
// An accessor without a bufferView is zeros plus its sparse values: nothing in the file bounds
// its count, so a typo could ask for gigabytes. This many components (128 MiB as doubles).
constexpr std::size_t kMaxUnbackedComponents = std::size_t{1} << 24;
// Decoded images: per side, GL_MAX_TEXTURE_SIZE of common GPUs; in all, so that tinygltf 2.7
// (which sizes its copy of the pixels in int) cannot overflow on 16-bit RGBA.
constexpr std::uint32_t kMaxImageSide = 16384;
constexpr std::uint64_t kMaxImagePixels = std::uint64_t{1} << 27;

// The extensions lenslab implements, so the only ones a file may require.
const std::vector<std::string> kSupportedExtensions = {"KHR_materials_unlit"};

// ---- problems and notes ----

// A problem with the file, in words; loadGltf prefixes the file name and throws InputError.
struct Problem : std::runtime_error {
  using std::runtime_error::runtime_error;
};

template <class... Parts>
[[noreturn]] void refuse(const Parts&... parts) {
  throw Problem(cat(parts...));
}

// tinygltf ends each of its errors with a newline; a message here is one line: "first; second".
std::string oneLine(const std::string& text) {
  std::string out, line;
  std::istringstream in(text);
  while (std::getline(in, line)) {
    std::replace(line.begin(), line.end(), '\r', ' ');
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    const auto last = line.find_last_not_of(" \t");
    if (!out.empty()) out += "; ";
    out += line.substr(first, last - first + 1);
  }
  return out;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

void noteOnce(std::vector<std::string>& notes, const std::string& note) {
  if (std::find(notes.begin(), notes.end(), note) == notes.end()) notes.push_back(note);
}

void requireIndex(int index, std::size_t count, const std::string& what, const char* kind) {
  if (index < 0 || static_cast<std::size_t>(index) >= count)
    refuse(what, " refers to ", kind, " ", index, ", which does not exist (",
           count == 0 ? std::string("the file has none") : cat("valid: 0 to ", count - 1), ")");
}

std::size_t toIndex(int index) { return static_cast<std::size_t>(index); }

// ---- component types ----

std::size_t componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;  // not a glTF component type
  }
}

std::string componentTypeName(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    default: return cat("componentType ", componentType);
  }
}

std::string typeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return cat("type ", type);
  }
}

bool isUnsignedIndexType(int componentType) {
  return componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
         componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
         componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

// Where each component of one element lies. Matrix columns start on 4-byte boundaries (glTF
// "Data Alignment"), which only matters for byte and short matrices.
struct ElementLayout {
  std::size_t componentSize = 0;
  std::size_t components = 0;
  std::size_t rows = 0;          // components per column (all of them for scalars and vectors)
  std::size_t columnStride = 0;  // bytes
  std::size_t size = 0;          // bytes of one element
  std::size_t offset(std::size_t c) const { return c / rows * columnStride + c % rows * componentSize; }
};

// Empty (components == 0) for an unknown type or component type.
ElementLayout elementLayout(int type, int componentType) {
  ElementLayout l;
  l.componentSize = componentSize(componentType);
  std::size_t columns = 1;
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: l.rows = 1; break;
    case TINYGLTF_TYPE_VEC2: l.rows = 2; break;
    case TINYGLTF_TYPE_VEC3: l.rows = 3; break;
    case TINYGLTF_TYPE_VEC4: l.rows = 4; break;
    case TINYGLTF_TYPE_MAT2: l.rows = columns = 2; break;
    case TINYGLTF_TYPE_MAT3: l.rows = columns = 3; break;
    case TINYGLTF_TYPE_MAT4: l.rows = columns = 4; break;
    default: return {};
  }
  if (l.componentSize == 0) return {};
  l.components = l.rows * columns;
  l.columnStride = l.rows * l.componentSize;
  if (columns > 1) l.columnStride = (l.columnStride + 3) / 4 * 4;
  l.size = l.columnStride * columns;
  return l;
}

// One component as stored (integers as their integer value).
double storedComponent(const unsigned char* p, int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return static_cast<std::int8_t>(p[0]);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
    case TINYGLTF_COMPONENT_TYPE_SHORT: { std::int16_t v; std::memcpy(&v, p, 2); return v; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { std::uint16_t v; std::memcpy(&v, p, 2); return v; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { std::uint32_t v; std::memcpy(&v, p, 4); return v; }
    case TINYGLTF_COMPONENT_TYPE_FLOAT: { float v; std::memcpy(&v, p, 4); return v; }
    default: return 0.0;
  }
}

// glTF's "normalized" integers (spec, "Animations", the table of decoding equations).
double normalizedComponent(double stored, int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return std::max(stored / 127.0, -1.0);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return stored / 255.0;
    case TINYGLTF_COMPONENT_TYPE_SHORT: return std::max(stored / 32767.0, -1.0);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return stored / 65535.0;
    default: return stored;
  }
}

// ---- the file and the GLB container ----

std::string readFile(const fs::path& file) {
  std::error_code ec;
  if (fs::is_directory(file, ec)) refuse("cannot read file: ", std::strerror(EISDIR));
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(file.c_str(), "rb"), &std::fclose);
  if (!f) refuse("cannot read file: ", std::strerror(errno));
  std::string bytes;
  if (const auto size = fs::file_size(file, ec); !ec) bytes.reserve(static_cast<std::size_t>(size));
  char chunk[1 << 16];
  while (const std::size_t n = std::fread(chunk, 1, sizeof chunk, f.get())) bytes.append(chunk, n);
  if (std::ferror(f.get())) refuse("cannot read file: ", std::strerror(errno));
  return bytes;
}

bool startsWithGlbMagic(std::string_view bytes) { return bytes.substr(0, 4) == "glTF"; }

std::uint32_t littleEndian32(std::string_view bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  return v;
}

constexpr std::uint32_t kGlbJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kGlbBinChunk = 0x004E4942;   // "BIN\0"

struct GlbChunks {
  std::string_view json;
  std::optional<std::string_view> bin;
};

// The GLB container (glTF 2.0, "Binary glTF Layout"): a 12-byte header (magic, version 2, total
// length), then chunks of (length, type, data) with lengths that are multiples of 4: JSON first,
// an optional BIN second, chunks of unknown type anywhere after the JSON (to be ignored).
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
    if (length > bytes.size() - at - 8) refuse("GLB chunk ", index, " (", length, " bytes) runs past the end of the file");
    const std::string_view data = bytes.substr(at + 8, length);
    if (index == 0 && type != kGlbJsonChunk) refuse("the first GLB chunk must be JSON (type 0x4E4F534A)");
    if (index > 0 && type == kGlbJsonChunk) refuse("GLB chunk ", index, " is a second JSON chunk");
    if (type == kGlbBinChunk && index != 1) refuse("GLB chunk ", index, " is BIN; a BIN chunk must come right after the JSON");
    if (index == 0) chunks.json = data;
    if (type == kGlbBinChunk) chunks.bin = data;
    at += 8 + length;
  }
  if (at == 12) refuse("GLB has no JSON chunk (the file is only a header)");
  return chunks;
}

// tinygltf 2.7 takes the chunk after the JSON for BIN whatever its type and stops there. It gets
// a GLB of the JSON and BIN chunks only, so that unknown chunks are ignored as the spec asks
// (empty when the file is just that already, to spare a copy of a large file).
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

// ---- the JSON, before tinygltf sees it ----

// The deepest nesting of arrays and objects (strings skipped), refused beyond kMaxJsonDepth.
void checkNestingDepth(std::string_view text) {
  int depth = 0;
  bool inString = false, escaped = false;
  for (const char c : text) {
    if (inString) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) refuse("the JSON nests deeper than ", kMaxJsonDepth, " levels");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

nlohmann::json parseJson(std::string_view text) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) refuse("the file is empty (glTF JSON starts with '{')");
  if (text.substr(0, 3) == "\xEF\xBB\xBF")
    refuse("the JSON starts with a UTF-8 byte-order mark, which glTF forbids (it must begin with '{')");
  checkNestingDepth(text);
  try {
    return nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::exception& e) {
    std::string what = e.what();  // "[json.exception.parse_error.101] parse error at ..."
    if (const auto end = what.find("] "); what.starts_with("[json.exception") && end != std::string::npos)
      what.erase(0, end + 2);
    refuse("invalid JSON: ", what);
  }
}

// "http://...", "file:..." (RFC 3986: a letter, then letters, digits, '+', '-', '.', then ':');
// data: URIs are the one scheme glTF readers must take. (No std::regex: libstdc++'s recurses per
// character and overflows the stack on a long data: URI.)
bool hasUriScheme(const std::string& uri) {
  if (uri.empty() || !std::isalpha(static_cast<unsigned char>(uri[0])) || uri.starts_with("data:")) return false;
  for (const char c : uri) {
    if (c == ':') return true;
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.') return false;
  }
  return false;
}

// root[key] when it is an array, else an empty array (no copy: buffers may hold megabytes).
const nlohmann::json& arrayAt(const nlohmann::json& root, const char* key) {
  static const nlohmann::json empty = nlohmann::json::array();
  const auto found = root.find(key);
  return found != root.end() && found->is_array() ? *found : empty;
}

// A string member, or "" when absent or not a string.
std::string stringAt(const nlohmann::json& object, const char* key) {
  if (!object.is_object()) return {};
  const auto found = object.find(key);
  return found != object.end() && found->is_string() ? found->get<std::string>() : std::string();
}

// What tinygltf lets pass or words unclearly: the top level's shape, required extensions (named
// before tinygltf trips over the data they encode), buffers without data, URIs that are not
// files beside the scene.
void precheckJson(const nlohmann::json& root, bool binary) {
  if (!root.is_object()) refuse("the top level of the JSON must be an object, not ", root.type_name());
  for (const char* key : {"accessors", "animations", "buffers", "bufferViews", "cameras", "images", "materials",
                          "meshes", "nodes", "samplers", "scenes", "skins", "textures", "extensionsUsed",
                          "extensionsRequired"})
    if (root.contains(key) && !root[key].is_array()) refuse("\"", key, "\" must be an array, not ", root[key].type_name());
  if (root.contains("asset") && !root["asset"].is_object()) refuse("\"asset\" must be an object");
  for (const auto& e : arrayAt(root, "extensionsRequired"))
    if (!e.is_string() || std::find(kSupportedExtensions.begin(), kSupportedExtensions.end(), e.get<std::string>()) ==
                              kSupportedExtensions.end())
      refuse("extensionsRequired lists ", e.is_string() ? e.get<std::string>() : e.dump(),
             ", which lenslab does not support (supported: ", joined(kSupportedExtensions), ")");
  const nlohmann::json& buffers = arrayAt(root, "buffers");
  for (std::size_t i = 0; i < buffers.size(); ++i) {
    if (buffers[i].is_object() && !buffers[i].contains("uri") && !(binary && i == 0))
      refuse("buffer ", i, " has no uri; only the first buffer of a .glb (its BIN chunk) may leave it out");
    if (const std::string uri = stringAt(buffers[i], "uri"); hasUriScheme(uri))
      refuse("buffer ", i, ": uri ", uri, " is not a relative path; lenslab reads files beside the scene and data: URIs");
  }
  const nlohmann::json& images = arrayAt(root, "images");
  for (std::size_t i = 0; i < images.size(); ++i)
    if (const std::string uri = stringAt(images[i], "uri"); hasUriScheme(uri))
      refuse("image ", i, ": uri ", uri, " is not a relative path; lenslab reads files beside the scene and data: URIs");
  // tinygltf 2.7 keeps only the matrix of a node that also has translation, rotation or scale.
  const nlohmann::json& nodes = arrayAt(root, "nodes");
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].is_object() && nodes[i].contains("matrix") &&
        (nodes[i].contains("translation") || nodes[i].contains("rotation") || nodes[i].contains("scale")))
      refuse("node ", i, " has both a matrix and translation/rotation/scale; glTF allows one or the other");
}

// ---- tinygltf ----

// tinygltf 2.7 decodes every image while it parses, used or not, and hands the callback for an
// image in a bufferView a pointer that it never checked against the buffer. This one keeps the
// encoded bytes of uri images only: bufferView images are read later from a checked view, and
// only the images the drawn scene samples are decoded (decodeImage).
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  if (image->bufferView < 0 && bytes != nullptr && size > 0) image->image.assign(bytes, bytes + size);
  return true;
}

tinygltf::Model parseModel(std::string_view input, bool binary, const fs::path& directory) {
  if (input.size() > UINT_MAX) refuse("the file is larger than the 4 GiB that glTF allows");
  tinygltf::TinyGLTF gltf;
  gltf.SetImageLoader(&keepEncodedImage, nullptr);
  tinygltf::Model model;
  std::string error, warning;
  bool ok = false;
  const auto size = static_cast<unsigned int>(input.size());
  try {
    ok = binary ? gltf.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(input.data()),
                                            size, directory.string())
                : gltf.LoadASCIIFromString(&model, &error, &warning, input.data(), size, directory.string());
  } catch (const std::exception& e) {
    refuse("tinygltf failed: ", e.what());
  }
  if (!ok) {
    // tinygltf 2.7 puts some reasons for failing (an empty image file) in the warnings only.
    const std::string reason = oneLine(error.empty() ? warning : error);
    refuse(reason.empty() ? std::string("tinygltf could not read it") : reason);
  }
  return model;
}

// A bufferView's bytes, after checking that it lies inside its buffer.
Bytes viewBytes(const tinygltf::Model& model, int viewIndex, const std::string& what) {
  requireIndex(viewIndex, model.bufferViews.size(), what, "bufferView");
  const tinygltf::BufferView& view = model.bufferViews[toIndex(viewIndex)];
  requireIndex(view.buffer, model.buffers.size(), cat("bufferView ", viewIndex), "buffer");
  const std::vector<unsigned char>& data = model.buffers[toIndex(view.buffer)].data;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
    refuse("bufferView ", viewIndex, " (byteOffset ", view.byteOffset, ", byteLength ", view.byteLength,
           ") runs past the end of buffer ", view.buffer, " (", data.size(), " bytes)");
  return Bytes(data).subspan(view.byteOffset, view.byteLength);
}

// ---- accessors ----

struct Elements {
  std::size_t count = 0;
  std::size_t components = 0;
  std::vector<double> values;  // count × components, element after element
  double at(std::size_t element, std::size_t component) const { return values[element * components + component]; }
};

// Reads accessors with every byte checked; tinygltf 2.7 gives only the JSON fields (it neither
// checks ranges nor applies sparse substitution).
class AccessorReader {
 public:
  explicit AccessorReader(const tinygltf::Model& model) : model_(model) {}

  // The elements after sparse substitution, checked against the declared min/max (which hold
  // stored values), then normalised integers mapped to [0, 1] or [-1, 1].
  Elements read(int index) const {
    const tinygltf::Accessor& a = model_.accessors[toIndex(index)];
    const std::string where = cat("accessor ", index);
    const ElementLayout layout = checkedLayout(a, where);
    Elements e;
    e.count = a.count;
    e.components = layout.components;
    e.values.assign(e.count * e.components, 0.0);
    if (a.bufferView >= 0) {
      const std::size_t stride = model_.bufferViews[toIndex(a.bufferView)].byteStride;
      decode(region(a.bufferView, a.byteOffset, a.count, layout, stride, where), a.count, layout, a.componentType, e.values.data());
    }
    if (a.sparse.isSparse) substituteSparse(a, layout, where, e);
    checkMinMax(a, where, e);
    if (a.normalized)
      for (double& v : e.values) v = normalizedComponent(v, a.componentType);
    return e;
  }

  // Everything about the accessor that can be checked without reading its data.
  void checkLayout(int index) const { (void)checkedLayout(model_.accessors[toIndex(index)], cat("accessor ", index)); }

 private:
  struct Region {
    const unsigned char* first = nullptr;
    std::size_t stride = 0;
  };

  ElementLayout checkedLayout(const tinygltf::Accessor& a, const std::string& where) const {
    const ElementLayout layout = elementLayout(a.type, a.componentType);
    if (layout.components == 0)
      refuse(where, ": ", typeName(a.type), " of ", componentTypeName(a.componentType),
             " is not a glTF accessor format (types SCALAR, VEC2-4, MAT2-4 of BYTE, UNSIGNED_BYTE, SHORT, "
             "UNSIGNED_SHORT, UNSIGNED_INT or FLOAT)");
    if (a.count == 0) refuse(where, ": count is 0; it must be at least 1");
    if (a.normalized && layout.componentSize > 2)
      refuse(where, ": normalized is set on ", componentTypeName(a.componentType),
             "; only BYTE, UNSIGNED_BYTE, SHORT and UNSIGNED_SHORT can be normalized");
    if (a.bufferView != -1) {
      requireIndex(a.bufferView, model_.bufferViews.size(), where, "bufferView");
      (void)region(a.bufferView, a.byteOffset, a.count, layout, model_.bufferViews[toIndex(a.bufferView)].byteStride, where);
    } else if (a.count > kMaxUnbackedComponents / layout.components) {
      refuse(where, ": count ", a.count, " without a bufferView is more than lenslab reads (",
             kMaxUnbackedComponents / layout.components, " of ", typeName(a.type), ")");
    }
    return layout;
  }

  // `count` elements from `byteOffset` in a bufferView, after checking that all lie inside it.
  Region region(int viewIndex, std::size_t byteOffset, std::size_t count, const ElementLayout& layout,
                std::size_t byteStride, const std::string& where) const {
    const Bytes view = viewBytes(model_, viewIndex, where);
    if (byteStride != 0 && byteStride < layout.size)
      refuse(where, ": byteStride ", byteStride, " of bufferView ", viewIndex, " is smaller than one element (",
             layout.size, " bytes)");
    const std::size_t stride = byteStride != 0 ? byteStride : layout.size;
    const std::size_t length = view.size();
    // Written so that nothing overflows, however large the count the file claims.
    if (byteOffset > length || layout.size > length - byteOffset || count - 1 > (length - byteOffset - layout.size) / stride)
      refuse(where, ": byteOffset + count*stride exceeds bufferView ", viewIndex, " (byteOffset ", byteOffset, ", count ",
             count, ", stride ", stride, ", length ", length, ")");
    return {view.data() + byteOffset, stride};
  }

  static void decode(const Region& r, std::size_t count, const ElementLayout& layout, int componentType, double* out) {
    for (std::size_t e = 0; e < count; ++e)
      for (std::size_t c = 0; c < layout.components; ++c)
        *out++ = storedComponent(r.first + e * r.stride + layout.offset(c), componentType);
  }

  // glTF sparse accessors: `count` strictly increasing element indices, each replaced by the value
  // at the same position in the values view (both tightly packed).
  void substituteSparse(const tinygltf::Accessor& a, const ElementLayout& layout, const std::string& where, Elements& e) const {
    const auto& sparse = a.sparse;
    if (sparse.count < 1 || static_cast<std::size_t>(sparse.count) > e.count)
      refuse(where, ": sparse.count ", sparse.count, " must be from 1 to the accessor's count (", e.count, ")");
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) refuse(where, ": a sparse byteOffset is negative");
    const int indexType = sparse.indices.componentType;
    if (!isUnsignedIndexType(indexType))
      refuse(where, ": sparse.indices.componentType is ", componentTypeName(indexType),
             "; it must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    const auto n = static_cast<std::size_t>(sparse.count);
    const ElementLayout indexLayout = elementLayout(TINYGLTF_TYPE_SCALAR, indexType);
    std::vector<double> targets(n), values(n * layout.components);
    decode(region(sparse.indices.bufferView, static_cast<std::size_t>(sparse.indices.byteOffset), n, indexLayout, 0,
                  where + " sparse.indices"),
           n, indexLayout, indexType, targets.data());
    decode(region(sparse.values.bufferView, static_cast<std::size_t>(sparse.values.byteOffset), n, layout, 0,
                  where + " sparse.values"),
           n, layout, a.componentType, values.data());
    for (std::size_t i = 0; i < n; ++i) {
      if (targets[i] >= static_cast<double>(e.count))
        refuse(where, ": sparse index ", targets[i], " is not below the accessor's count (", e.count, ")");
      if (i > 0 && targets[i] <= targets[i - 1]) refuse(where, ": sparse indices must strictly increase (", targets[i - 1], " then ", targets[i], ")");
      std::copy_n(&values[i * e.components], e.components, &e.values[static_cast<std::size_t>(targets[i]) * e.components]);
    }
  }

  // The declared bounds must hold the data (the validator's ACCESSOR_ELEMENT_OUT_OF_*_BOUND).
  static void checkMinMax(const tinygltf::Accessor& a, const std::string& where, const Elements& e) {
    for (const auto* bound : {&a.minValues, &a.maxValues})
      if (!bound->empty() && bound->size() != e.components)
        refuse(where, ": ", bound == &a.minValues ? "min" : "max", " has ", bound->size(), " numbers; a ", typeName(a.type),
               " accessor needs ", e.components);
    if (a.minValues.empty() && a.maxValues.empty()) return;
    // Float data is compared with a little slack: writers round min/max to a few decimals.
    auto slack = [&](double bound) { return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ? 1e-6 * (1.0 + std::abs(bound)) : 0.0; };
    for (std::size_t i = 0; i < e.count; ++i)
      for (std::size_t c = 0; c < e.components; ++c) {
        const double v = e.at(i, c);
        if (!std::isfinite(v)) refuse(where, ": element ", i, " is not a finite number");
        const bool low = !a.minValues.empty() && v < a.minValues[c] - slack(a.minValues[c]);
        const bool high = !a.maxValues.empty() && v > a.maxValues[c] + slack(a.maxValues[c]);
        if (low || high)
          refuse(where, ": element ", i, " component ", c, " is ", v, ", ", low ? "below the declared min " : "above the declared max ",
                 low ? a.minValues[c] : a.maxValues[c]);
      }
  }

  const tinygltf::Model& model_;
};

// ---- images ----

std::string imageLabel(const tinygltf::Model& model, int index) {
  const tinygltf::Image& image = model.images[toIndex(index)];
  std::string label = cat("image ", index);
  if (!image.name.empty()) label += cat(" \"", image.name, "\"");
  if (!image.uri.empty() && !image.uri.starts_with("data:")) label += cat(" (", image.uri, ")");
  return label;
}

// The encoded image: from its bufferView, or the bytes keepEncodedImage kept of its uri.
Bytes encodedImage(const tinygltf::Model& model, int index) {
  const tinygltf::Image& image = model.images[toIndex(index)];
  if (image.bufferView >= 0) return viewBytes(model, image.bufferView, imageLabel(model, index));
  if (image.image.empty()) refuse(imageLabel(model, index), ": cannot read the image file");
  return Bytes(image.image);
}

enum class ImageFormat { Unknown, Png, Jpeg };

struct ImageHeader {
  ImageFormat format = ImageFormat::Unknown;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
};

std::uint32_t bigEndian(Bytes bytes, std::size_t at, std::size_t count) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < count; ++i) v = v << 8 | bytes[at + i];
  return v;
}

// PNG: an 8-byte signature, then chunks (4-byte big-endian length, type, data, CRC), IHDR first
// (width, height), IEND last. Walking them finds a cut-off file without inflating anything.
ImageHeader inspectPng(Bytes b, const std::string& label) {
  ImageHeader header{ImageFormat::Png};
  for (std::size_t at = 8, index = 0;; ++index) {
    if (b.size() - at < 12 || bigEndian(b, at, 4) > b.size() - at - 12)
      refuse(label, ": PNG data ends before its IEND chunk (the file is cut off)");
    const std::uint32_t length = bigEndian(b, at, 4);
    const std::string_view type(reinterpret_cast<const char*>(&b[at + 4]), 4);
    if (index == 0) {
      if (type != "IHDR" || length != 13) refuse(label, ": PNG does not start with its IHDR chunk");
      header.width = bigEndian(b, at + 8, 4);
      header.height = bigEndian(b, at + 12, 4);
    }
    if (type == "IEND") return header;
    at += 12 + length;
  }
}

// JPEG: after SOI (FF D8), segments of FF, a marker and (but for RSTn and TEM) a 2-byte length
// that counts itself; the frame header (SOF0-SOF15 but DHT, JPG, DAC) holds height, then width.
ImageHeader inspectJpeg(Bytes b, const std::string& label) {
  for (std::size_t at = 2;;) {
    if (b.size() - at < 4) refuse(label, ": JPEG data ends before its frame header (the file is cut off)");
    if (b[at] != 0xFF) refuse(label, ": JPEG segment marker expected at byte ", at);
    const unsigned marker = b[at + 1];
    if (marker == 0xFF) { ++at; continue; }  // fill byte
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) { at += 2; continue; }
    if (marker == 0xD9 || marker == 0xDA) refuse(label, ": JPEG has no frame header before its image data");
    const std::uint32_t length = bigEndian(b, at + 2, 2);
    if (length < 2 || length > b.size() - at - 2) refuse(label, ": JPEG data ends inside a segment (the file is cut off)");
    const bool frame = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (frame) {
      if (length < 8) refuse(label, ": JPEG frame header is too short");
      return {ImageFormat::Jpeg, bigEndian(b, at + 7, 2), bigEndian(b, at + 5, 2)};
    }
    at += 2 + length;
  }
}

// The format and size an image claims, from its first bytes; refuses a PNG or JPEG that is cut
// off. Unknown formats are left to the caller: glTF extensions may bring other formats.
ImageHeader inspectImage(Bytes b, const std::string& label) {
  static constexpr unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (b.size() >= 8 && std::equal(kPng, kPng + 8, b.begin())) return inspectPng(b, label);
  if (b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) return inspectJpeg(b, label);
  return {};
}

// tinygltf asks stb_image for 4 channels of 8 or 16 bits (16-bit samples in host order). Fewer
// channels are expanded all the same (grey → RGB, grey + alpha → RGB + A), should that change.
std::vector<std::uint8_t> toRgba8(const tinygltf::Image& decoded, const std::string& label) {
  const auto channels = static_cast<std::size_t>(decoded.component);
  const std::size_t bytesPerSample = decoded.bits == 16 ? 2 : 1;
  const std::size_t pixels = static_cast<std::size_t>(decoded.width) * static_cast<std::size_t>(decoded.height);
  if (channels < 1 || channels > 4 || (decoded.bits != 8 && decoded.bits != 16) ||
      decoded.image.size() < pixels * channels * bytesPerSample)
    refuse(label, ": decoded to ", channels, " channels of ", decoded.bits, " bits, which lenslab cannot use");
  auto sample = [&](std::size_t pixel, std::size_t channel) -> std::uint8_t {
    const unsigned char* p = &decoded.image[(pixel * channels + channel) * bytesPerSample];
    if (bytesPerSample == 1) return *p;
    std::uint16_t v;
    std::memcpy(&v, p, 2);
    return static_cast<std::uint8_t>((v * 255u + 32767u) / 65535u);
  };
  std::vector<std::uint8_t> rgba(pixels * 4);
  for (std::size_t i = 0; i < pixels; ++i) {
    std::uint8_t* out = &rgba[i * 4];
    const std::uint8_t first = sample(i, 0);
    out[0] = first;
    out[1] = channels >= 3 ? sample(i, 1) : first;
    out[2] = channels >= 3 ? sample(i, 2) : first;
    out[3] = channels == 4 ? sample(i, 3) : channels == 2 ? sample(i, 1) : 255;
  }
  return rgba;
}

TextureImage decodeImage(const tinygltf::Model& model, int index) {
  const std::string label = imageLabel(model, index);
  const Bytes encoded = encodedImage(model, index);
  const ImageHeader header = inspectImage(encoded, label);
  if (header.format == ImageFormat::Unknown) refuse(label, ": neither PNG nor JPEG, the image formats lenslab decodes");
  if (header.width < 1 || header.height < 1 || header.width > kMaxImageSide || header.height > kMaxImageSide ||
      std::uint64_t{header.width} * header.height > kMaxImagePixels)
    refuse(label, ": ", header.width, "x", header.height, " pixels; lenslab decodes up to ", kMaxImageSide, " per side and ",
           kMaxImagePixels, " in all");
  if (encoded.size() > INT_MAX) refuse(label, ": more than 2 GiB of encoded data");
  tinygltf::Image decoded;
  decoded.name = model.images[toIndex(index)].name;
  std::string error, warning;
  if (!tinygltf::LoadImageData(&decoded, index, &error, &warning, 0, 0, encoded.data(), static_cast<int>(encoded.size()), nullptr))
    refuse(label, " could not be decoded: ", oneLine(error));
  TextureImage image;
  image.name = !decoded.name.empty() ? decoded.name : model.images[toIndex(index)].uri.starts_with("data:") ? "" : model.images[toIndex(index)].uri;
  image.width = decoded.width;
  image.height = decoded.height;
  image.rgba8 = toRgba8(decoded, label);
  return image;
}

// ---- the checks that make the rest safe: every reference resolves, every view fits ----

class ModelCheck {
 public:
  ModelCheck(const tinygltf::Model& model, const AccessorReader& reader) : m_(model), reader_(reader) {}

  // Runs every check and returns each node's parent (-1 for roots).
  std::vector<int> run() const {
    asset();
    buffers();
    for (std::size_t i = 0; i < m_.bufferViews.size(); ++i) bufferView(static_cast<int>(i));
    accessors();
    meshes();
    materials();
    samplersAndTextures();
    images();
    for (std::size_t i = 0; i < m_.cameras.size(); ++i) camera(static_cast<int>(i));
    skinsAndAnimations();
    extensionPlacement();
    nodes();
    const std::vector<int> parents = nodeParents();
    scenes(parents);
    return parents;
  }

 private:
  // asset.version is "<major>.<minor>" (digits only); lenslab reads major version 2.
  void asset() const {
    const std::string& version = m_.asset.version;
    const auto dot = version.find('.');
    auto digits = [](std::string_view s) {
      return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    if (dot == std::string::npos || !digits(std::string_view(version).substr(0, dot)) || !digits(std::string_view(version).substr(dot + 1)))
      refuse("asset.version is \"", version, "\"; glTF 2.0 files say \"2.0\"");
    if (version.substr(0, dot) != "2") refuse("asset.version is ", version, "; lenslab reads glTF 2.x");
    const std::string& minimum = m_.asset.minVersion;
    if (!minimum.empty() && minimum != "2.0") refuse("asset.minVersion is ", minimum, "; lenslab reads glTF 2.0");
  }

  void buffers() const {
    for (std::size_t i = 0; i < m_.buffers.size(); ++i)
      if (m_.buffers[i].data.empty()) refuse("buffer ", i, " is empty (byteLength must be at least 1)");
  }

  void bufferView(int i) const {
    const tinygltf::BufferView& view = m_.bufferViews[toIndex(i)];
    if (view.byteLength == 0) refuse("bufferView ", i, ": byteLength is 0; it must be at least 1");
    if (view.byteStride != 0 && (view.byteStride < 4 || view.byteStride > 252 || view.byteStride % 4 != 0))
      refuse("bufferView ", i, ": byteStride ", view.byteStride, " must be a multiple of 4 from 4 to 252");
    (void)viewBytes(m_, i, cat("bufferView ", i));
  }

  // Layout for all; data as well where min/max are declared (the validator reads those too).
  void accessors() const {
    for (std::size_t i = 0; i < m_.accessors.size(); ++i) {
      const tinygltf::Accessor& a = m_.accessors[i];
      reader_.checkLayout(static_cast<int>(i));
      if (!a.minValues.empty() || !a.maxValues.empty() || a.sparse.isSparse) (void)reader_.read(static_cast<int>(i));
    }
  }

  void meshes() const {
    for (std::size_t i = 0; i < m_.meshes.size(); ++i)
      for (std::size_t k = 0; k < m_.meshes[i].primitives.size(); ++k) primitive(m_.meshes[i].primitives[k], cat("mesh ", i, " primitive ", k));
  }

  void primitive(const tinygltf::Primitive& p, const std::string& where) const {
    if (p.mode < -1 || p.mode > TINYGLTF_MODE_TRIANGLE_FAN) refuse(where, ": mode ", p.mode, " is not a glTF primitive mode (0 to 6)");
    if (p.indices != -1) requireIndex(p.indices, m_.accessors.size(), cat(where, " indices"), "accessor");
    if (p.material != -1) requireIndex(p.material, m_.materials.size(), where, "material");
    std::optional<std::size_t> count;
    for (const auto& [name, accessor] : p.attributes) {
      requireIndex(accessor, m_.accessors.size(), cat(where, " attribute ", name), "accessor");
      const std::size_t n = m_.accessors[toIndex(accessor)].count;
      if (count && *count != n) refuse(where, ": attribute ", name, " has ", n, " elements, another has ", *count, "; all must have the same count");
      count = n;
    }
    for (const auto& target : p.targets)
      for (const auto& [name, accessor] : target) requireIndex(accessor, m_.accessors.size(), cat(where, " morph target ", name), "accessor");
  }

  void materials() const {
    for (std::size_t i = 0; i < m_.materials.size(); ++i) {
      const tinygltf::Material& m = m_.materials[i];
      const std::string where = cat("material ", i, m.name.empty() ? "" : cat(" \"", m.name, "\""));
      const std::vector<double>& f = m.pbrMetallicRoughness.baseColorFactor;
      if (f.size() != 4) refuse(where, ": baseColorFactor has ", f.size(), " numbers; it needs 4 (RGBA)");
      for (std::size_t c = 0; c < 4; ++c)
        if (!(f[c] >= 0.0 && f[c] <= 1.0)) refuse(where, ": baseColorFactor[", c, "] is ", f[c], "; each must be within [0, 1]");
      if (m.alphaMode != "OPAQUE" && m.alphaMode != "MASK" && m.alphaMode != "BLEND")
        refuse(where, ": alphaMode \"", m.alphaMode, "\" must be OPAQUE, MASK or BLEND");
      if (!(m.alphaCutoff >= 0.0) || !std::isfinite(m.alphaCutoff)) refuse(where, ": alphaCutoff ", m.alphaCutoff, " must be a finite number >= 0");
      const std::pair<const char*, int> textures[] = {
          {"baseColorTexture", m.pbrMetallicRoughness.baseColorTexture.index},
          {"metallicRoughnessTexture", m.pbrMetallicRoughness.metallicRoughnessTexture.index},
          {"normalTexture", m.normalTexture.index},
          {"occlusionTexture", m.occlusionTexture.index},
          {"emissiveTexture", m.emissiveTexture.index}};
      for (const auto& [name, index] : textures)
        if (index != -1) requireIndex(index, m_.textures.size(), cat(where, " ", name), "texture");
    }
  }

  void samplersAndTextures() const {
    auto oneOf = [](int v, std::initializer_list<int> valid) { return std::find(valid.begin(), valid.end(), v) != valid.end(); };
    for (std::size_t i = 0; i < m_.samplers.size(); ++i) {
      const tinygltf::Sampler& s = m_.samplers[i];
      for (const int wrap : {s.wrapS, s.wrapT})
        if (!oneOf(wrap, {10497, 33071, 33648}))
          refuse("sampler ", i, ": wrap mode ", wrap, " must be 10497 (REPEAT), 33071 (CLAMP_TO_EDGE) or 33648 (MIRRORED_REPEAT)");
      if (!oneOf(s.magFilter, {-1, 9728, 9729})) refuse("sampler ", i, ": magFilter ", s.magFilter, " must be 9728 (NEAREST) or 9729 (LINEAR)");
      if (!oneOf(s.minFilter, {-1, 9728, 9729, 9984, 9985, 9986, 9987}))
        refuse("sampler ", i, ": minFilter ", s.minFilter, " must be 9728, 9729 or 9984 to 9987 (NEAREST, LINEAR, *_MIPMAP_*)");
    }
    for (std::size_t i = 0; i < m_.textures.size(); ++i) {
      const tinygltf::Texture& t = m_.textures[i];
      if (t.source != -1) requireIndex(t.source, m_.images.size(), cat("texture ", i, " source"), "image");
      if (t.sampler != -1) requireIndex(t.sampler, m_.samplers.size(), cat("texture ", i), "sampler");
    }
  }

  // Every image must be readable and, when PNG or JPEG, whole; only used ones are decoded.
  void images() const {
    for (std::size_t i = 0; i < m_.images.size(); ++i) {
      const int index = static_cast<int>(i);
      (void)inspectImage(encodedImage(m_, index), imageLabel(m_, index));
    }
  }

  void camera(int index) const {
    const tinygltf::Camera& c = m_.cameras[toIndex(index)];
    const std::string where = cat("camera ", index, c.name.empty() ? "" : cat(" \"", c.name, "\""));
    auto positive = [&](double v, const char* field) {
      if (!std::isfinite(v) || !(v > 0.0)) refuse(where, ": ", field, " is ", v, "; it must be a positive finite number");
    };
    if (c.type == "perspective") {
      const tinygltf::PerspectiveCamera& p = c.perspective;
      positive(p.yfov, "yfov");
      if (p.yfov >= std::numbers::pi) refuse(where, ": yfov is ", p.yfov, "; it must be below pi (radians)");
      positive(p.znear, "znear");
      if (p.aspectRatio != 0.0) positive(p.aspectRatio, "aspectRatio");  // tinygltf: 0 = absent
      if (p.zfar != 0.0) {                                                // tinygltf: 0 = absent (infinite)
        positive(p.zfar, "zfar");
        if (p.zfar <= p.znear) refuse(where, ": zfar ", p.zfar, " must be greater than znear ", p.znear);
      }
    } else if (c.type == "orthographic") {
      const tinygltf::OrthographicCamera& o = c.orthographic;
      positive(o.xmag, "xmag");
      positive(o.ymag, "ymag");
      positive(o.zfar, "zfar");
      if (!std::isfinite(o.znear) || o.znear < 0.0) refuse(where, ": znear is ", o.znear, "; it must be a finite number >= 0");
      if (o.zfar <= o.znear) refuse(where, ": zfar ", o.zfar, " must be greater than znear ", o.znear);
    } else {
      refuse(where, ": type \"", c.type, "\" must be \"perspective\" or \"orthographic\"");
    }
  }

  void skinsAndAnimations() const {
    for (std::size_t i = 0; i < m_.skins.size(); ++i) {
      const tinygltf::Skin& s = m_.skins[i];
      for (const int joint : s.joints) requireIndex(joint, m_.nodes.size(), cat("skin ", i, " joints"), "node");
      if (s.skeleton != -1) requireIndex(s.skeleton, m_.nodes.size(), cat("skin ", i, " skeleton"), "node");
      if (s.inverseBindMatrices != -1) requireIndex(s.inverseBindMatrices, m_.accessors.size(), cat("skin ", i, " inverseBindMatrices"), "accessor");
    }
    for (std::size_t i = 0; i < m_.animations.size(); ++i) {
      const tinygltf::Animation& a = m_.animations[i];
      for (std::size_t s = 0; s < a.samplers.size(); ++s) {
        requireIndex(a.samplers[s].input, m_.accessors.size(), cat("animation ", i, " sampler ", s, " input"), "accessor");
        requireIndex(a.samplers[s].output, m_.accessors.size(), cat("animation ", i, " sampler ", s, " output"), "accessor");
      }
      for (std::size_t c = 0; c < a.channels.size(); ++c) {
        const tinygltf::AnimationChannel& channel = a.channels[c];
        const std::string where = cat("animation ", i, " channel ", c);
        requireIndex(channel.sampler, a.samplers.size(), where, "sampler");
        requireIndex(channel.target_node, m_.nodes.size(), cat(where, " target"), "node");
        animationCounts(a.samplers[toIndex(channel.sampler)], channel, where);
      }
    }
  }

  // An animation output holds one value per key time (three for cubic splines), times the number
  // of morph targets when it drives weights. Animations are not played, but a file that gets this
  // wrong is not to be trusted.
  void animationCounts(const tinygltf::AnimationSampler& s, const tinygltf::AnimationChannel& channel, const std::string& where) const {
    const std::size_t times = m_.accessors[toIndex(s.input)].count;
    std::size_t perTime = s.interpolation == "CUBICSPLINE" ? 3 : 1;
    if (channel.target_path == "weights") {
      const tinygltf::Node& node = m_.nodes[toIndex(channel.target_node)];
      if (node.mesh < 0 || toIndex(node.mesh) >= m_.meshes.size() || m_.meshes[toIndex(node.mesh)].primitives.empty()) return;
      perTime *= m_.meshes[toIndex(node.mesh)].primitives[0].targets.size();
    }
    const std::size_t values = m_.accessors[toIndex(s.output)].count;
    if (values != times * perTime) refuse(where, ": its output holds ", values, " values but ", times, " key times need ", times * perTime);
  }

  // The extensions lenslab reads must sit where they belong (the validator's
  // UNEXPECTED_EXTENSION_OBJECT): unlit on a material, texture transforms on a texture reference.
  void extensionPlacement() const {
    auto check = [](const tinygltf::ExtensionMap& extensions, const std::string& where) {
      if (extensions.count("KHR_materials_unlit")) refuse(where, " carries KHR_materials_unlit, which belongs on a material");
      if (extensions.count("KHR_texture_transform"))
        refuse(where, " carries KHR_texture_transform, which belongs on a texture reference (textureInfo)");
    };
    for (std::size_t i = 0; i < m_.samplers.size(); ++i) check(m_.samplers[i].extensions, cat("sampler ", i));
    for (std::size_t i = 0; i < m_.textures.size(); ++i) check(m_.textures[i].extensions, cat("texture ", i));
    for (std::size_t i = 0; i < m_.images.size(); ++i) check(m_.images[i].extensions, cat("image ", i));
    for (std::size_t i = 0; i < m_.nodes.size(); ++i) check(m_.nodes[i].extensions, cat("node ", i));
    for (std::size_t i = 0; i < m_.meshes.size(); ++i) check(m_.meshes[i].extensions, cat("mesh ", i));
    for (std::size_t i = 0; i < m_.buffers.size(); ++i) check(m_.buffers[i].extensions, cat("buffer ", i));
    for (std::size_t i = 0; i < m_.cameras.size(); ++i) check(m_.cameras[i].extensions, cat("camera ", i));
    for (std::size_t i = 0; i < m_.materials.size(); ++i)
      if (m_.materials[i].extensions.count("KHR_texture_transform"))
        refuse("material ", i, " carries KHR_texture_transform, which belongs on a texture reference (textureInfo)");
  }

  // glTF: "node hierarchy MUST be a set of disjoint strict trees": one parent at most, no loops.
  // This is what lets the scene walk visit each node once, however the file is drawn.
  std::vector<int> nodeParents() const {
    std::vector<int> parent(m_.nodes.size(), -1);
    for (std::size_t i = 0; i < m_.nodes.size(); ++i)
      for (const int child : m_.nodes[i].children) {
        requireIndex(child, m_.nodes.size(), cat("node ", i, " children"), "node");
        if (toIndex(child) == i) refuse("node ", i, " lists itself as a child: the node hierarchy has a loop");
        if (parent[toIndex(child)] != -1)
          refuse("node ", child, " is a child of both node ", parent[toIndex(child)], " and node ", i, "; a glTF node has at most one parent");
        parent[toIndex(child)] = static_cast<int>(i);
      }
    // With one parent each, walking up from any node reaches a root or goes round a loop.
    enum : char { kUnseen, kOnPath, kDone };
    std::vector<char> state(m_.nodes.size(), kUnseen);
    for (std::size_t start = 0; start < m_.nodes.size(); ++start) {
      std::vector<int> path;
      int node = static_cast<int>(start);
      while (node != -1 && state[toIndex(node)] == kUnseen) {
        state[toIndex(node)] = kOnPath;
        path.push_back(node);
        node = parent[toIndex(node)];
      }
      if (node != -1 && state[toIndex(node)] == kOnPath)
        refuse("node ", node, " is its own ancestor: the node hierarchy has a loop");
      for (const int n : path) state[toIndex(n)] = kDone;
    }
    return parent;
  }

  void nodes() const {
    for (std::size_t i = 0; i < m_.nodes.size(); ++i) {
      const tinygltf::Node& n = m_.nodes[i];
      const std::string where = cat("node ", i);
      if (n.mesh != -1) requireIndex(n.mesh, m_.meshes.size(), where, "mesh");
      if (n.camera != -1) requireIndex(n.camera, m_.cameras.size(), where, "camera");
      if (n.skin != -1) requireIndex(n.skin, m_.skins.size(), where, "skin");
      const std::pair<const char*, const std::vector<double>*> fields[] = {
          {"matrix", &n.matrix}, {"translation", &n.translation}, {"rotation", &n.rotation}, {"scale", &n.scale}};
      const std::size_t sizes[] = {16, 3, 4, 3};
      for (std::size_t f = 0; f < 4; ++f) {
        const std::vector<double>& v = *fields[f].second;
        if (!v.empty() && v.size() != sizes[f]) refuse(where, ": ", fields[f].first, " has ", v.size(), " numbers; it needs ", sizes[f]);
        for (const double x : v)
          if (!std::isfinite(x)) refuse(where, ": ", fields[f].first, " holds a number that is not finite");
      }
      if (n.rotation.size() == 4 && std::hypot(n.rotation[0], n.rotation[1], n.rotation[2]) == 0.0 && n.rotation[3] == 0.0)
        refuse(where, ": rotation (0, 0, 0, 0) is not a unit quaternion");
    }
  }

  void scenes(const std::vector<int>& parents) const {
    for (std::size_t s = 0; s < m_.scenes.size(); ++s) {
      std::vector<int> seen;
      for (const int n : m_.scenes[s].nodes) {
        requireIndex(n, m_.nodes.size(), cat("scene ", s), "node");
        if (parents[toIndex(n)] != -1)
          refuse("scene ", s, " lists node ", n, ", a child of node ", parents[toIndex(n)], "; a scene lists root nodes only");
        if (std::find(seen.begin(), seen.end(), n) != seen.end()) refuse("scene ", s, " lists node ", n, " twice");
        seen.push_back(n);
      }
    }
    if (m_.defaultScene != -1) requireIndex(m_.defaultScene, m_.scenes.size(), "\"scene\" (the default scene)", "scene");
  }

  const tinygltf::Model& m_;
  const AccessorReader& reader_;
};

// ---- primitives → meshes ----

bool drawsTriangles(int mode) {
  return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

// glTF 2.0, "Topology types": strip triangle i is (i, i+1, i+2) for even i and (i, i+2, i+1)
// for odd i, so that all keep the first one's winding; fan triangle i is (i+1, i+2, 0).
std::vector<std::uint32_t> triangleList(int mode, const std::vector<std::uint32_t>& order) {
  std::vector<std::uint32_t> out;
  const std::size_t n = order.size();
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    out.assign(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n / 3 * 3));
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (std::size_t i = 0; i + 2 < n; ++i) {
      if (i % 2 == 0) out.insert(out.end(), {order[i], order[i + 1], order[i + 2]});
      else out.insert(out.end(), {order[i], order[i + 2], order[i + 1]});
    }
  } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
    for (std::size_t i = 0; i + 2 < n; ++i) out.insert(out.end(), {order[i + 1], order[i + 2], order[0]});
  }
  return out;
}

// glTF: "When normals are not specified, client implementations MUST calculate flat normals":
// every triangle gets three vertices of its own that carry its face normal.
void makeFlatNormals(Mesh& mesh) {
  std::vector<Vertex> vertices;
  vertices.reserve(mesh.indices.size());
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    Vertex a = mesh.vertices[mesh.indices[t]], b = mesh.vertices[mesh.indices[t + 1]], c = mesh.vertices[mesh.indices[t + 2]];
    const glm::dvec3 cross = glm::cross(glm::dvec3(b.position - a.position), glm::dvec3(c.position - a.position));
    const double length = glm::length(cross);
    const glm::vec3 normal = length > 0.0 && std::isfinite(length) ? glm::vec3(cross / length) : glm::vec3(0, 0, 1);
    a.normal = b.normal = c.normal = normal;
    vertices.insert(vertices.end(), {a, b, c});
  }
  mesh.vertices = std::move(vertices);
  for (std::size_t i = 0; i < mesh.indices.size(); ++i) mesh.indices[i] = static_cast<std::uint32_t>(i);
}

// The formats glTF 2.0 allows for the attributes lenslab reads ("Meshes", attribute table).
struct AttributeFormat {
  std::vector<int> types;
  bool normalizedIntegers = false;  // also normalized UNSIGNED_BYTE / UNSIGNED_SHORT
  const char* valid = "";
};

const AttributeFormat kPositionFormat{{TINYGLTF_TYPE_VEC3}, false, "VEC3 FLOAT"};
const AttributeFormat kNormalFormat{{TINYGLTF_TYPE_VEC3}, false, "VEC3 FLOAT"};
const AttributeFormat kTexcoordFormat{{TINYGLTF_TYPE_VEC2}, true, "VEC2 of FLOAT or of normalized UNSIGNED_BYTE/UNSIGNED_SHORT"};
const AttributeFormat kColorFormat{{TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, true,
                                   "VEC3/VEC4 of FLOAT or of normalized UNSIGNED_BYTE/UNSIGNED_SHORT"};

class PrimitiveConverter {
 public:
  PrimitiveConverter(const tinygltf::Model& model, const AccessorReader& reader, std::vector<std::string>& notes)
      : model_(model), reader_(reader), notes_(notes) {}

  // The primitive as a triangle mesh (material not yet assigned), or nothing where lenslab does
  // not draw it (points, lines, no POSITION, no whole triangle). Refuses malformed data.
  std::optional<Mesh> convert(int meshIndex, std::size_t k) const {
    const tinygltf::Mesh& gltfMesh = model_.meshes[toIndex(meshIndex)];
    const tinygltf::Primitive& p = gltfMesh.primitives[k];
    const std::string where = cat("mesh ", meshIndex, " primitive ", k);
    const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
    if (!drawsTriangles(mode)) {
      noteOnce(notes_, "points and lines are not drawn (lenslab draws triangles)");
      return std::nullopt;
    }
    if (!p.attributes.count("POSITION")) {
      noteOnce(notes_, cat(where, " has no POSITION and is not drawn"));
      return std::nullopt;
    }
    if (!p.targets.empty()) noteOnce(notes_, "morph targets are ignored: meshes are drawn without them");

    Mesh mesh;
    mesh.name = gltfMesh.name.empty() ? cat("mesh", meshIndex) : gltfMesh.name;
    if (gltfMesh.primitives.size() > 1) mesh.name += cat("#", k);
    const std::size_t vertexCount = readVertices(p, where, mesh);
    const std::vector<std::uint32_t> order = vertexOrder(p, vertexCount, where);
    if (mode == TINYGLTF_MODE_TRIANGLES && order.size() % 3 != 0)
      noteOnce(notes_, cat(where, ": ", order.size(), " vertices are not whole triangles; the last ", order.size() % 3, " are left out"));
    mesh.indices = triangleList(mode, order);
    if (mesh.indices.empty()) {
      noteOnce(notes_, cat(where, " has no whole triangle and is not drawn"));
      return std::nullopt;
    }
    if (!p.attributes.count("NORMAL")) makeFlatNormals(mesh);
    return mesh;
  }

 private:
  // POSITION, NORMAL, TEXCOORD_0 and COLOR_0 into mesh.vertices; returns the vertex count.
  std::size_t readVertices(const tinygltf::Primitive& p, const std::string& where, Mesh& mesh) const {
    const Elements positions = *readAttribute(p, "POSITION", kPositionFormat, std::nullopt, where);
    const std::size_t n = positions.count;
    mesh.vertices.resize(n);
    for (std::size_t i = 0; i < n; ++i) mesh.vertices[i].position = glm::vec3(positions.at(i, 0), positions.at(i, 1), positions.at(i, 2));
    if (const auto normals = readAttribute(p, "NORMAL", kNormalFormat, n, where)) {
      for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 v(normals->at(i, 0), normals->at(i, 1), normals->at(i, 2));
        const double length = glm::length(v);
        if (length == 0.0) noteOnce(notes_, cat(where, " has zero-length normals; they are drawn as +Z"));
        mesh.vertices[i].normal = length > 0.0 ? glm::vec3(v / length) : glm::vec3(0, 0, 1);
      }
    }
    if (const auto uvs = readAttribute(p, "TEXCOORD_0", kTexcoordFormat, n, where))
      for (std::size_t i = 0; i < n; ++i) mesh.vertices[i].uv = glm::vec2(uvs->at(i, 0), uvs->at(i, 1));
    if (const auto colors = readAttribute(p, "COLOR_0", kColorFormat, n, where)) {
      for (std::size_t i = 0; i < n; ++i)
        mesh.vertices[i].color = glm::vec4(colors->at(i, 0), colors->at(i, 1), colors->at(i, 2), colors->components == 4 ? colors->at(i, 3) : 1.0);
      mesh.hasVertexColors = true;
    }
    return n;
  }

  // An attribute in one of its allowed formats, every value finite; nothing when absent.
  std::optional<Elements> readAttribute(const tinygltf::Primitive& p, const char* name, const AttributeFormat& format,
                                        std::optional<std::size_t> vertexCount, const std::string& where) const {
    const auto found = p.attributes.find(name);
    if (found == p.attributes.end()) return std::nullopt;
    const tinygltf::Accessor& a = model_.accessors[toIndex(found->second)];
    const std::string what = cat(where, " ", name, " (accessor ", found->second, ")");
    const bool isFloat = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT && !a.normalized;
    const bool isNormalizedInteger = format.normalizedIntegers && a.normalized &&
                                     (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                      a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    if (std::find(format.types.begin(), format.types.end(), a.type) == format.types.end() || !(isFloat || isNormalizedInteger))
      refuse(what, " is ", typeName(a.type), " of ", a.normalized ? "normalized " : "", componentTypeName(a.componentType),
             "; it must be ", format.valid);
    Elements e = reader_.read(found->second);
    if (vertexCount && e.count != *vertexCount) refuse(what, " has ", e.count, " elements but POSITION has ", *vertexCount);
    for (std::size_t i = 0; i < e.values.size(); ++i)
      if (!std::isfinite(e.values[i])) refuse(what, ": element ", i / e.components, " is not a finite number");
    return e;
  }

  // The primitive's vertex order: its indices, each checked against the vertex count, or 0..n-1.
  std::vector<std::uint32_t> vertexOrder(const tinygltf::Primitive& p, std::size_t vertexCount, const std::string& where) const {
    std::vector<std::uint32_t> order;
    if (p.indices < 0) {
      if (vertexCount > UINT32_MAX) refuse(where, ": ", vertexCount, " vertices are more than 32-bit indices reach");
      order.resize(vertexCount);
      for (std::size_t i = 0; i < vertexCount; ++i) order[i] = static_cast<std::uint32_t>(i);
      return order;
    }
    const tinygltf::Accessor& a = model_.accessors[toIndex(p.indices)];
    if (a.type != TINYGLTF_TYPE_SCALAR || !isUnsignedIndexType(a.componentType) || a.normalized)
      refuse(where, " indices (accessor ", p.indices, ") are ", a.normalized ? "normalized " : "", typeName(a.type), " of ",
             componentTypeName(a.componentType), "; they must be SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    const Elements e = reader_.read(p.indices);
    order.reserve(e.count);
    for (std::size_t i = 0; i < e.count; ++i) {
      const double v = e.values[i];
      if (v >= static_cast<double>(vertexCount))
        refuse(where, " indices (accessor ", p.indices, "): element ", i, " is ", v, ", not below the vertex count ", vertexCount);
      order.push_back(static_cast<std::uint32_t>(v));
    }
    return order;
  }

  const tinygltf::Model& model_;
  const AccessorReader& reader_;
  std::vector<std::string>& notes_;
};

// ---- the drawn scene ----

// A node's transform: its matrix (column-major, as GLM stores it) or T * R * S.
glm::dmat4 localTransform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());
  glm::dmat4 m(1.0);
  if (node.translation.size() == 3) m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
  if (node.rotation.size() == 4) {
    const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);  // GLM: w first
    m = m * glm::mat4_cast(glm::normalize(q));  // writers round their quaternions; rotate, never shear
  }
  if (node.scale.size() == 3)
    m = m * glm::dmat4(glm::dvec4(node.scale[0], 0, 0, 0), glm::dvec4(0, node.scale[1], 0, 0), glm::dvec4(0, 0, node.scale[2], 0),
                       glm::dvec4(0, 0, 0, 1));
  return m;
}

Sampler convertSampler(const tinygltf::Sampler& s) {
  Sampler sampler;  // Scene.h's defaults stand where the file leaves a filter undefined
  sampler.wrapS = static_cast<Wrap>(s.wrapS);
  sampler.wrapT = static_cast<Wrap>(s.wrapT);
  if (s.magFilter != -1) sampler.magFilter = static_cast<Filter>(s.magFilter);
  if (s.minFilter != -1) sampler.minFilter = static_cast<Filter>(s.minFilter);
  return sampler;
}

// Walks the default scene's node trees and fills the Scene with what they draw; meshes,
// materials, textures and images are added when first used, so indices come out compact.
class SceneBuilder {
 public:
  SceneBuilder(const tinygltf::Model& model, const AccessorReader& reader, const std::vector<int>& parents, Scene& scene)
      : model_(model), reader_(reader), parents_(parents), scene_(scene), converter_(model, reader, scene.notes) {}

  void build() {
    placeNodes(drawnRoots());
    checkUndrawnMeshes();
    noteIgnoredFeatures();
  }

 private:
  // The `scene` index, else scene 0, else every root node.
  std::vector<int> drawnRoots() {
    if (model_.scenes.empty()) {
      std::vector<int> roots;
      for (std::size_t i = 0; i < parents_.size(); ++i)
        if (parents_[i] == -1) roots.push_back(static_cast<int>(i));
      if (!roots.empty()) noteOnce(scene_.notes, "the file has no scenes: all root nodes are drawn");
      return roots;
    }
    const int index = model_.defaultScene >= 0 ? model_.defaultScene : 0;
    if (model_.scenes.size() > 1)
      noteOnce(scene_.notes, cat("the file has ", model_.scenes.size(), " scenes; scene ", index,
                                 model_.defaultScene >= 0 ? " (its default)" : " (the first: no default is given)", " is drawn"));
    return model_.scenes[toIndex(index)].nodes;
  }

  // Depth first, without recursion (a hierarchy may be deeper than the stack): the checks made
  // it a forest, so each node is met once.
  void placeNodes(const std::vector<int>& roots) {
    std::vector<std::pair<int, glm::dmat4>> pending;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) pending.emplace_back(*it, glm::dmat4(1.0));
    while (!pending.empty()) {
      const auto [index, worldFromParent] = pending.back();
      pending.pop_back();
      const tinygltf::Node& node = model_.nodes[toIndex(index)];
      const glm::dmat4 worldFromNode = worldFromParent * localTransform(node);
      for (int i = 0; i < 16; ++i)
        if (!std::isfinite(glm::value_ptr(worldFromNode)[i])) refuse("node ", index, ": its world transform is not finite");
      placeNode(node, worldFromNode);
      for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) pending.emplace_back(*it, worldFromNode);
    }
  }

  void placeNode(const tinygltf::Node& node, const glm::dmat4& worldFromNode) {
    if (node.mesh >= 0) {
      const std::size_t primitives = model_.meshes[toIndex(node.mesh)].primitives.size();
      for (std::size_t k = 0; k < primitives; ++k)
        if (const int mesh = meshFor(node.mesh, k); mesh >= 0) scene_.instances.push_back({mesh, worldFromNode});
    }
    if (node.camera >= 0) addCamera(node.camera, worldFromNode);
    if (node.skin >= 0) noteOnce(scene_.notes, "skins are ignored: skinned meshes are drawn in their bind pose");
  }

  // The Scene mesh of a glTF primitive, converted on first use; -1 where nothing is drawn.
  int meshFor(int meshIndex, std::size_t k) {
    const auto key = std::make_pair(meshIndex, k);
    if (const auto found = meshes_.find(key); found != meshes_.end()) return found->second;
    int index = -1;
    if (std::optional<Mesh> mesh = converter_.convert(meshIndex, k)) {
      const int material = model_.meshes[toIndex(meshIndex)].primitives[k].material;
      mesh->material = material >= 0 ? materialFor(material) : -1;  // -1: glTF's default material
      scene_.meshes.push_back(std::move(*mesh));
      index = static_cast<int>(scene_.meshes.size()) - 1;
    }
    meshes_.emplace(key, index);
    return index;
  }

  int materialFor(int gltfIndex) {
    if (const auto found = materials_.find(gltfIndex); found != materials_.end()) return found->second;
    const tinygltf::Material& m = model_.materials[toIndex(gltfIndex)];
    Material material;
    material.name = m.name;
    const std::vector<double>& f = m.pbrMetallicRoughness.baseColorFactor;
    material.baseColorFactor = glm::vec4(f[0], f[1], f[2], f[3]);
    material.unlit = m.extensions.count("KHR_materials_unlit") > 0;
    material.alphaMode = m.alphaMode == "MASK" ? AlphaMode::Mask : m.alphaMode == "BLEND" ? AlphaMode::Blend : AlphaMode::Opaque;
    if (material.alphaMode == AlphaMode::Blend) noteOnce(scene_.notes, "alphaMode BLEND is drawn opaque (lenslab sorts no transparency)");
    material.alphaCutoff = static_cast<float>(m.alphaCutoff);
    material.doubleSided = m.doubleSided;
    const tinygltf::TextureInfo& base = m.pbrMetallicRoughness.baseColorTexture;
    if (base.index >= 0 && base.texCoord != 0)
      noteOnce(scene_.notes, cat("material ", gltfIndex, " samples its base colour texture with TEXCOORD_", base.texCoord,
                                 "; lenslab reads TEXCOORD_0 only, so that texture is left out"));
    else if (base.index >= 0)
      material.baseColorTexture = textureFor(base.index);
    if (m.normalTexture.index >= 0 || m.occlusionTexture.index >= 0 || m.emissiveTexture.index >= 0 ||
        m.pbrMetallicRoughness.metallicRoughnessTexture.index >= 0)
      noteOnce(scene_.notes, "normal, occlusion, emissive and metallic-roughness inputs are ignored (lenslab shades base colour x Lambert)");
    scene_.materials.push_back(std::move(material));
    return materials_[gltfIndex] = static_cast<int>(scene_.materials.size()) - 1;
  }

  int textureFor(int gltfIndex) {
    if (const auto found = textures_.find(gltfIndex); found != textures_.end()) return found->second;
    const tinygltf::Texture& t = model_.textures[toIndex(gltfIndex)];
    if (t.source < 0) refuse("texture ", gltfIndex, " has no source image (lenslab reads PNG and JPEG through \"source\")");
    Texture texture;
    texture.image = imageFor(t.source);
    if (t.sampler >= 0) texture.sampler = convertSampler(model_.samplers[toIndex(t.sampler)]);
    scene_.textures.push_back(texture);
    return textures_[gltfIndex] = static_cast<int>(scene_.textures.size()) - 1;
  }

  int imageFor(int gltfIndex) {
    if (const auto found = images_.find(gltfIndex); found != images_.end()) return found->second;
    scene_.images.push_back(decodeImage(model_, gltfIndex));
    return images_[gltfIndex] = static_cast<int>(scene_.images.size()) - 1;
  }

  void addCamera(int index, const glm::dmat4& worldFromCamera) {
    const tinygltf::Camera& c = model_.cameras[toIndex(index)];  // values checked by ModelCheck
    SceneCamera camera;
    camera.name = c.name;
    camera.worldFromCamera = worldFromCamera;
    camera.perspective = c.type == "perspective";
    if (camera.perspective) {
      camera.yfovRadians = c.perspective.yfov;
      camera.aspectRatio = c.perspective.aspectRatio;
      camera.znear = c.perspective.znear;
      if (c.perspective.zfar != 0.0) camera.zfar = c.perspective.zfar;
    } else {
      camera.xmag = c.orthographic.xmag;
      camera.ymag = c.orthographic.ymag;
      camera.znear = c.orthographic.znear;
      camera.zfar = c.orthographic.zfar;
    }
    scene_.cameras.push_back(camera);
  }

  // Primitives the drawn scene does not reach are converted too, and dropped, so that a broken
  // file is refused whichever of its scenes it would draw. Their notes are not the scene's.
  void checkUndrawnMeshes() {
    std::vector<std::string> ignoredNotes;
    const PrimitiveConverter quiet(model_, reader_, ignoredNotes);
    for (std::size_t i = 0; i < model_.meshes.size(); ++i)
      for (std::size_t k = 0; k < model_.meshes[i].primitives.size(); ++k)
        if (!meshes_.count({static_cast<int>(i), k})) (void)quiet.convert(static_cast<int>(i), k);
  }

  void noteIgnoredFeatures() {
    if (!model_.animations.empty())
      noteOnce(scene_.notes, cat(model_.animations.size(), " animation(s) ignored: the scene is drawn at rest"));
    for (const std::string& used : model_.extensionsUsed)
      if (std::find(kSupportedExtensions.begin(), kSupportedExtensions.end(), used) == kSupportedExtensions.end())
        noteOnce(scene_.notes, cat("extension ", used, " is used but not supported by lenslab; it is ignored"));
  }

  const tinygltf::Model& model_;
  const AccessorReader& reader_;
  const std::vector<int>& parents_;
  Scene& scene_;
  PrimitiveConverter converter_;
  std::map<std::pair<int, std::size_t>, int> meshes_;
  std::map<int, int> materials_, textures_, images_;
};

Scene load(const fs::path& file) {
  const std::string bytes = readFile(file);
  const bool binary = startsWithGlbMagic(bytes);
  if (!binary && file.extension() == ".glb")
    refuse(bytes.empty() ? "the file is empty" : "not a binary glTF", ": a .glb starts with the magic \"glTF\"");
  std::string glb;
  std::string_view jsonText = bytes;
  if (binary) {
    const GlbChunks chunks = splitGlb(bytes);
    jsonText = chunks.json;
    glb = glbForTinygltf(chunks, bytes.size());
  }
  precheckJson(parseJson(jsonText), binary);
  const tinygltf::Model model = parseModel(glb.empty() ? std::string_view(bytes) : std::string_view(glb), binary, file.parent_path());
  const AccessorReader reader(model);
  const std::vector<int> parents = ModelCheck(model, reader).run();
  Scene scene;
  scene.source = file.string();
  SceneBuilder(model, reader, parents, scene).build();
  scene.bounds = computeBounds(scene);
  return scene;
}

}  // namespace

Scene loadGltf(const fs::path& file) {
  try {
    return load(file);
  } catch (const Problem& problem) {
    throw InputError(cat(file.string(), ": ", oneLine(problem.what())));
  } catch (const std::bad_alloc&) {
    throw InputError(cat(file.string(), ": not enough memory to load it"));
  }
}

}  // namespace lenslab
