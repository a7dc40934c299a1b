#pragma once
// What the ray caster fetches for a hit, so that scene/ShadeSurface.h shades it as scene.frag
// shades a fragment: the triangle's vertices interpolated at the hit (SurfacePoint), and its
// textures sampled there, filtered over the sample's footprint by ray differentials (HitFetch).
#include "camera/Ray.h"
#include "raycast/TextureSampler.h"
#include "scene/Scene.h"
#include "scene/ShadeSurface.h"

#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace lenslab {

// The triangle a ray hit: its vertices, its corners (relative to the same origin as the ray) and
// the hit's barycentric coordinates (b0, b1, b2), as Embree gives them.
struct HitTriangle {
  std::array<const Vertex*, 3> vertices{};
  std::array<glm::dvec3, 3> corners{};
  std::array<float, 3> b{};
};

// Barycentric (b1, b2) where `ray` meets the plane of the triangle's corners.
glm::dvec2 barycentricOnPlane(const Ray& ray, const HitTriangle& triangle);

// A texture lookup's footprint: barycentric (b1, b2) where the sample's ray and the same sample's
// rays one footprint over in x and in y meet the hit triangle's plane.
struct TextureFootprint {
  glm::dvec2 here{0.0};
  glm::dvec2 acrossX{0.0};
  glm::dvec2 acrossY{0.0};
};

// `rayAt(offset)`: the same sample's ray from the pixel `offset` over; `ray` is rayAt({0, 0}).
template <class RayAt>
TextureFootprint textureFootprint(const HitTriangle& triangle, const Ray& ray, const RayAt& rayAt, double footprintPx) {
  return {barycentricOnPlane(ray, triangle), barycentricOnPlane(rayAt(glm::dvec2(footprintPx, 0.0)), triangle),
          barycentricOnPlane(rayAt(glm::dvec2(0.0, footprintPx)), triangle)};
}

// Whether shading a point of `m` may read a texture (and so needs a TextureFootprint).
bool readsTextures(const SurfaceMaterial& m);

// The hit's geometry for the shading: vertex colour, normal and tangent interpolated, the
// normal into world axes by `normalFromModel`, the tangent by `tangentFromModel` (scene.vert's
// worldTangentFromModel) with its handedness turned where the instance `mirrored`.
SurfacePoint surfacePoint(const HitTriangle& triangle, const glm::mat3& normalFromModel,
                          const glm::mat3& tangentFromModel, bool mirrored, bool normalMapped);

// The hit's textures, each through its slot's uv set and transform (material_maps.glsl's slotUv,
// as scene.frag), with the footprint's uv derivatives through the same transform (a scaled uv
// widens the footprint as GL's derivatives of the transformed uv do); the scene's environment.
class HitFetch final : public SurfaceFetch {
 public:
  // `samplers`: by texture index, colour (sRGB-decoded); `dataSamplers`: the same read as data.
  HitFetch(const Scene& scene, const Material& material, const std::vector<TextureSampler>& samplers,
           const std::vector<TextureSampler>& dataSamplers, const HitTriangle& triangle,
           const TextureFootprint& footprint);

  glm::vec4 baseColorTexel() const override { return sample(material_.baseColorTexture, false); }
  glm::vec4 metallicRoughnessTexel() const override { return sample(material_.metallicRoughnessTexture, true); }
  float occlusionTexel() const override { return sample(material_.occlusionTexture, true).r; }
  glm::vec3 emissiveTexel() const override { return glm::vec3(sample(material_.emissiveTexture, false)); }
  glm::vec3 normalTexel() const override { return glm::vec3(sample(material_.normalTexture, true)); }
  glm::vec3 environmentDiffuse(const glm::vec3& normal) const override;
  glm::vec3 environmentSpecular(const glm::vec3& reflected, float perceptualRoughness) const override;

 private:
  glm::vec4 sample(const TextureRef& ref, bool data) const;

  const Scene& scene_;
  const Material& material_;
  const std::vector<TextureSampler>& samplers_;
  const std::vector<TextureSampler>& dataSamplers_;
  const HitTriangle& triangle_;
  const TextureFootprint& footprint_;
};

}  // namespace lenslab
