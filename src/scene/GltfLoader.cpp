#include "scene/GltfLoader.h"

#include "core/Error.h"
#include "core/Text.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstring>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <regex>
#include <set>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

constexpr int kMaxNodeDepth = 1024;

const std::set<std::string> kSupportedRequiredExtensions = {"KHR_materials_unlit"};

std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

std::size_t componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

int componentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

// One component of one element, as a double; normalised integers map to [0, 1] or [−1, 1].
double readComponent(const unsigned char* p, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: { float v; std::memcpy(&v, p, 4); return v; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: { const double v = p[0]; return normalized ? v / 255.0 : v; }
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const double v = static_cast<std::int8_t>(p[0]);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t v; std::memcpy(&v, p, 2);
      return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      std::int16_t v; std::memcpy(&v, p, 2);
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      std::uint32_t v; std::memcpy(&v, p, 4);
      return normalized ? v / 4294967295.0 : v;
    }
    default: return 0.0;
  }
}

class Loader {
 public:
  explicit Loader(fs::path file) : file_(std::move(file)) {}

  Scene load() {
    parse();
    checkAsset();
    checkExtensions();
    checkReferences();
    scene_.source = file_.string();
    const std::vector<int> roots = rootNodes();
    std::vector<int> stack;
    for (int root : roots) visitNode(root, glm::dmat4(1.0), stack);
    checkUndrawnData();
    noteIgnoredFeatures();
    scene_.bounds = computeBounds(scene_);
    return std::move(scene_);
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(oneLine(cat(file_.string(), ": ", message)));
  }

  void note(const std::string& message) {
    if (std::find(scene_.notes.begin(), scene_.notes.end(), message) == scene_.notes.end())
      scene_.notes.push_back(message);
  }

  // ---- parsing ----

  void parse() {
    std::ifstream in(file_, std::ios::binary);
    if (!in) fail(cat("cannot read the scene file (", fs::exists(file_) ? "permission denied" : "no such file", ")"));
    char head[4] = {0, 0, 0, 0};
    in.read(head, 4);
    const std::streamsize got = in.gcount();
    in.close();
    const bool binary = got == 4 && std::string(head, 4) == "glTF";
    if (got >= 3 && static_cast<unsigned char>(head[0]) == 0xEF && static_cast<unsigned char>(head[1]) == 0xBB &&
        static_cast<unsigned char>(head[2]) == 0xBF)
      fail("starts with a UTF-8 byte-order mark, which glTF forbids (JSON must begin with '{')");
    if (!binary && file_.extension() == ".glb")
      fail("is not a binary glTF: its first four bytes are not the magic 'glTF'");

    precheck(binary);
    tinygltf::TinyGLTF gltf;
    std::string error, warning;
    const bool ok = binary ? gltf.LoadBinaryFromFile(&model_, &error, &warning, file_.string())
                           : gltf.LoadASCIIFromFile(&model_, &error, &warning, file_.string());
    if (!ok) fail(error.empty() ? "tinygltf could not load it" : error);
  }

  // Checks that tinygltf lets pass or reports less clearly: the GLB container's structure, the JSON's
  // top-level types, nodes with both matrix and TRS, and required extensions (named before
  // tinygltf trips over the data they encode).
  void precheck(bool binary) const {
    std::ifstream in(file_, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::string jsonText = bytes;
    if (binary) jsonText = glbJsonChunk(bytes);
    nlohmann::json root = nlohmann::json::parse(jsonText, nullptr, false);
    if (root.is_discarded()) return;  // tinygltf reports the syntax error with its position
    if (!root.is_object()) fail("the top level must be a JSON object");
    if (root.contains("extensionsRequired") && root["extensionsRequired"].is_array())
      for (const auto& e : root["extensionsRequired"])
        if (e.is_string() && !kSupportedRequiredExtensions.count(e.get<std::string>()))
          fail(cat("extensionsRequired lists ", e.get<std::string>(),
                   ", which lenslab does not support (supported: KHR_materials_unlit)"));
    for (const char* key : {"accessors", "animations", "buffers", "bufferViews", "cameras", "images", "materials",
                            "meshes", "nodes", "samplers", "scenes", "skins", "textures", "extensionsUsed",
                            "extensionsRequired"})
      if (root.contains(key) && !root[key].is_array()) fail(cat("\"", key, "\" must be an array"));
    if (root.contains("asset") && !root["asset"].is_object()) fail("\"asset\" must be an object");
    if (root.contains("nodes"))
      for (std::size_t i = 0; i < root["nodes"].size(); ++i) {
        const auto& node = root["nodes"][i];
        if (node.is_object() && node.contains("matrix") &&
            (node.contains("translation") || node.contains("rotation") || node.contains("scale")))
          fail(cat("node ", i, " has both a matrix and translation/rotation/scale; glTF allows one or the other"));
      }
  }

  // The GLB container: a 12-byte header (magic, version 2, total length), then chunks of
  // (length, type, data) whose lengths are multiples of 4, JSON first, an optional BIN second.
  std::string glbJsonChunk(const std::string& bytes) const {
    auto u32 = [&](std::size_t at) {
      std::uint32_t v = 0;
      std::memcpy(&v, bytes.data() + at, 4);
      return v;
    };
    if (bytes.size() < 12) fail("is too short for a GLB header (12 bytes)");
    if (u32(4) != 2) fail(cat("GLB version is ", u32(4), "; lenslab reads version 2"));
    if (u32(8) != bytes.size()) fail(cat("GLB header says ", u32(8), " bytes but the file has ", bytes.size()));
    std::size_t at = 12;
    std::string json;
    for (int chunk = 0; at < bytes.size(); ++chunk) {
      if (bytes.size() - at < 8) fail(cat("GLB chunk ", chunk, " is cut off in its header"));
      const std::uint32_t length = u32(at), type = u32(at + 4);
      if (length % 4 != 0) fail(cat("GLB chunk ", chunk, " has length ", length, ", not a multiple of 4"));
      if (length > bytes.size() - at - 8) fail(cat("GLB chunk ", chunk, " runs past the end of the file"));
      constexpr std::uint32_t kJson = 0x4E4F534A, kBin = 0x004E4942;
      if (chunk == 0 && type != kJson) fail("the first GLB chunk must be JSON");
      if (chunk == 1 && type != kBin) fail("the second GLB chunk must be BIN");
      if (chunk == 0) json = bytes.substr(at + 8, length);
      at += 8 + length;
    }
    if (json.empty()) fail("GLB has no JSON chunk");
    return json;
  }

  void checkAsset() {
    static const std::regex versionPattern(R"(^([0-9]+)\.([0-9]+)$)");
    std::smatch m;
    const std::string& version = model_.asset.version;
    if (!std::regex_match(version, m, versionPattern))
      fail(cat("asset.version is \"", version, "\"; glTF 2.0 files say \"2.0\""));
    if (m[1].str() != "2") fail(cat("asset.version is ", version, "; lenslab reads glTF 2.x"));
  }

  void checkExtensions() {
    for (const std::string& required : model_.extensionsRequired)
      if (!kSupportedRequiredExtensions.count(required))
        fail(cat("extensionsRequired lists ", required, ", which lenslab does not support (supported: KHR_materials_unlit)"));
    for (const std::string& used : model_.extensionsUsed)
      if (!kSupportedRequiredExtensions.count(used))
        note(cat("extension ", used, " is used but not supported; it is ignored"));
    // Extensions placed on objects they do not extend make the file invalid.
    auto refuseOn = [&](const tinygltf::ExtensionMap& extensions, const std::string& where) {
      for (const auto& [name, value] : extensions)
        if (name == "KHR_materials_unlit" || name == "KHR_texture_transform")
          fail(cat(where, " carries ", name, ", which belongs on ",
                   name == "KHR_materials_unlit" ? "a material" : "a texture reference (textureInfo)"));
    };
    for (std::size_t i = 0; i < model_.samplers.size(); ++i) refuseOn(model_.samplers[i].extensions, cat("sampler ", i));
    for (std::size_t i = 0; i < model_.textures.size(); ++i) refuseOn(model_.textures[i].extensions, cat("texture ", i));
    for (std::size_t i = 0; i < model_.images.size(); ++i) refuseOn(model_.images[i].extensions, cat("image ", i));
    for (std::size_t i = 0; i < model_.nodes.size(); ++i) refuseOn(model_.nodes[i].extensions, cat("node ", i));
    for (std::size_t i = 0; i < model_.meshes.size(); ++i) refuseOn(model_.meshes[i].extensions, cat("mesh ", i));
    for (std::size_t i = 0; i < model_.buffers.size(); ++i) refuseOn(model_.buffers[i].extensions, cat("buffer ", i));
  }

  template <class T>
  bool valid(int index, const std::vector<T>& items) const {
    return index >= 0 && static_cast<std::size_t>(index) < items.size();
  }

  void requireIndex(int index, std::size_t size, const std::string& what, const std::string& kind) const {
    if (index < 0 || static_cast<std::size_t>(index) >= size)
      fail(cat(what, " refers to ", kind, " ", index, ", which does not exist (the file has ", size, ")"));
  }

  // Every reference in the file must resolve, whether or not the default scene uses it (the
  // validator calls an unresolved one an error, and a file with one is not to be trusted).
  void checkReferences() const {
    const tinygltf::Model& m = model_;
    for (std::size_t i = 0; i < m.buffers.size(); ++i)
      if (m.buffers[i].data.empty()) fail(cat("buffer ", i, " is empty (byteLength must be at least 1)"));
    for (std::size_t i = 0; i < m.bufferViews.size(); ++i) {
      const tinygltf::BufferView& v = m.bufferViews[i];
      requireIndex(v.buffer, m.buffers.size(), cat("bufferView ", i), "buffer");
      const std::size_t size = m.buffers[static_cast<std::size_t>(v.buffer)].data.size();
      if (v.byteOffset > size || v.byteLength > size - v.byteOffset)
        fail(cat("bufferView ", i, " (offset ", v.byteOffset, ", length ", v.byteLength, ") runs past the end of buffer ",
                 v.buffer, " (", size, " bytes)"));
      if (v.byteStride != 0 && (v.byteStride < 4 || v.byteStride > 252 || v.byteStride % 4 != 0))
        fail(cat("bufferView ", i, ": byteStride ", v.byteStride, " must be a multiple of 4 from 4 to 252"));
    }
    for (std::size_t i = 0; i < m.accessors.size(); ++i) {
      const tinygltf::Accessor& a = m.accessors[i];
      if (a.bufferView != -1) requireIndex(a.bufferView, m.bufferViews.size(), cat("accessor ", i), "bufferView");
      if (a.sparse.isSparse) {
        requireIndex(a.sparse.indices.bufferView, m.bufferViews.size(), cat("accessor ", i, " sparse indices"), "bufferView");
        requireIndex(a.sparse.values.bufferView, m.bufferViews.size(), cat("accessor ", i, " sparse values"), "bufferView");
      }
    }
    for (std::size_t i = 0; i < m.meshes.size(); ++i)
      for (std::size_t k = 0; k < m.meshes[i].primitives.size(); ++k) {
        const tinygltf::Primitive& p = m.meshes[i].primitives[k];
        const std::string where = cat("mesh ", i, " primitive ", k);
        for (const auto& [name, accessor] : p.attributes)
          requireIndex(accessor, m.accessors.size(), cat(where, " attribute ", name), "accessor");
        if (p.indices != -1) requireIndex(p.indices, m.accessors.size(), cat(where, " indices"), "accessor");
        if (p.material != -1) requireIndex(p.material, m.materials.size(), where, "material");
      }
    for (std::size_t i = 0; i < m.materials.size(); ++i) {
      const int t = m.materials[i].pbrMetallicRoughness.baseColorTexture.index;
      if (t != -1) requireIndex(t, m.textures.size(), cat("material ", i, " baseColorTexture"), "texture");
    }
    for (std::size_t i = 0; i < m.images.size(); ++i)
      if (m.images[i].image.empty())
        fail(cat("image ", i, m.images[i].uri.empty() ? "" : cat(" (", m.images[i].uri, ")"),
                 " could not be read or decoded (lenslab reads PNG and JPEG files next to the scene)"));
    for (std::size_t i = 0; i < m.textures.size(); ++i) {
      const tinygltf::Texture& t = m.textures[i];
      if (t.source != -1) requireIndex(t.source, m.images.size(), cat("texture ", i, " source"), "image");
      if (t.sampler != -1) requireIndex(t.sampler, m.samplers.size(), cat("texture ", i), "sampler");
    }
    for (std::size_t i = 0; i < m.nodes.size(); ++i) {
      const tinygltf::Node& n = m.nodes[i];
      const std::string where = cat("node ", i);
      if (n.mesh != -1) requireIndex(n.mesh, m.meshes.size(), where, "mesh");
      if (n.camera != -1) requireIndex(n.camera, m.cameras.size(), where, "camera");
      if (n.skin != -1) requireIndex(n.skin, m.skins.size(), where, "skin");
      for (int c : n.children) requireIndex(c, m.nodes.size(), cat(where, " children"), "node");
      if (!n.matrix.empty() && (!n.translation.empty() || !n.rotation.empty() || !n.scale.empty()))
        fail(cat(where, " has both a matrix and translation/rotation/scale; glTF allows one or the other"));
    }
    for (std::size_t i = 0; i < m.scenes.size(); ++i)
      for (int n : m.scenes[i].nodes) requireIndex(n, m.nodes.size(), cat("scene ", i), "node");
    for (std::size_t i = 0; i < m.skins.size(); ++i) {
      for (int j : m.skins[i].joints) requireIndex(j, m.nodes.size(), cat("skin ", i, " joints"), "node");
      if (m.skins[i].inverseBindMatrices != -1)
        requireIndex(m.skins[i].inverseBindMatrices, m.accessors.size(), cat("skin ", i, " inverseBindMatrices"), "accessor");
    }
    for (std::size_t i = 0; i < m.animations.size(); ++i) {
      const tinygltf::Animation& a = m.animations[i];
      for (std::size_t s = 0; s < a.samplers.size(); ++s) {
        const std::string where = cat("animation ", i, " sampler ", s);
        requireIndex(a.samplers[s].input, m.accessors.size(), cat(where, " input"), "accessor");
        requireIndex(a.samplers[s].output, m.accessors.size(), cat(where, " output"), "accessor");
      }
      for (std::size_t c = 0; c < a.channels.size(); ++c) {
        const tinygltf::AnimationChannel& ch = a.channels[c];
        const std::string where = cat("animation ", i, " channel ", c);
        requireIndex(ch.sampler, a.samplers.size(), where, "sampler");
        requireIndex(ch.target_node, m.nodes.size(), cat(where, " target"), "node");
        checkAnimationCounts(a.samplers[static_cast<std::size_t>(ch.sampler)], ch, where);
      }
    }
    if (m.defaultScene != -1 && !m.scenes.empty()) requireIndex(m.defaultScene, m.scenes.size(), "scene", "scene");
  }

  // An animation's output holds one value (three for cubic splines) per input time, times the
  // number of morph targets for weights.
  void checkAnimationCounts(const tinygltf::AnimationSampler& s, const tinygltf::AnimationChannel& ch,
                            const std::string& where) const {
    const std::size_t times = model_.accessors[static_cast<std::size_t>(s.input)].count;
    std::size_t perTime = s.interpolation == "CUBICSPLINE" ? 3 : 1;
    if (ch.target_path == "weights") {
      const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(ch.target_node)];
      if (node.mesh < 0 || model_.meshes[static_cast<std::size_t>(node.mesh)].primitives.empty()) return;
      perTime *= model_.meshes[static_cast<std::size_t>(node.mesh)].primitives[0].targets.size();
    }
    const std::size_t values = model_.accessors[static_cast<std::size_t>(s.output)].count;
    if (values != times * perTime)
      fail(cat(where, ": its output holds ", values, " values but ", times, " key times need ", times * perTime));
  }

  // ---- nodes ----

  std::vector<int> rootNodes() {
    if (model_.scenes.empty()) {
      // No scenes: every node that is nobody's child is a root.
      std::vector<bool> isChild(model_.nodes.size(), false);
      for (const tinygltf::Node& n : model_.nodes)
        for (int c : n.children) isChild[static_cast<std::size_t>(c)] = true;
      std::vector<int> roots;
      for (std::size_t i = 0; i < model_.nodes.size(); ++i)
        if (!isChild[i]) roots.push_back(static_cast<int>(i));
      if (roots.empty() && !model_.nodes.empty()) fail("every node is a child of another: the node hierarchy has a loop");
      return roots;
    }
    const int sceneIndex = model_.defaultScene >= 0 ? model_.defaultScene : 0;
    if (model_.scenes.size() > 1) note(cat("the file has ", model_.scenes.size(), " scenes; scene ", sceneIndex, " is drawn"));
    return model_.scenes[static_cast<std::size_t>(sceneIndex)].nodes;
  }

  glm::dmat4 localTransform(const tinygltf::Node& node, int index) const {
    if (node.matrix.size() == 16) {
      glm::dmat4 m;
      for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = node.matrix[static_cast<std::size_t>(i)];  // column-major, as glTF
      return m;
    }
    if (!node.matrix.empty()) fail(cat("node ", index, ": matrix must have 16 numbers"));
    glm::dmat4 m(1.0);
    if (!node.translation.empty()) {
      if (node.translation.size() != 3) fail(cat("node ", index, ": translation must have 3 numbers"));
      m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    }
    if (!node.rotation.empty()) {
      if (node.rotation.size() != 4) fail(cat("node ", index, ": rotation must be a quaternion [x, y, z, w]"));
      const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);  // w first
      m = m * glm::mat4_cast(glm::normalize(q));
    }
    if (!node.scale.empty()) {
      if (node.scale.size() != 3) fail(cat("node ", index, ": scale must have 3 numbers"));
      m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    }
    return m;
  }

  void visitNode(int index, const glm::dmat4& parentFromWorld, std::vector<int>& stack) {
    requireIndex(index, model_.nodes.size(), "the scene", "node");
    if (std::find(stack.begin(), stack.end(), index) != stack.end())
      fail(cat("node ", index, " is its own ancestor: the node hierarchy has a loop"));
    if (stack.size() > kMaxNodeDepth) fail(cat("the node hierarchy is deeper than ", kMaxNodeDepth));
    const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(index)];
    const glm::dmat4 worldFromNode = parentFromWorld * localTransform(node, index);
    for (int i = 0; i < 16; ++i)
      if (!std::isfinite(glm::value_ptr(worldFromNode)[i])) fail(cat("node ", index, ": its transform is not finite"));
    if (node.mesh >= 0) addMeshInstances(node.mesh, worldFromNode);
    if (node.camera >= 0) addCamera(node.camera, worldFromNode);
    if (node.skin >= 0) note("skins are ignored: skinned meshes are drawn in their bind pose");
    stack.push_back(index);
    for (int child : node.children) visitNode(child, worldFromNode, stack);
    stack.pop_back();
  }

  // ---- accessors ----

  struct Elements {
    std::size_t count = 0;
    int components = 0;
    std::vector<double> values;  // count * components
  };

  // Reads `count` elements of a bufferView region, checking every byte it touches.
  void readRegion(int bufferViewIndex, std::size_t byteOffset, std::size_t count, int componentType, int components,
                  bool normalized, std::size_t elementStride, const std::string& what, double* out) const {
    const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(bufferViewIndex)];
    const std::vector<unsigned char>& data = model_.buffers[static_cast<std::size_t>(view.buffer)].data;
    const std::size_t size = componentSize(componentType);
    const std::size_t elementSize = size * static_cast<std::size_t>(components);
    const std::size_t stride = elementStride ? elementStride : elementSize;
    if (stride < elementSize) fail(cat(what, ": byteStride ", stride, " is smaller than one element (", elementSize, " bytes)"));
    if (count == 0) return;
    const std::size_t needed = byteOffset + (count - 1) * stride + elementSize;
    if (byteOffset > view.byteLength || needed > view.byteLength)
      fail(cat(what, ": ", count, " elements from offset ", byteOffset, " need ", needed,
               " bytes but bufferView ", bufferViewIndex, " has ", view.byteLength));
    const unsigned char* base = data.data() + view.byteOffset + byteOffset;
    for (std::size_t e = 0; e < count; ++e)
      for (int c = 0; c < components; ++c)
        out[e * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)] =
            readComponent(base + e * stride + static_cast<std::size_t>(c) * size, componentType, normalized);
  }

  Elements readAccessor(int index, const std::string& what) const {
    const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
    const std::string where = cat(what, " (accessor ", index, ")");
    Elements e;
    e.components = componentCount(a.type);
    if (e.components == 0) fail(cat(where, ": unknown type ", a.type));
    if (componentSize(a.componentType) == 0) fail(cat(where, ": unknown componentType ", a.componentType));
    if (a.count > (std::size_t{1} << 28)) fail(cat(where, ": count ", a.count, " is beyond what lenslab reads"));
    e.count = a.count;
    e.values.assign(e.count * static_cast<std::size_t>(e.components), 0.0);
    if (a.bufferView >= 0) {
      const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
      readRegion(a.bufferView, a.byteOffset, a.count, a.componentType, e.components, a.normalized, view.byteStride,
                 where, e.values.data());
    }
    if (a.sparse.isSparse) applySparse(a, e, where);
    checkMinMax(a, e, where);
    return e;
  }

  // glTF sparse accessors substitute `count` elements, at the given indices, into the base data.
  void applySparse(const tinygltf::Accessor& a, Elements& e, const std::string& where) const {
    if (a.sparse.count < 1 || static_cast<std::size_t>(a.sparse.count) > a.count)
      fail(cat(where, ": sparse count ", a.sparse.count, " must be from 1 to the accessor's count ", a.count));
    const auto n = static_cast<std::size_t>(a.sparse.count);
    const int indexType = a.sparse.indices.componentType;
    if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
      fail(cat(where, ": sparse indices must be unsigned byte, short or int"));
    std::vector<double> indices(n), values(n * static_cast<std::size_t>(e.components));
    readRegion(a.sparse.indices.bufferView, static_cast<std::size_t>(a.sparse.indices.byteOffset), n, indexType, 1, false,
               0, cat(where, " sparse indices"), indices.data());
    readRegion(a.sparse.values.bufferView, static_cast<std::size_t>(a.sparse.values.byteOffset), n, a.componentType,
               e.components, a.normalized, 0, cat(where, " sparse values"), values.data());
    for (std::size_t i = 0; i < n; ++i) {
      const auto target = static_cast<std::size_t>(indices[i]);
      if (target >= e.count) fail(cat(where, ": sparse index ", target, " is beyond the accessor's count ", e.count));
      for (int c = 0; c < e.components; ++c)
        e.values[target * static_cast<std::size_t>(e.components) + static_cast<std::size_t>(c)] =
            values[i * static_cast<std::size_t>(e.components) + static_cast<std::size_t>(c)];
    }
  }

  // Declared bounds must hold the data (the validator's ACCESSOR_ELEMENT_OUT_OF_*_BOUND).
  void checkMinMax(const tinygltf::Accessor& a, const Elements& e, const std::string& where) const {
    const auto comps = static_cast<std::size_t>(e.components);
    const bool hasMin = a.minValues.size() == comps, hasMax = a.maxValues.size() == comps;
    if (!hasMin && !hasMax) return;
    for (std::size_t i = 0; i < e.count; ++i)
      for (std::size_t c = 0; c < comps; ++c) {
        const double v = e.values[i * comps + c];
        if (!std::isfinite(v)) fail(cat(where, ": element ", i, " is not a finite number"));
        if (hasMin && v < a.minValues[c] - 1e-6 * (1.0 + std::abs(a.minValues[c])))
          fail(cat(where, ": element ", i, " component ", c, " is ", v, ", below the declared min ", a.minValues[c]));
        if (hasMax && v > a.maxValues[c] + 1e-6 * (1.0 + std::abs(a.maxValues[c])))
          fail(cat(where, ": element ", i, " component ", c, " is ", v, ", above the declared max ", a.maxValues[c]));
      }
  }

  // ---- meshes ----

  void addMeshInstances(int meshIndex, const glm::dmat4& worldFromModel) {
    const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(meshIndex)];
    for (std::size_t k = 0; k < mesh.primitives.size(); ++k) {
      const auto key = std::make_pair(meshIndex, static_cast<int>(k));
      auto found = meshMap_.find(key);
      if (found == meshMap_.end()) {
        std::optional<Mesh> converted = convertPrimitive(mesh, meshIndex, k);
        int index = -1;
        if (converted) {
          const int material = mesh.primitives[k].material;
          converted->material = material >= 0 ? materialIndex(material) : -1;
          scene_.meshes.push_back(std::move(*converted));
          index = static_cast<int>(scene_.meshes.size()) - 1;
        }
        found = meshMap_.emplace(key, index).first;
      }
      if (found->second < 0) continue;
      scene_.instances.push_back({found->second, worldFromModel});
    }
  }

  // The triangle list of a primitive, or an empty vector for a mode lenslab does not draw.
  std::vector<std::uint32_t> triangleIndices(const tinygltf::Primitive& p, std::size_t vertexCount, const std::string& where) {
    std::vector<std::uint32_t> source;
    if (p.indices >= 0) {
      const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(p.indices)];
      if (a.type != TINYGLTF_TYPE_SCALAR ||
          (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
           a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
           a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) || a.normalized)
        fail(cat(where, " indices (accessor ", p.indices, ") must be scalar unsigned byte, short or int"));
      const Elements e = readAccessor(p.indices, cat(where, " indices"));
      source.reserve(e.count);
      for (double v : e.values) {
        if (v >= static_cast<double>(vertexCount))
          fail(cat(where, ": index ", v, " is beyond the ", vertexCount, " vertices"));
        source.push_back(static_cast<std::uint32_t>(v));
      }
    } else {
      source.resize(vertexCount);
      for (std::size_t i = 0; i < vertexCount; ++i) source[i] = static_cast<std::uint32_t>(i);
    }
    const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
    std::vector<std::uint32_t> triangles;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      triangles.assign(source.begin(), source.begin() + static_cast<std::ptrdiff_t>(source.size() / 3 * 3));
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      // Every other triangle of a strip is wound the other way; swap to keep them counter-clockwise.
      for (std::size_t i = 2; i < source.size(); ++i) {
        if (i % 2 == 0) triangles.insert(triangles.end(), {source[i - 2], source[i - 1], source[i]});
        else triangles.insert(triangles.end(), {source[i - 1], source[i - 2], source[i]});
      }
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
      for (std::size_t i = 2; i < source.size(); ++i)
        triangles.insert(triangles.end(), {source[0], source[i - 1], source[i]});
    }
    return triangles;
  }

  // The primitive as a triangle mesh (material not yet assigned), or nothing when lenslab does not
  // draw it (points, lines, no POSITION). Throws for malformed data.
  std::optional<Mesh> convertPrimitive(const tinygltf::Mesh& gltfMesh, int meshIndex, std::size_t k) {
    const tinygltf::Primitive& p = gltfMesh.primitives[k];
    const std::string where = cat("mesh ", meshIndex, " primitive ", k);
    const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      note("points and lines are not drawn (lenslab draws triangles)");
      return std::nullopt;
    }
    const auto position = p.attributes.find("POSITION");
    if (position == p.attributes.end()) {
      note(cat(where, " has no POSITION and is skipped"));
      return std::nullopt;
    }
    if (!p.targets.empty()) note("morph targets are ignored: meshes are drawn without them");

    const tinygltf::Accessor& pa = model_.accessors[static_cast<std::size_t>(position->second)];
    if (pa.type != TINYGLTF_TYPE_VEC3 || pa.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
      fail(cat(where, " POSITION (accessor ", position->second, ") must be VEC3 float"));
    const Elements positions = readAccessor(position->second, cat(where, " POSITION"));
    const std::size_t n = positions.count;

    Mesh mesh;
    mesh.name = gltfMesh.name.empty() ? cat("mesh", meshIndex) : gltfMesh.name;
    if (gltfMesh.primitives.size() > 1) mesh.name += cat("#", k);
    mesh.vertices.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double* v = &positions.values[i * 3];
      if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
        fail(cat(where, " POSITION element ", i, " is not finite"));
      mesh.vertices[i].position = glm::vec3(v[0], v[1], v[2]);
    }
    bool hasNormals = false;
    if (auto it = p.attributes.find("NORMAL"); it != p.attributes.end()) {
      const Elements e = readAttribute(it->second, where + " NORMAL", n, {3});
      for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 v(e.values[i * 3], e.values[i * 3 + 1], e.values[i * 3 + 2]);
        const float length = glm::length(v);
        mesh.vertices[i].normal = length > 0.0f && std::isfinite(length) ? v / length : glm::vec3(0, 0, 1);
      }
      hasNormals = true;
    }
    if (auto it = p.attributes.find("TEXCOORD_0"); it != p.attributes.end()) {
      const Elements e = readAttribute(it->second, where + " TEXCOORD_0", n, {2});
      for (std::size_t i = 0; i < n; ++i) mesh.vertices[i].uv = glm::vec2(e.values[i * 2], e.values[i * 2 + 1]);
    }
    if (auto it = p.attributes.find("COLOR_0"); it != p.attributes.end()) {
      const Elements e = readAttribute(it->second, where + " COLOR_0", n, {3, 4});
      const auto c = static_cast<std::size_t>(e.components);
      for (std::size_t i = 0; i < n; ++i)
        mesh.vertices[i].color = glm::vec4(e.values[i * c], e.values[i * c + 1], e.values[i * c + 2], c == 4 ? e.values[i * c + 3] : 1.0);
      mesh.hasVertexColors = true;
    }

    mesh.indices = triangleIndices(p, n, where);
    if (mesh.indices.empty()) {
      note(cat(where, " has no complete triangle and is skipped"));
      return std::nullopt;
    }
    if (!hasNormals) makeFlatNormals(mesh);
    return mesh;
  }

  Elements readAttribute(int accessor, const std::string& what, std::size_t vertexCount, std::initializer_list<int> components) {
    Elements e = readAccessor(accessor, what);
    if (std::find(components.begin(), components.end(), e.components) == components.end())
      fail(cat(what, " (accessor ", accessor, ") has ", e.components, " components per element"));
    if (e.count != vertexCount)
      fail(cat(what, " (accessor ", accessor, ") has ", e.count, " elements but POSITION has ", vertexCount));
    return e;
  }

  // glTF: "When normals are not specified, client implementations MUST calculate flat normals":
  // each triangle gets its own three vertices carrying its face normal.
  static void makeFlatNormals(Mesh& mesh) {
    std::vector<Vertex> vertices;
    vertices.reserve(mesh.indices.size());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      Vertex a = mesh.vertices[mesh.indices[t]], b = mesh.vertices[mesh.indices[t + 1]], c = mesh.vertices[mesh.indices[t + 2]];
      glm::vec3 normal = glm::cross(b.position - a.position, c.position - a.position);
      const float length = glm::length(normal);
      normal = length > 0.0f ? normal / length : glm::vec3(0, 0, 1);
      a.normal = b.normal = c.normal = normal;
      vertices.insert(vertices.end(), {a, b, c});
    }
    mesh.vertices = std::move(vertices);
    for (std::size_t i = 0; i < mesh.indices.size(); ++i) mesh.indices[i] = static_cast<std::uint32_t>(i);
  }

  // ---- materials and textures ----

  int materialIndex(int gltfIndex) {
    if (auto it = materialMap_.find(gltfIndex); it != materialMap_.end()) return it->second;
    const tinygltf::Material& m = model_.materials[static_cast<std::size_t>(gltfIndex)];
    Material material;
    material.name = m.name;
    const std::vector<double>& f = m.pbrMetallicRoughness.baseColorFactor;
    if (f.size() == 4) material.baseColorFactor = glm::vec4(f[0], f[1], f[2], f[3]);
    material.unlit = m.extensions.count("KHR_materials_unlit") > 0;
    if (m.alphaMode == "MASK") material.alphaMode = AlphaMode::Mask;
    else if (m.alphaMode == "BLEND") {
      material.alphaMode = AlphaMode::Blend;
      note("alphaMode BLEND is drawn opaque (lenslab sorts no transparency)");
    }
    material.alphaCutoff = static_cast<float>(m.alphaCutoff);
    material.doubleSided = m.doubleSided;
    const tinygltf::TextureInfo& baseTexture = m.pbrMetallicRoughness.baseColorTexture;
    if (baseTexture.index >= 0) {
      if (baseTexture.texCoord != 0) note(cat("material ", gltfIndex, " samples its base colour from TEXCOORD_", baseTexture.texCoord, "; only TEXCOORD_0 is read, so that texture is not drawn"));
      else material.baseColorTexture = textureIndex(baseTexture.index);
    }
    if (m.normalTexture.index >= 0 || m.occlusionTexture.index >= 0 || m.emissiveTexture.index >= 0 ||
        m.pbrMetallicRoughness.metallicRoughnessTexture.index >= 0)
      note("normal, occlusion, emissive and metallic-roughness inputs are ignored (lenslab's shading is base colour × Lambert)");
    scene_.materials.push_back(material);
    const int index = static_cast<int>(scene_.materials.size()) - 1;
    materialMap_[gltfIndex] = index;
    return index;
  }

  static Wrap wrapMode(int value) {
    switch (value) {
      case 33071: return Wrap::ClampToEdge;
      case 33648: return Wrap::MirroredRepeat;
      default: return Wrap::Repeat;
    }
  }

  static Filter filterMode(int value, Filter fallback) {
    switch (value) {
      case 9728: return Filter::Nearest;
      case 9729: return Filter::Linear;
      case 9984: return Filter::NearestMipmapNearest;
      case 9985: return Filter::LinearMipmapNearest;
      case 9986: return Filter::NearestMipmapLinear;
      case 9987: return Filter::LinearMipmapLinear;
      default: return fallback;
    }
  }

  int textureIndex(int gltfIndex) {
    if (auto it = textureMap_.find(gltfIndex); it != textureMap_.end()) return it->second;
    const tinygltf::Texture& t = model_.textures[static_cast<std::size_t>(gltfIndex)];
    if (t.source < 0) fail(cat("texture ", gltfIndex, " has no image source"));
    Texture texture;
    texture.image = imageIndex(t.source);
    if (t.sampler >= 0) {
      const tinygltf::Sampler& s = model_.samplers[static_cast<std::size_t>(t.sampler)];
      texture.sampler.wrapS = wrapMode(s.wrapS);
      texture.sampler.wrapT = wrapMode(s.wrapT);
      texture.sampler.magFilter = filterMode(s.magFilter, Filter::Linear);
      if (texture.sampler.magFilter != Filter::Nearest) texture.sampler.magFilter = Filter::Linear;
      texture.sampler.minFilter = filterMode(s.minFilter, Filter::LinearMipmapLinear);
    }
    scene_.textures.push_back(texture);
    const int index = static_cast<int>(scene_.textures.size()) - 1;
    textureMap_[gltfIndex] = index;
    return index;
  }

  int imageIndex(int gltfIndex) {
    if (auto it = imageMap_.find(gltfIndex); it != imageMap_.end()) return it->second;
    const tinygltf::Image& src = model_.images[static_cast<std::size_t>(gltfIndex)];
    const std::string where = cat("image ", gltfIndex, src.name.empty() ? "" : cat(" (", src.name, ")"),
                                  src.uri.empty() ? "" : cat(" ", src.uri));
    if (src.width <= 0 || src.height <= 0 || src.image.empty())
      fail(cat(where, " could not be decoded (lenslab reads PNG and JPEG)"));
    const int channels = src.component;
    const int bytesPerChannel = src.bits == 16 ? 2 : 1;
    if (channels < 1 || channels > 4 || (src.bits != 8 && src.bits != 16))
      fail(cat(where, ": ", channels, " channels of ", src.bits, " bits are not supported"));
    const std::size_t pixels = static_cast<std::size_t>(src.width) * static_cast<std::size_t>(src.height);
    if (src.image.size() < pixels * static_cast<std::size_t>(channels * bytesPerChannel))
      fail(cat(where, ": decoded data is shorter than ", src.width, "x", src.height));
    TextureImage image;
    image.name = src.name.empty() ? src.uri : src.name;
    image.width = src.width;
    image.height = src.height;
    image.rgba8.resize(pixels * 4);
    for (std::size_t i = 0; i < pixels; ++i) {
      std::uint8_t c[4] = {0, 0, 0, 255};
      for (int k = 0; k < channels; ++k) {
        const std::size_t at = (i * static_cast<std::size_t>(channels) + static_cast<std::size_t>(k)) * static_cast<std::size_t>(bytesPerChannel);
        // 16-bit: keep the high byte (little-endian as decoded).
        c[k] = bytesPerChannel == 2 ? src.image[at + 1] : src.image[at];
      }
      if (channels == 1) c[1] = c[2] = c[0];
      if (channels == 2) { c[3] = c[1]; c[1] = c[2] = c[0]; }  // grey + alpha
      std::memcpy(&image.rgba8[i * 4], c, 4);
    }
    scene_.images.push_back(std::move(image));
    const int index = static_cast<int>(scene_.images.size()) - 1;
    imageMap_[gltfIndex] = index;
    return index;
  }

  // ---- cameras ----

  void addCamera(int index, const glm::dmat4& worldFromCamera) {
    const tinygltf::Camera& c = model_.cameras[static_cast<std::size_t>(index)];
    const std::string where = cat("camera ", index, c.name.empty() ? "" : cat(" (", c.name, ")"));
    auto positive = [&](double v, const char* field) {
      if (!std::isfinite(v) || !(v > 0.0)) fail(cat(where, ": ", field, " is ", v, "; it must be a positive finite number"));
    };
    SceneCamera camera;
    camera.name = c.name;
    camera.worldFromCamera = worldFromCamera;
    if (c.type == "perspective") {
      camera.perspective = true;
      positive(c.perspective.yfov, "yfov");
      positive(c.perspective.znear, "znear");
      if (c.perspective.yfov >= 3.14159265358979) fail(cat(where, ": yfov ", c.perspective.yfov, " must be below pi"));
      if (c.perspective.aspectRatio != 0.0) positive(c.perspective.aspectRatio, "aspectRatio");
      camera.yfovRadians = c.perspective.yfov;
      camera.aspectRatio = c.perspective.aspectRatio;
      camera.znear = c.perspective.znear;
      if (c.perspective.zfar != 0.0) {
        positive(c.perspective.zfar, "zfar");
        if (c.perspective.zfar <= c.perspective.znear) fail(cat(where, ": zfar must exceed znear"));
        camera.zfar = c.perspective.zfar;
      }
    } else if (c.type == "orthographic") {
      camera.perspective = false;
      positive(std::abs(c.orthographic.xmag), "xmag");
      positive(std::abs(c.orthographic.ymag), "ymag");
      positive(c.orthographic.zfar, "zfar");
      if (!std::isfinite(c.orthographic.znear) || c.orthographic.znear < 0.0)
        fail(cat(where, ": znear must be a finite number ≥ 0"));
      if (c.orthographic.zfar <= c.orthographic.znear) fail(cat(where, ": zfar must exceed znear"));
      camera.xmag = std::abs(c.orthographic.xmag);
      camera.ymag = std::abs(c.orthographic.ymag);
      camera.znear = c.orthographic.znear;
      camera.zfar = c.orthographic.zfar;
    } else {
      fail(cat(where, ": type \"", c.type, "\" must be \"perspective\" or \"orthographic\""));
    }
    scene_.cameras.push_back(camera);
  }

  // Meshes and accessors the drawn scene does not use are still checked, so that a broken file is
  // refused whichever scene it would draw: the same conversion, with the result dropped.
  void checkUndrawnData() {
    for (std::size_t i = 0; i < model_.meshes.size(); ++i)
      for (std::size_t k = 0; k < model_.meshes[i].primitives.size(); ++k)
        if (!meshMap_.count({static_cast<int>(i), static_cast<int>(k)}))
          (void)convertPrimitive(model_.meshes[i], static_cast<int>(i), k);
    for (std::size_t i = 0; i < model_.accessors.size(); ++i)
      if (!model_.accessors[i].minValues.empty() || !model_.accessors[i].maxValues.empty())
        (void)readAccessor(static_cast<int>(i), cat("accessor ", i));
  }

  void noteIgnoredFeatures() {
    if (!model_.animations.empty()) note(cat(model_.animations.size(), " animation(s) ignored: the scene is drawn at rest"));
  }

  fs::path file_;
  tinygltf::Model model_;
  Scene scene_;
  std::map<std::pair<int, int>, int> meshMap_;
  std::map<int, int> materialMap_, textureMap_, imageMap_;
};



}  // namespace

Scene loadGltf(const fs::path& file) { return Loader(file).load(); }

}  // namespace lenslab
