#include "raycast/SurfaceInputs.h"

#include "scene/Environment.h"
#include "scene/MaterialMaps.h"

#include <cmath>

namespace lenslab {

glm::dvec2 barycentricOnPlane(const Ray& ray, const HitTriangle& triangle) {
  const glm::dvec3& p0 = triangle.corners[0];
  const glm::dvec3 e1 = triangle.corners[1] - p0, e2 = triangle.corners[2] - p0;
  const glm::dvec3 normal = glm::cross(e1, e2);
  const double denom = glm::dot(ray.direction, normal);
  const double t = std::abs(denom) > 0.0 ? glm::dot(p0 - ray.origin, normal) / denom : 0.0;
  const glm::dvec3 q = ray.origin + t * ray.direction - p0;
  const double d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
  const double d20 = glm::dot(q, e1), d21 = glm::dot(q, e2);
  const double det = d00 * d11 - d01 * d01;
  if (det == 0.0) return {0.0, 0.0};
  return {(d11 * d20 - d01 * d21) / det, (d00 * d21 - d01 * d20) / det};
}

bool readsTextures(const SurfaceMaterial& m) {
  return m.hasBaseColorTexture || m.hasMetallicRoughnessTexture || m.hasOcclusionTexture || m.normalMapped ||
         m.hasEmissiveTexture;
}

SurfacePoint surfacePoint(const HitTriangle& triangle, const glm::mat3& normalFromModel,
                          const glm::mat3& tangentFromModel, bool mirrored, bool normalMapped) {
  const Vertex& v0 = *triangle.vertices[0];
  const Vertex& v1 = *triangle.vertices[1];
  const Vertex& v2 = *triangle.vertices[2];
  const float b0 = triangle.b[0], b1 = triangle.b[1], b2 = triangle.b[2];
  SurfacePoint p;
  p.vertexColor = b0 * v0.color + b1 * v1.color + b2 * v2.color;
  // The loader gives a mesh without normals its face normals.
  p.normal = normalFromModel * (b0 * v0.normal + b1 * v1.normal + b2 * v2.normal);
  if (normalMapped) {
    const glm::vec4 t = b0 * v0.tangent + b1 * v1.tangent + b2 * v2.tangent;
    p.tangent = tangentFromModel * glm::vec3(t);
    p.handedness = mirrored ? -t.w : t.w;
  }
  return p;
}

HitFetch::HitFetch(const Scene& scene, const Material& material, const std::vector<TextureSampler>& samplers,
                   const std::vector<TextureSampler>& dataSamplers, const HitTriangle& triangle,
                   const TextureFootprint& footprint)
    : scene_(scene),
      material_(material),
      samplers_(samplers),
      dataSamplers_(dataSamplers),
      triangle_(triangle),
      footprint_(footprint) {}

glm::vec4 HitFetch::sample(const TextureRef& ref, bool data) const {
  const Vertex& v0 = *triangle_.vertices[0];
  const Vertex& v1 = *triangle_.vertices[1];
  const Vertex& v2 = *triangle_.vertices[2];
  // The slot's uv where barycentric (b1, b2) of the triangle's plane is (in double, then rounded).
  const auto uvAt = [&](glm::dvec2 b) {
    const auto at = [&](glm::vec2 Vertex::*set) {
      return glm::vec2((1.0 - b.x - b.y) * glm::dvec2(v0.*set) + b.x * glm::dvec2(v1.*set) + b.y * glm::dvec2(v2.*set));
    };
    return slotUv(at(&Vertex::uv), at(&Vertex::uv1), ref.texCoord, ref.uvFromTexCoord);
  };
  // The lookup itself at Embree's hit, as the rasterizer's at its interpolated uv.
  const float b0 = triangle_.b[0], b1 = triangle_.b[1], b2 = triangle_.b[2];
  const glm::vec2 uv0 = b0 * v0.uv + b1 * v1.uv + b2 * v2.uv, uv1 = b0 * v0.uv1 + b1 * v1.uv1 + b2 * v2.uv1;
  const glm::vec2 uvHere = uvAt(footprint_.here);
  const auto index = static_cast<std::size_t>(ref.texture);
  const Texture& texture = scene_.textures[index];
  return (data ? dataSamplers_ : samplers_)[index].sample(
      texture.sampler, slotUv(uv0, uv1, ref.texCoord, ref.uvFromTexCoord), uvAt(footprint_.acrossX) - uvHere,
      uvAt(footprint_.acrossY) - uvHere);
}

glm::vec3 HitFetch::environmentDiffuse(const glm::vec3& normal) const { return scene_.environment->diffuse(normal); }

glm::vec3 HitFetch::environmentSpecular(const glm::vec3& reflected, float perceptualRoughness) const {
  return scene_.environment->specular(reflected, perceptualRoughness);
}

}  // namespace lenslab
