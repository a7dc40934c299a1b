#pragma once
// A glTF material assembled at one surface point, as the ray caster evaluates it: the functions of
// shaders/common/shade_surface.glsl compiled as C++ (ShadeSurface.cpp), the same text the
// rasterizer's scene.frag includes, so both renderers make the same surface of the same inputs.
// Each renderer fetches the inputs its own way (SurfaceFetch). Pure.
#include "scene/Brdf.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <span>

namespace lenslab {

// What the shading takes of a material (shade_surface.glsl's SurfaceMaterial: the same fields).
struct SurfaceMaterial {
  glm::vec4 baseColorFactor{1.0f};  // linear RGBA
  bool hasBaseColorTexture = false;
  bool alphaMask = false;  // alphaMode MASK: cut out where alpha < alphaCutoff
  float alphaCutoff = 0.5f;
  bool doubleSided = false;
  bool unlit = false;
  float metallicFactor = 1.0f;
  float roughnessFactor = 1.0f;  // perceptual
  bool hasMetallicRoughnessTexture = false;
  bool hasOcclusionTexture = false;
  float occlusionStrength = 1.0f;
  bool normalMapped = false;  // a normal texture, and tangents to carry it
  float normalScale = 1.0f;
  glm::vec3 emissive{0.0f};         // emissiveFactor × strength, linear
  bool hasEmissiveTexture = false;  // and an emissive factor that is not 0
};

// The material as both renderers shade it; `hasTangents`: whether its mesh has tangents (its own
// or generated ones, scene/Tangents.h), without which a normal map is not applied.
SurfaceMaterial surfaceMaterial(const Material& material, bool hasTangents);

// The geometry at a point, interpolated over its triangle (shade_surface.glsl's SurfacePoint).
struct SurfacePoint {
  glm::vec4 vertexColor{1.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};        // vertex normal, world axes, not normalised
  glm::vec3 tangent{0.0f};                   // vertex tangent xyz, world axes (for a normal map)
  float handedness = 1.0f;                   // the tangent's w × the sign of the instance's determinant
  bool frontFacing = true;                   // as GL decides it (winding, mirrored instances turned)
  glm::vec3 position{0.0f};                  // relative to the lights' origin
  glm::vec3 towardViewer{0.0f, 0.0f, 1.0f};  // unit
};

// What the point sends toward the viewer.
struct ShadedSurface {
  glm::vec3 radiance{0.0f};  // emission included
  glm::vec3 normal{0.0f};    // the shading normal (unit, world)
  float alpha = 1.0f;        // the base colour's alpha clamped to [0, 1], for a blend material
};

// What lights the point: punctual lights (positions relative to SurfacePoint::position's origin)
// and either the uniform surround or the environment.
struct SurfaceLighting {
  std::span<const ShadingLight> lights;
  float ambient = 0.0f;      // the uniform surround's radiance (Lighting::ambient)
  bool environment = false;  // an environment lights the scene (SurfaceFetch's lookups), not `ambient`
};

// What a renderer fetches for a point, its own way: the material's textures (each asked only where
// the material has that texture) and the environment's lookups (only where
// SurfaceLighting::environment).
class SurfaceFetch {
 public:
  virtual ~SurfaceFetch() = default;
  virtual glm::vec4 baseColorTexel() const = 0;          // linear RGBA
  virtual glm::vec4 metallicRoughnessTexel() const = 0;  // linear: G roughness, B metallic
  virtual float occlusionTexel() const = 0;              // linear R
  virtual glm::vec3 emissiveTexel() const = 0;           // linear RGB
  virtual glm::vec3 normalTexel() const = 0;             // linear RGB, 0…1
  // Environment::diffuse and ::specular (scene/Environment.h).
  virtual glm::vec3 environmentDiffuse(const glm::vec3& normal) const = 0;
  virtual glm::vec3 environmentSpecular(const glm::vec3& reflected, float perceptualRoughness) const = 0;
};

// Factor × vertex colour × texture.
glm::vec4 surfaceBaseColor(const SurfaceMaterial& m, const glm::vec4& vertexColor, const SurfaceFetch& fetch);
// Whether alphaMode MASK cuts the point out.
bool alphaCutOut(const SurfaceMaterial& m, const glm::vec4& base);
// The point shaded, from its base colour (surfaceBaseColor; a point not cut out).
ShadedSurface shadeSurface(const SurfaceMaterial& m, const glm::vec4& base, const SurfacePoint& p,
                           const SurfaceLighting& lighting, const SurfaceFetch& fetch);

}  // namespace lenslab
