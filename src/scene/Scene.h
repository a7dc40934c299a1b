#pragma once
// The renderable scene: what every renderer (raster and ray caster) draws, flattened out of glTF.
// Pure data (GLM + std), no GL: src/render uploads it, src/raycast will intersect it.
#include "core/Bounds.h"
#include "scene/Environment.h"
#include "scene/SceneAnimation.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace lenslab {

// Texture wrap and filter modes, glTF's sampler values (they are the GL enum values, kept as
// plain integers here so that this header stays free of GL).
enum class Wrap : int { Repeat = 10497, ClampToEdge = 33071, MirroredRepeat = 33648 };
enum class Filter : int {
  Nearest = 9728,
  Linear = 9729,
  NearestMipmapNearest = 9984,
  LinearMipmapNearest = 9985,
  NearestMipmapLinear = 9986,
  LinearMipmapLinear = 9987,
};

struct Sampler {
  Wrap wrapS = Wrap::Repeat;
  Wrap wrapT = Wrap::Repeat;
  Filter magFilter = Filter::Linear;
  Filter minFilter = Filter::LinearMipmapLinear;  // glTF leaves it to the renderer; this is ours
};

// An 8-bit RGBA image, rows from the top (glTF's UV origin is the image's top-left corner).
struct TextureImage {
  std::string name;
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba8;  // width * height * 4
};

// A texture as a material uses it: an image and how to sample it.
struct Texture {
  int image = -1;  // index into Scene::images
  Sampler sampler;
};

enum class AlphaMode { Opaque, Mask, Blend };

// A material's use of a texture: which texture, which TEXCOORD_n set, and KHR_texture_transform's
// map of that set's coordinates (uv' = uvFromTexCoord · (u, v, 1)), the identity where the file
// gives none.
struct TextureRef {
  int texture = -1;  // index into Scene::textures, -1 = none
  int texCoord = 0;  // TEXCOORD_0 or TEXCOORD_1
  glm::mat3 uvFromTexCoord{1.0f};
  bool present() const { return texture >= 0; }
};

struct Material {
  std::string name;
  glm::vec4 baseColorFactor{1.0f};  // linear RGBA
  TextureRef baseColorTexture;      // sRGB
  bool unlit = false;               // KHR_materials_unlit: colour = base colour
  // Emitted radiance, linear: emissiveFactor × KHR_materials_emissive_strength's strength (which
  // may exceed 1: a light source), times the emissive texture (sRGB) where there is one. Added to
  // the shaded colour, lit or unlit.
  glm::vec3 emissive{0.0f};
  TextureRef emissiveTexture;  // sRGB
  bool emits() const { return emissive != glm::vec3(0.0f); }
  // glTF 2.0 metallic-roughness, with the specification's defaults (a rough metal).
  float metallicFactor = 1.0f;
  float roughnessFactor = 1.0f;         // perceptual roughness; the GGX alpha is its square
  TextureRef metallicRoughnessTexture;  // linear: G = roughness, B = metallic
  TextureRef occlusionTexture;          // linear: R
  float occlusionStrength = 1.0f;
  TextureRef normalTexture;  // linear, tangent space (docs/materials.md)
  float normalScale = 1.0f;  // scales the map's x and y before the normal is normalised
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;
  bool doubleSided = false;
};

struct Vertex {
  glm::vec3 position{0.0f};  // model units
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  glm::vec2 uv{0.0f};
  glm::vec4 color{1.0f};    // COLOR_0, linear; white when absent
  glm::vec4 tangent{0.0f};  // TANGENT (xyz unit, w = ±1 the bitangent's sign); zero when the mesh has none
  glm::vec2 uv1{0.0f};      // TEXCOORD_1
};

// One triangle list with one material (glTF strips and fans are converted to lists).
struct Mesh {
  std::string name;
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;  // always indexed, 3 per triangle
  int material = -1;                   // index into Scene::materials, -1 = glTF default material
  bool hasVertexColors = false;
  bool hasTangents = false;  // from the file, or generated for a normal map
};

// A mesh placed in the world by the node hierarchy.
struct Instance {
  int mesh = -1;
  glm::dmat4 worldFromModel{1.0};
  // The glTF node that places it (its index in the file's "nodes"), which the instance AOV
  // reports; -1 for an instance made in code. A node with a mesh of several primitives places
  // one instance per primitive, all with the node's index.
  int gltfNode = -1;
  std::string gltfNodeName;  // that node's name in the file, may be empty (instances.json names it)
};

// The largest world coordinate a scene may have. Both renderers carry positions in float
// relative to a nearby origin (the raster: clipFromModel composed in double; the ray caster:
// geometry relative to the scene's bounds), which holds to ~1e15; Embree loses triangles beyond
// ~1e20 and float clip coordinates overflow near 1e38. Loaders refuse vertices beyond it.
constexpr double kMaxWorldCoordinate = 1e15;

// The largest radiance, intensity or emission a scene may give: about a float's largest (3.4028e38), as
// both renderers carry them in float. Loaders refuse more, naming this limit; a frame that sums
// to more anyway is written with a warning (io/ImageFile.h's radianceOverflowWarning).
constexpr double kMaxRadiance = 3.4e38;

// A camera stored in the glTF file, with its node's placement (it looks along -Z, up +Y).
struct SceneCamera {
  std::string name;      // the camera's name in the file, may be empty
  std::string nodeName;  // the name of the node that places it, may be empty
  int gltfNode = -1;     // that node's index in the file
  bool perspective = true;
  double yfovRadians = 0.0;  // perspective
  double aspectRatio = 0.0;  // perspective, 0 = not given (use the image's)
  double xmag = 0.0;         // orthographic half-width
  double ymag = 0.0;         // orthographic half-height
  double znear = 0.0;
  double zfar = std::numeric_limits<double>::infinity();  // infinite when absent
  glm::dmat4 worldFromCamera{1.0};
};

// lenslab's own lighting (docs/materials.md): a uniform surround of radiance `ambient`, and, in a
// scene without KHR_lights_punctual lights, one directional light shining along −toLight of
// π · diffuse lux, so that a white Lambert surface facing it reflects radiance `diffuse`
// (scene/ShadingLights.h). n faces the viewer on double-sided materials. No shadows.
struct Lighting {
  glm::vec3 toLight = glm::normalize(glm::vec3(0.35f, 0.8f, 0.5f));  // world, unit
  float ambient = 0.25f;
  float diffuse = 0.75f;
  glm::vec3 background{0.05f, 0.06f, 0.08f};  // linear colour where no surface is hit
};

// A KHR_lights_punctual light placed by its node, in the extension's units: a directional light's
// intensity is illuminance (lux), a point or spot light's is luminous intensity (candela).
enum class LightType { Directional, Point, Spot };
struct PunctualLight {
  std::string name;
  LightType type = LightType::Point;
  glm::vec3 color{1.0f};  // linear
  float intensity = 1.0f;
  double range = 0.0;  // world units; 0 = unbounded (inverse square only)
  float innerConeAngleRadians = 0.0f;
  float outerConeAngleRadians = 0.7853982f;   // π/4
  glm::dvec3 worldPosition{0.0};              // point and spot
  glm::dvec3 worldDirection{0.0, 0.0, -1.0};  // unit, the way the light shines (its node's −Z)
  int gltfNode = -1;
};

struct Scene {
  std::string source;  // file it came from, for messages
  // Every file it was read from: the .gltf or .glb, then each buffer and image file its URIs name
  // (data: URIs are in the first). Empty for a scene made in code. The sweep's cached reference
  // is keyed on their bytes (report/ReferenceCache.h).
  std::vector<std::filesystem::path> files;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<TextureImage> images;
  std::vector<Instance> instances;
  std::vector<SceneCamera> cameras;
  Lighting lighting;
  std::vector<PunctualLight> lights;  // KHR_lights_punctual; empty = lenslab's one default light
  Bounds bounds;                      // world-space bounds of all instances
  std::vector<std::string> notes;     // what the loader left out and why (shown by `lenslab info`)
  SceneAnimation animation;           // what poseScene needs to move instances and cameras; empty when nothing moves
  // The environment (--environment): the background both renderers show where no surface is, and
  // the image lighting's lookups; null = none (lighting.background, and no image lighting).
  std::shared_ptr<const EnvironmentLookup> environment;

  std::size_t triangleCount() const;  // over all instances
};

// World-space bounds of every instance's vertices.
Bounds computeBounds(const Scene& scene);

// The matrix that carries a model's normals into world directions: the inverse transpose of
// worldFromModel's linear part, divided by its largest entry. Only the directions it gives are
// used (normalised after), and a model scaled by 1e-12 would otherwise hand float normals of
// length 1e12, whose squared length (1e24 per component, summed) overflows float in normalize.
glm::dmat3 worldNormalFromModel(const glm::dmat4& worldFromModel);

}  // namespace lenslab
