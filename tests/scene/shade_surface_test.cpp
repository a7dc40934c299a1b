// The material assembly (shaders/common/shade_surface.glsl compiled as C++) against what glTF says
// it does, on cases with closed forms, and the contract with the renderers' fetches: a texture is
// asked for only where the material has it, the environment only where it lights the scene.
#include "scene/ShadeSurface.h"

#include <gtest/gtest.h>

#include <array>

namespace lenslab {
namespace {

// Fixed texels, and a count of what was asked.
class CountingFetch final : public SurfaceFetch {
 public:
  glm::vec4 baseColorTexel() const override {
    ++asked[0];
    return glm::vec4(0.5f, 0.25f, 1.0f, 0.5f);
  }
  glm::vec4 metallicRoughnessTexel() const override {
    ++asked[1];
    return glm::vec4(1.0f, 0.5f, 0.0f, 1.0f);
  }
  float occlusionTexel() const override {
    ++asked[2];
    return 0.25f;
  }
  glm::vec3 emissiveTexel() const override {
    ++asked[3];
    return glm::vec3(0.5f);
  }
  glm::vec3 normalTexel() const override {
    ++asked[4];
    return glm::vec3(0.5f, 0.5f, 1.0f);
  }
  glm::vec3 environmentDiffuse(const glm::vec3&) const override {
    ++asked[5];
    return glm::vec3(1.0f);
  }
  glm::vec3 environmentSpecular(const glm::vec3&, float) const override {
    ++asked[6];
    return glm::vec3(1.0f);
  }
  mutable std::array<int, 7> asked{};
};

SurfacePoint facingUp() {
  SurfacePoint p;
  p.normal = {0.0f, 0.0f, 2.0f};  // not unit, as interpolated
  p.towardViewer = {0.0f, 0.0f, 1.0f};
  return p;
}

TEST(SurfaceMaterial, TakesTheMaterialAsBothRenderersShadeIt) {
  Material material;
  material.baseColorFactor = {0.1f, 0.2f, 0.3f, 0.4f};
  material.alphaMode = AlphaMode::Mask;
  material.alphaCutoff = 0.3f;
  material.normalTexture.texture = 0;
  material.normalScale = 0.7f;
  material.emissiveTexture.texture = 1;
  material.occlusionTexture.texture = 2;
  material.occlusionStrength = 0.6f;
  SurfaceMaterial m = surfaceMaterial(material, true);
  EXPECT_EQ(m.baseColorFactor, material.baseColorFactor);
  EXPECT_TRUE(m.alphaMask);
  EXPECT_EQ(m.alphaCutoff, 0.3f);
  EXPECT_TRUE(m.normalMapped);
  EXPECT_EQ(m.normalScale, 0.7f);
  EXPECT_TRUE(m.hasOcclusionTexture);
  EXPECT_EQ(m.occlusionStrength, 0.6f);
  EXPECT_FALSE(m.hasBaseColorTexture);
  EXPECT_FALSE(m.hasMetallicRoughnessTexture);
  // glTF's emissive factor defaults to 0, which the texture multiplies: it is not read.
  EXPECT_FALSE(m.hasEmissiveTexture);
  material.emissive = {1.0f, 0.0f, 0.0f};
  EXPECT_TRUE(surfaceMaterial(material, true).hasEmissiveTexture);
  // A normal map needs tangents to carry it.
  EXPECT_FALSE(surfaceMaterial(material, false).normalMapped);
}

TEST(ShadeSurface, UnlitIsTheBaseColourPlusEmissionWithAlphaClamped) {
  SurfaceMaterial m;
  m.unlit = true;
  m.baseColorFactor = {0.5f, 1.0f, 2.0f, 1.5f};
  m.hasBaseColorTexture = true;
  m.emissive = {1.0f, 2.0f, 3.0f};
  m.hasEmissiveTexture = true;
  const CountingFetch fetch;
  SurfacePoint p = facingUp();
  p.vertexColor = {1.0f, 1.0f, 0.5f, 1.0f};
  const glm::vec4 base = surfaceBaseColor(m, p.vertexColor, fetch);
  EXPECT_EQ(base, glm::vec4(0.25f, 0.25f, 1.0f, 0.75f));  // factor × vertex colour × texel
  const ShadedSurface s = shadeSurface(m, base, p, SurfaceLighting{}, fetch);
  EXPECT_EQ(s.radiance, glm::vec3(0.25f, 0.25f, 1.0f) + glm::vec3(0.5f, 1.0f, 1.5f));
  EXPECT_EQ(s.alpha, 0.75f);
  m.baseColorFactor.a = 3.0f;
  EXPECT_EQ(shadeSurface(m, surfaceBaseColor(m, p.vertexColor, fetch), p, SurfaceLighting{}, fetch).alpha, 1.0f);
  EXPECT_EQ(shadeSurface(m, glm::vec4(1.0f, 1.0f, 1.0f, -0.5f), p, SurfaceLighting{}, fetch).alpha, 0.0f);
  // Unlit: no light, no metallic-roughness, no environment asked.
  EXPECT_EQ(fetch.asked[1] + fetch.asked[2] + fetch.asked[5] + fetch.asked[6], 0);
}

TEST(ShadeSurface, AMaskCutsOutBelowItsCutoffOnly) {
  SurfaceMaterial m;
  m.alphaMask = true;
  m.alphaCutoff = 0.5f;
  EXPECT_TRUE(alphaCutOut(m, glm::vec4(1.0f, 1.0f, 1.0f, 0.49f)));
  EXPECT_FALSE(alphaCutOut(m, glm::vec4(1.0f, 1.0f, 1.0f, 0.5f)));
  m.alphaMask = false;
  EXPECT_FALSE(alphaCutOut(m, glm::vec4(0.0f)));
}

TEST(ShadeSurface, ADoubleSidedBackFaceTurnsItsNormalToTheViewer) {
  SurfaceMaterial m;
  SurfacePoint p = facingUp();
  p.frontFacing = false;
  p.towardViewer = {0.0f, 0.0f, -1.0f};
  const CountingFetch fetch;
  const SurfaceLighting dark{};
  EXPECT_EQ(shadeSurface(m, glm::vec4(1.0f), p, dark, fetch).normal, glm::vec3(0.0f, 0.0f, 1.0f));
  m.doubleSided = true;
  EXPECT_EQ(shadeSurface(m, glm::vec4(1.0f), p, dark, fetch).normal, glm::vec3(0.0f, 0.0f, -1.0f));
}

TEST(ShadeSurface, OcclusionDarkensTheSurroundNotThePunctualLights) {
  // A white rough dielectric under a uniform surround: the image light times 1 + strength·(texel − 1).
  SurfaceMaterial m;
  m.metallicFactor = 0.0f;
  m.baseColorFactor = glm::vec4(1.0f);
  const SurfacePoint p = facingUp();
  const CountingFetch fetch;
  const SurfaceLighting surround{{}, 1.0f, false};
  const glm::vec3 open = shadeSurface(m, glm::vec4(1.0f), p, surround, fetch).radiance;
  m.hasOcclusionTexture = true;
  m.occlusionStrength = 0.5f;
  const glm::vec3 occluded = shadeSurface(m, glm::vec4(1.0f), p, surround, fetch).radiance;
  EXPECT_NEAR(occluded.g / open.g, 1.0f + 0.5f * (0.25f - 1.0f), 1e-6f);
  // A directional light straight above: the occlusion map leaves it alone.
  ShadingLight sun;
  sun.type = 0;
  sun.intensity = glm::vec3(3.0f);
  sun.direction = {0.0f, 0.0f, -1.0f};
  const std::array<ShadingLight, 1> lights{sun};
  const SurfaceLighting lit{lights, 0.0f, false};
  m.hasOcclusionTexture = false;
  const glm::vec3 bare = shadeSurface(m, glm::vec4(1.0f), p, lit, fetch).radiance;
  m.hasOcclusionTexture = true;
  EXPECT_EQ(shadeSurface(m, glm::vec4(1.0f), p, lit, fetch).radiance, bare);
  EXPECT_GT(bare.g, 0.0f);
}

TEST(ShadeSurface, AsksForTheEnvironmentOnlyWhereItLightsTheScene) {
  SurfaceMaterial m;
  const CountingFetch fetch;
  const SurfacePoint p = facingUp();
  (void)shadeSurface(m, glm::vec4(1.0f), p, SurfaceLighting{{}, 0.5f, false}, fetch);
  EXPECT_EQ(fetch.asked[5] + fetch.asked[6], 0);
  (void)shadeSurface(m, glm::vec4(1.0f), p, SurfaceLighting{{}, 0.5f, true}, fetch);
  EXPECT_EQ(fetch.asked[5], 1);
  EXPECT_EQ(fetch.asked[6], 1);
  // No texture asked of a material without any.
  EXPECT_EQ(fetch.asked[0] + fetch.asked[1] + fetch.asked[2] + fetch.asked[3] + fetch.asked[4], 0);
}

}  // namespace
}  // namespace lenslab
