#include "scene/gltf/ModelChecks.h"

#include "scene/gltf/Images.h"
#include "scene/gltf/Problems.h"
#include "scene/gltf/TinygltfModel.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace lenslab::gltf {

namespace {

// How far a node's rotation may be from unit length, and a matrix from TRS (relative to its
// largest element; the cosine between columns): floats as exporters write them pass, a matrix with
// a projection or a skew and a quaternion that scales do not.
constexpr double kUnitQuaternionTolerance = 1e-3;
constexpr double kTrsMatrixTolerance = 1e-4;

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
    if (dot == std::string::npos || !digits(std::string_view(version).substr(0, dot)) ||
        !digits(std::string_view(version).substr(dot + 1)))
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
      for (std::size_t k = 0; k < m_.meshes[i].primitives.size(); ++k)
        primitive(m_.meshes[i].primitives[k], cat("mesh ", i, " primitive ", k));
  }

  void primitive(const tinygltf::Primitive& p, const std::string& where) const {
    if (p.mode < -1 || p.mode > TINYGLTF_MODE_TRIANGLE_FAN)
      refuse(where, ": mode ", p.mode, " is not a glTF primitive mode (0 to 6)");
    if (p.indices != -1) requireIndex(p.indices, m_.accessors.size(), cat(where, " indices"), "accessor");
    if (p.material != -1) requireIndex(p.material, m_.materials.size(), where, "material");
    std::optional<std::size_t> count;
    for (const auto& [name, accessor] : p.attributes) {
      requireIndex(accessor, m_.accessors.size(), cat(where, " attribute ", name), "accessor");
      const std::size_t n = m_.accessors[toIndex(accessor)].count;
      if (count && *count != n)
        refuse(where, ": attribute ", name, " has ", n, " elements, another has ", *count,
               "; all must have the same count");
      count = n;
    }
    for (const auto& target : p.targets)
      for (const auto& [name, accessor] : target)
        requireIndex(accessor, m_.accessors.size(), cat(where, " morph target ", name), "accessor");
  }

  void materials() const {
    for (std::size_t i = 0; i < m_.materials.size(); ++i) {
      const tinygltf::Material& m = m_.materials[i];
      const std::string where = cat("material ", i, m.name.empty() ? "" : cat(" \"", m.name, "\""));
      const std::vector<double>& f = m.pbrMetallicRoughness.baseColorFactor;
      if (f.size() != 4) refuse(where, ": baseColorFactor has ", f.size(), " numbers; it needs 4 (RGBA)");
      for (std::size_t c = 0; c < 4; ++c)
        if (!(f[c] >= 0.0 && f[c] <= 1.0))
          refuse(where, ": baseColorFactor[", c, "] is ", f[c], "; each must be within [0, 1]");
      const std::vector<double>& e = m.emissiveFactor;
      if (e.size() != 3) refuse(where, ": emissiveFactor has ", e.size(), " numbers; it needs 3 (RGB)");
      for (std::size_t c = 0; c < 3; ++c)
        if (!(e[c] >= 0.0 && e[c] <= 1.0))
          refuse(where, ": emissiveFactor[", c, "] is ", e[c],
                 "; each must be within [0, 1] (KHR_materials_emissive_strength scales it beyond)");
      if (m.alphaMode != "OPAQUE" && m.alphaMode != "MASK" && m.alphaMode != "BLEND")
        refuse(where, ": alphaMode \"", m.alphaMode, "\" must be OPAQUE, MASK or BLEND");
      if (!(m.alphaCutoff >= 0.0) || !std::isfinite(m.alphaCutoff))
        refuse(where, ": alphaCutoff ", m.alphaCutoff, " must be a finite number >= 0");
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
    auto oneOf = [](int v, std::initializer_list<int> valid) {
      return std::find(valid.begin(), valid.end(), v) != valid.end();
    };
    for (std::size_t i = 0; i < m_.samplers.size(); ++i) {
      const tinygltf::Sampler& s = m_.samplers[i];
      for (const int wrap : {s.wrapS, s.wrapT})
        if (!oneOf(wrap, {10497, 33071, 33648}))
          refuse("sampler ", i, ": wrap mode ", wrap,
                 " must be 10497 (REPEAT), 33071 (CLAMP_TO_EDGE) or 33648 (MIRRORED_REPEAT)");
      if (!oneOf(s.magFilter, {-1, 9728, 9729}))
        refuse("sampler ", i, ": magFilter ", s.magFilter, " must be 9728 (NEAREST) or 9729 (LINEAR)");
      if (!oneOf(s.minFilter, {-1, 9728, 9729, 9984, 9985, 9986, 9987}))
        refuse("sampler ", i, ": minFilter ", s.minFilter,
               " must be 9728, 9729 or 9984 to 9987 (NEAREST, LINEAR, *_MIPMAP_*)");
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
      if (!std::isfinite(v) || !(v > 0.0))
        refuse(where, ": ", field, " is ", v, "; it must be a positive finite number");
    };
    if (c.type == "perspective") {
      const tinygltf::PerspectiveCamera& p = c.perspective;
      positive(p.yfov, "yfov");
      if (p.yfov >= std::numbers::pi) refuse(where, ": yfov is ", p.yfov, "; it must be below pi (radians)");
      positive(p.znear, "znear");
      if (p.aspectRatio != 0.0) positive(p.aspectRatio, "aspectRatio");  // tinygltf: 0 = absent
      if (p.zfar != 0.0) {                                               // tinygltf: 0 = absent (infinite)
        positive(p.zfar, "zfar");
        if (p.zfar <= p.znear) refuse(where, ": zfar ", p.zfar, " must be greater than znear ", p.znear);
      }
    } else if (c.type == "orthographic") {
      const tinygltf::OrthographicCamera& o = c.orthographic;
      positive(o.xmag, "xmag");
      positive(o.ymag, "ymag");
      positive(o.zfar, "zfar");
      if (!std::isfinite(o.znear) || o.znear < 0.0)
        refuse(where, ": znear is ", o.znear, "; it must be a finite number >= 0");
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
      if (s.inverseBindMatrices != -1)
        requireIndex(s.inverseBindMatrices, m_.accessors.size(), cat("skin ", i, " inverseBindMatrices"), "accessor");
    }
    for (std::size_t i = 0; i < m_.animations.size(); ++i) {
      const tinygltf::Animation& a = m_.animations[i];
      for (std::size_t s = 0; s < a.samplers.size(); ++s) {
        requireIndex(a.samplers[s].input, m_.accessors.size(), cat("animation ", i, " sampler ", s, " input"),
                     "accessor");
        requireIndex(a.samplers[s].output, m_.accessors.size(), cat("animation ", i, " sampler ", s, " output"),
                     "accessor");
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
  // of morph targets when it drives weights. Weights are not played, but a file that gets this
  // wrong is not to be trusted.
  void animationCounts(const tinygltf::AnimationSampler& s, const tinygltf::AnimationChannel& channel,
                       const std::string& where) const {
    const std::size_t times = m_.accessors[toIndex(s.input)].count;
    std::size_t perTime = s.interpolation == "CUBICSPLINE" ? 3 : 1;
    if (channel.target_path == "weights") {
      const tinygltf::Node& node = m_.nodes[toIndex(channel.target_node)];
      if (node.mesh < 0 || toIndex(node.mesh) >= m_.meshes.size() || m_.meshes[toIndex(node.mesh)].primitives.empty())
        return;
      perTime *= m_.meshes[toIndex(node.mesh)].primitives[0].targets.size();
    }
    const std::size_t values = m_.accessors[toIndex(s.output)].count;
    if (values != times * perTime)
      refuse(where, ": its output holds ", values, " values but ", times, " key times need ", times * perTime);
  }

  // The extensions lenslab reads must sit where they belong (the validator's
  // UNEXPECTED_EXTENSION_OBJECT): unlit on a material, texture transforms on a texture reference.
  void extensionPlacement() const {
    auto check = [](const tinygltf::ExtensionMap& extensions, const std::string& where) {
      if (extensions.count("KHR_materials_unlit"))
        refuse(where, " carries KHR_materials_unlit, which belongs on a material");
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
          refuse("node ", child, " is a child of both node ", parent[toIndex(child)], " and node ", i,
                 "; a glTF node has at most one parent");
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
        if (!v.empty() && v.size() != sizes[f])
          refuse(where, ": ", fields[f].first, " has ", v.size(), " numbers; it needs ", sizes[f]);
        for (const double x : v)
          if (!std::isfinite(x)) refuse(where, ": ", fields[f].first, " holds a number that is not finite");
      }
      if (n.rotation.size() == 4) {
        const double length = std::sqrt(n.rotation[0] * n.rotation[0] + n.rotation[1] * n.rotation[1] +
                                        n.rotation[2] * n.rotation[2] + n.rotation[3] * n.rotation[3]);
        // Exporters write floats: a unit quaternion's length is 1 to about 1e-7.
        if (!(std::abs(length - 1.0) <= kUnitQuaternionTolerance))
          refuse(where, ": rotation (", n.rotation[0], ", ", n.rotation[1], ", ", n.rotation[2], ", ", n.rotation[3],
                 ") has length ", length, "; glTF requires a unit quaternion (length 1 within ",
                 kUnitQuaternionTolerance, ")");
      }
      if (n.matrix.size() == 16) checkTrsMatrix(n.matrix, where);
    }
  }

  // glTF: a node's matrix "MUST be decomposable to TRS": no projection (its bottom row 0, 0, 0, 1)
  // and no skew (the columns of its upper 3 × 3 perpendicular), each within a float's rounding.
  static void checkTrsMatrix(const std::vector<double>& m, const std::string& where) {
    double largest = 1.0;
    for (const double x : m) largest = std::max(largest, std::abs(x));
    const double tolerance = kTrsMatrixTolerance * largest;
    if (std::abs(m[3]) > tolerance || std::abs(m[7]) > tolerance || std::abs(m[11]) > tolerance ||
        std::abs(m[15] - 1.0) > tolerance)
      refuse(where, ": matrix has the bottom row (", m[3], ", ", m[7], ", ", m[11], ", ", m[15],
             "), not (0, 0, 0, 1); glTF requires a matrix decomposable to translation, rotation and scale");
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j) {
        const double* a = &m[static_cast<std::size_t>(4 * i)];
        const double* b = &m[static_cast<std::size_t>(4 * j)];
        const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        const double norms =
            std::sqrt((a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) * (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]));
        if (std::abs(dot) > kTrsMatrixTolerance * norms)
          refuse(where, ": matrix skews (its columns ", i + 1, " and ", j + 1, " are not perpendicular: cos ",
                 dot / norms, "); glTF requires a matrix decomposable to translation, rotation and scale");
      }
  }

  void scenes(const std::vector<int>& parents) const {
    for (std::size_t s = 0; s < m_.scenes.size(); ++s) {
      std::vector<int> seen;
      for (const int n : m_.scenes[s].nodes) {
        requireIndex(n, m_.nodes.size(), cat("scene ", s), "node");
        if (parents[toIndex(n)] != -1)
          refuse("scene ", s, " lists node ", n, ", a child of node ", parents[toIndex(n)],
                 "; a scene lists root nodes only");
        if (std::find(seen.begin(), seen.end(), n) != seen.end()) refuse("scene ", s, " lists node ", n, " twice");
        seen.push_back(n);
      }
    }
    if (m_.defaultScene != -1)
      requireIndex(m_.defaultScene, m_.scenes.size(), "\"scene\" (the default scene)", "scene");
  }

  const tinygltf::Model& m_;
  const AccessorReader& reader_;
};

}  // namespace

std::vector<int> checkModel(const tinygltf::Model& model, const AccessorReader& reader) {
  return ModelCheck(model, reader).run();
}

}  // namespace lenslab::gltf
