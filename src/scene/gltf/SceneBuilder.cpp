#include "scene/gltf/SceneBuilder.h"

#include "core/NumberInput.h"
#include "scene/gltf/Animations.h"
#include "scene/gltf/Images.h"
#include "scene/gltf/Lights.h"
#include "scene/gltf/Limits.h"
#include "scene/gltf/Primitives.h"
#include "scene/gltf/Problems.h"
#include "scene/ShadingLights.h"
#include "scene/gltf/TextureInfo.h"
#include "scene/Tangents.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

namespace lenslab::gltf {

namespace {

// A node's transform: its matrix (column-major, as GLM stores it) or T * R * S.
glm::dmat4 localTransform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());
  glm::dmat4 m(1.0);
  if (node.translation.size() == 3)
    m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
  if (node.rotation.size() == 4) {
    const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);  // GLM: w first
    m = m * glm::mat4_cast(glm::normalize(q));  // writers round their quaternions; rotate, never shear
  }
  if (node.scale.size() == 3)
    m = m * glm::dmat4(glm::dvec4(node.scale[0], 0, 0, 0), glm::dvec4(0, node.scale[1], 0, 0),
                       glm::dvec4(0, 0, node.scale[2], 0), glm::dvec4(0, 0, 0, 1));
  return m;
}

// The node as poseScene needs it: its rest transform, and its T, R, S apart for channels to replace.
AnimatedNode restNode(const tinygltf::Node& node, int index, int parentSlot) {
  AnimatedNode a;
  a.parent = parentSlot;
  a.gltfNode = index;
  a.name = node.name;
  a.parentFromNodeAtRest = localTransform(node);
  if (node.matrix.size() == 16) return a;  // never animated (glTF); T, R, S stay identity
  if (node.translation.size() == 3)
    a.translation = glm::dvec3(node.translation[0], node.translation[1], node.translation[2]);
  if (node.rotation.size() == 4)
    a.rotation = glm::normalize(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
  if (node.scale.size() == 3) a.scale = glm::dvec3(node.scale[0], node.scale[1], node.scale[2]);
  return a;
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
  SceneBuilder(const tinygltf::Model& model, const AccessorReader& reader, const std::vector<int>& parents,
               Scene& scene)
      : model_(model),
        reader_(reader),
        parents_(parents),
        scene_(scene),
        converter_(model, reader, scene.notes),
        slotOfNode_(model.nodes.size(), -1) {}

  void build() {
    placeNodes(drawnRoots());
    checkUndrawnMeshes();
    readAnimations(model_, reader_, slotOfNode_, scene_);
    noteUnsupportedExtensions();
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
      noteOnce(scene_.notes,
               cat("the file has ", model_.scenes.size(), " scenes; scene ", index,
                   model_.defaultScene >= 0 ? " (its default)" : " (the first: no default is given)", " is drawn"));
    return model_.scenes[toIndex(index)].nodes;
  }

  // Depth first, without recursion (a hierarchy may be deeper than the stack): the checks made
  // it a forest, so each node is met once. Each placed node is also listed in scene.animation.nodes
  // (parents first), with the instances, cameras and lights it places, for poseScene.
  void placeNodes(const std::vector<int>& roots) {
    std::vector<std::tuple<int, glm::dmat4, int>> pending;  // node, worldFromParent, the parent's slot
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) pending.emplace_back(*it, glm::dmat4(1.0), -1);
    while (!pending.empty()) {
      const auto [index, worldFromParent, parentSlot] = pending.back();
      pending.pop_back();
      const tinygltf::Node& node = model_.nodes[toIndex(index)];
      const glm::dmat4 worldFromNode = worldFromParent * localTransform(node);
      for (int i = 0; i < 16; ++i)
        if (!std::isfinite(glm::value_ptr(worldFromNode)[i]))
          refuse("node ", index, ": its world transform is not finite");
      const int slot = static_cast<int>(scene_.animation.nodes.size());
      slotOfNode_[toIndex(index)] = slot;
      scene_.animation.nodes.push_back(restNode(node, index, parentSlot));
      placeNode(node, worldFromNode, scene_.animation.nodes.back());
      for (auto it = node.children.rbegin(); it != node.children.rend(); ++it)
        pending.emplace_back(*it, worldFromNode, slot);
    }
  }

  void placeNode(const tinygltf::Node& node, const glm::dmat4& worldFromNode, AnimatedNode& placed) {
    if (node.mesh >= 0) {
      const std::size_t primitives = model_.meshes[toIndex(node.mesh)].primitives.size();
      for (std::size_t k = 0; k < primitives; ++k)
        if (const int mesh = meshFor(node.mesh, k); mesh >= 0) {
          placed.instances.push_back(static_cast<int>(scene_.instances.size()));
          scene_.instances.push_back({mesh, worldFromNode, placed.gltfNode, node.name});
        }
    }
    if (node.camera >= 0) {
      refuseSingularCameraNode(node, placed.gltfNode, worldFromNode);
      placed.cameras.push_back(static_cast<int>(scene_.cameras.size()));
      addCamera(node.camera, worldFromNode);
      scene_.cameras.back().nodeName = node.name;
      scene_.cameras.back().gltfNode = placed.gltfNode;
    }
    if (node.skin >= 0) noteOnce(scene_.notes, "skins are ignored: skinned meshes are drawn in their bind pose");
    placeLight(node, worldFromNode, placed);
  }

  // KHR_lights_punctual: a light at its node's rest placement (poseScene moves it with its node).
  void placeLight(const tinygltf::Node& node, const glm::dmat4& worldFromNode, AnimatedNode& placed) {
    const int nodeIndex = placed.gltfNode;
    std::optional<PunctualLight> light = placedLight(model_, node, nodeIndex, worldFromNode);
    if (!light) return;
    if (scene_.lights.size() >= static_cast<std::size_t>(kMaxShadingLights))
      refuse("node ", nodeIndex, " places a KHR_lights_punctual light beyond the ", kMaxShadingLights,
             " lenslab shades; place at most ", kMaxShadingLights, " lights in the drawn scene");
    placed.lights.push_back(static_cast<int>(scene_.lights.size()));
    scene_.lights.push_back(std::move(*light));
  }

  // The Scene mesh of a glTF primitive, converted on first use; -1 where nothing is drawn.
  int meshFor(int meshIndex, std::size_t k) {
    const auto key = std::make_pair(meshIndex, k);
    if (const auto found = meshes_.find(key); found != meshes_.end()) return found->second;
    int index = -1;
    if (std::optional<Mesh> mesh = converter_.convert(meshIndex, k)) {
      const int material = model_.meshes[toIndex(meshIndex)].primitives[k].material;
      mesh->material = material >= 0 ? materialFor(material) : -1;  // -1: glTF's default material
      if (mesh->material >= 0) addTangentsForNormalMap(*mesh, meshIndex, k);
      scene_.meshes.push_back(std::move(*mesh));
      index = static_cast<int>(scene_.meshes.size()) - 1;
    }
    meshes_.emplace(key, index);
    return index;
  }

  // A mesh whose material has a normal map and whose file gives no TANGENT gets MikkTSpace
  // tangents, as glTF asks (scene/Tangents.h); meshes without a normal map need none.
  void addTangentsForNormalMap(Mesh& mesh, int meshIndex, std::size_t k) {
    const TextureRef& normalMap = scene_.materials[toIndex(mesh.material)].normalTexture;
    if (!normalMap.present() || mesh.hasTangents) return;
    const TangentStats stats = generateTangents(mesh, normalMap.texCoord);
    if (stats.fallbackVertices > 0)
      noteOnce(scene_.notes,
               cat("mesh ", meshIndex, " primitive ", k, ": ", stats.fallbackVertices,
                   " vertices have no uv gradient for their normal map's tangents (an arbitrary tangent is used)"));
  }

  int materialFor(int gltfIndex) {
    if (const auto found = materials_.find(gltfIndex); found != materials_.end()) return found->second;
    const tinygltf::Material& m = model_.materials[toIndex(gltfIndex)];
    Material material;
    material.name = m.name;
    const std::vector<double>& f = m.pbrMetallicRoughness.baseColorFactor;
    material.baseColorFactor = glm::vec4(f[0], f[1], f[2], f[3]);
    material.unlit = m.extensions.count("KHR_materials_unlit") > 0;
    material.alphaMode = m.alphaMode == "MASK"    ? AlphaMode::Mask
                         : m.alphaMode == "BLEND" ? AlphaMode::Blend
                                                  : AlphaMode::Opaque;
    material.alphaCutoff = static_cast<float>(m.alphaCutoff);
    material.doubleSided = m.doubleSided;
    material.baseColorTexture = textureRefFor(m.pbrMetallicRoughness.baseColorTexture, gltfIndex, "baseColorTexture");
    // Emission: the factor, scaled by KHR_materials_emissive_strength (glTF caps the factor at 1).
    const std::vector<double>& e = m.emissiveFactor;
    double strength = 1.0;
    if (const auto found = m.extensions.find("KHR_materials_emissive_strength"); found != m.extensions.end()) {
      const tinygltf::Value& s = found->second.Get("emissiveStrength");
      if (s.IsNumber()) strength = s.GetNumberAsDouble();
      if (!s.IsNumber() && found->second.Has("emissiveStrength"))
        refuse("material ", gltfIndex, " KHR_materials_emissive_strength.emissiveStrength must be a number");
      // Emitted radiance is a float from here to the pixel: at most a float's largest.
      if (const std::optional<std::string> problem = numberProblem(strength, NumberRange{0.0, kMaxRadiance, ""}))
        refuse("material ", gltfIndex, " KHR_materials_emissive_strength.emissiveStrength: ", *problem,
               " (a float's largest)");
    }
    if (e.size() == 3)
      material.emissive = glm::vec3(static_cast<float>(e[0] * strength), static_cast<float>(e[1] * strength),
                                    static_cast<float>(e[2] * strength));
    if (material.emits()) material.emissiveTexture = textureRefFor(m.emissiveTexture, gltfIndex, "emissiveTexture");
    // Normal map (tangents: meshFor); its scale multiplies the map's x and y.
    material.normalTexture = textureRefFor(m.normalTexture, gltfIndex, "normalTexture");
    material.normalScale = static_cast<float>(m.normalTexture.scale);
    if (!std::isfinite(material.normalScale))
      refuse("material ", gltfIndex, " normalTexture.scale must be a finite number");
    readMetallicRoughness(m, gltfIndex, material);
    scene_.materials.push_back(std::move(material));
    return materials_[gltfIndex] = static_cast<int>(scene_.materials.size()) - 1;
  }

  // glTF metallic-roughness and occlusion (factors in the schema ranges, else refused), the
  // textures through textureRefFor (TEXCOORD_0 or 1, with their uv transforms).
  void readMetallicRoughness(const tinygltf::Material& m, int gltfIndex, Material& material) {
    const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
    material.metallicFactor = static_cast<float>(pbr.metallicFactor);
    material.roughnessFactor = static_cast<float>(pbr.roughnessFactor);
    material.metallicRoughnessTexture =
        textureRefFor(pbr.metallicRoughnessTexture, gltfIndex, "metallicRoughnessTexture");
    material.occlusionTexture = textureRefFor(m.occlusionTexture, gltfIndex, "occlusionTexture");
    material.occlusionStrength = static_cast<float>(m.occlusionTexture.strength);
    if (!(material.metallicFactor >= 0.0f && material.metallicFactor <= 1.0f))
      refuse("material ", gltfIndex, " pbrMetallicRoughness.metallicFactor is ", pbr.metallicFactor,
             "; give a number in [0, 1]");
    if (!(material.roughnessFactor >= 0.0f && material.roughnessFactor <= 1.0f))
      refuse("material ", gltfIndex, " pbrMetallicRoughness.roughnessFactor is ", pbr.roughnessFactor,
             "; give a number in [0, 1]");
    if (!(material.occlusionStrength >= 0.0f && material.occlusionStrength <= 1.0f))
      refuse("material ", gltfIndex, " occlusionTexture.strength is ", m.occlusionTexture.strength,
             "; give a number in [0, 1]");
  }

  // A textureInfo as a TextureRef of this scene (its uv set and KHR_texture_transform); none,
  // with a note, where it samples a uv set lenslab does not read.
  template <class Info>
  TextureRef textureRefFor(const Info& info, int material, const char* slot) {
    if (info.index < 0) return {};
    const std::string where = cat("material ", material, " ", slot);
    (void)textureRef(-1, info.texCoord, info.extensions, where);  // refuses a malformed transform first
    const int set = effectiveTexCoord(info.texCoord, info.extensions);
    if (set != 0 && set != 1) {
      noteOnce(scene_.notes, cat(where, " samples TEXCOORD_", set,
                                 "; lenslab reads TEXCOORD_0 and TEXCOORD_1, so that texture is left out"));
      return {};
    }
    const int texture = textureFor(info.index);
    return textureRef(texture, info.texCoord, info.extensions, where,
                      scene_.textures[static_cast<std::size_t>(texture)].sampler);
  }

  int textureFor(int gltfIndex) {
    if (const auto found = textures_.find(gltfIndex); found != textures_.end()) return found->second;
    const tinygltf::Texture& t = model_.textures[toIndex(gltfIndex)];
    if (t.source < 0)
      refuse("texture ", gltfIndex, " has no source image (lenslab reads PNG and JPEG through \"source\")");
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

  // A camera looks along its node's −Z with +Y up: a node (or parent) scaled to 0 on an axis leaves it
  // no view direction, which would surface later as NaNs in the view; refused naming the node.
  static void refuseSingularCameraNode(const tinygltf::Node& node, int nodeIndex, const glm::dmat4& worldFromNode) {
    // Each axis scaled by its largest component (a length would overflow at 1e200), then the
    // determinant of the unit axes: a large but finite scale passes (it keeps the directions);
    // only a collapsed axis or a non-finite one is refused.
    glm::dmat3 axes(worldFromNode);
    bool usable = true;
    for (int i = 0; i < 3; ++i) {
      const glm::dvec3 a = glm::abs(axes[i]);
      const double largest = std::max({a.x, a.y, a.z});
      usable = usable && std::isfinite(largest) && largest > 0.0;
      if (usable) axes[i] = glm::normalize(axes[i] / largest);
    }
    if (usable && std::abs(glm::determinant(axes)) > 1e-9) return;
    refuse("node ", nodeIndex, node.name.empty() ? std::string() : cat(" \"", excerpt(node.name), "\""), " (camera ",
           node.camera,
           "): its world transform is singular (a scale of 0, with its parents'), so the camera has no view direction; "
           "give the node and its parents a non-zero scale");
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

  void noteUnsupportedExtensions() {
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
  std::vector<int> slotOfNode_;  // glTF node → index into scene.animation.nodes; -1 where not drawn
};

}  // namespace

void buildScene(const tinygltf::Model& model, const AccessorReader& reader, const std::vector<int>& parents,
                Scene& scene) {
  SceneBuilder(model, reader, parents, scene).build();
}

}  // namespace lenslab::gltf
