#include "scene/ShadeSurface.h"

#include "scene/MaterialMaps.h"

namespace lenslab {

namespace {

// The GLSL, as C++: glm's names are GLSL's; brdf.glsl's Surface and Light are Brdf.h's
// ShadingSurface and ShadingLight (the same fields), and its functions, and material_maps.glsl's,
// are their C++ compilations (Brdf.h, MaterialMaps.h). Compiled inside a class whose members are
// the includer's functions of shade_surface.glsl, answered by the renderer's SurfaceFetch.
using glm::clamp;

class ShadeSurfaceGlsl {
 public:
  // Either may be null where the function called asks nothing of it.
  ShadeSurfaceGlsl(const SurfaceLighting* lighting, const SurfaceFetch* fetch) : lighting_(lighting), fetch_(fetch) {}

 private:
  const SurfaceLighting* lighting_;
  const SurfaceFetch* fetch_;

  using vec3 = glm::vec3;
  using vec4 = glm::vec4;
  using Surface = ShadingSurface;
  using Light = ShadingLight;

  vec4 baseColorTexel() const { return fetch_->baseColorTexel(); }
  vec4 metallicRoughnessTexel() const { return fetch_->metallicRoughnessTexel(); }
  float occlusionTexel() const { return fetch_->occlusionTexel(); }
  vec3 emissiveTexel() const { return fetch_->emissiveTexel(); }
  vec3 normalTexel() const { return fetch_->normalTexel(); }
  int shadingLightCount() const { return static_cast<int>(lighting_->lights.size()); }
  Light shadingLight(int i) const { return lighting_->lights[static_cast<std::size_t>(i)]; }
  float ambientRadiance() const { return lighting_->ambient; }
  bool environmentLit() const { return lighting_->environment; }
  vec3 environmentDiffuseAt(vec3 n) const { return fetch_->environmentDiffuse(n); }
  vec3 environmentSpecularAt(vec3 r, float perceptualRoughness) const {
    return fetch_->environmentSpecular(r, perceptualRoughness);
  }
  vec3 dfgAt(float nv, float perceptualRoughness) const { return dfgLookup(nv, perceptualRoughness); }

 public:
#define SHADE_SURFACE_STRUCTS_DECLARED
#include "../../shaders/common/shade_surface.glsl"
#undef SHADE_SURFACE_STRUCTS_DECLARED
};

}  // namespace

SurfaceMaterial surfaceMaterial(const Material& material, bool hasTangents) {
  SurfaceMaterial m;
  m.baseColorFactor = material.baseColorFactor;
  m.hasBaseColorTexture = material.baseColorTexture.present();
  m.alphaMask = material.alphaMode == AlphaMode::Mask;
  m.alphaCutoff = material.alphaCutoff;
  m.doubleSided = material.doubleSided;
  m.unlit = material.unlit;
  m.metallicFactor = material.metallicFactor;
  m.roughnessFactor = material.roughnessFactor;
  m.hasMetallicRoughnessTexture = material.metallicRoughnessTexture.present();
  m.hasOcclusionTexture = material.occlusionTexture.present();
  m.occlusionStrength = material.occlusionStrength;
  m.normalMapped = material.normalTexture.present() && hasTangents;
  m.normalScale = material.normalScale;
  m.emissive = material.emissive;
  // An emissive texture times a zero factor adds nothing: it is not read.
  m.hasEmissiveTexture = material.emissiveTexture.present() && material.emits();
  return m;
}

glm::vec4 surfaceBaseColor(const SurfaceMaterial& m, const glm::vec4& vertexColor, const SurfaceFetch& fetch) {
  return ShadeSurfaceGlsl(nullptr, &fetch).surfaceBaseColor(m, vertexColor);
}

bool alphaCutOut(const SurfaceMaterial& m, const glm::vec4& base) {
  return ShadeSurfaceGlsl(nullptr, nullptr).alphaCutOut(m, base);
}

ShadedSurface shadeSurface(const SurfaceMaterial& m, const glm::vec4& base, const SurfacePoint& p,
                           const SurfaceLighting& lighting, const SurfaceFetch& fetch) {
  return ShadeSurfaceGlsl(&lighting, &fetch).shadeSurface(m, base, p);
}

}  // namespace lenslab
