// Normal maps and texture coordinates in both renderers against closed forms: a plane with a
// constant tilted normal map is shaded (and its normal AOV reads) like a plane actually tilted
// that way; a texture with KHR_texture_transform (offset, rotation, scale) on TEXCOORD_1 shows,
// at each pixel, the texel the transform's formula picks.
#include "../common/looking_at.h"
#include "camera/PhysicalCamera.h"
#include "camera/Projection.h"
#include "../common/gl_test_context.h"
#include "plan/FramePlan.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "render/ScenePass.h"
#include "scene/Brdf.h"
#include "scene/ProceduralScenes.h"
#include "scene/ShadingLights.h"
#include "scene/Tangents.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace lenslab {
namespace {
using test::Frame;
using test::frameOf;
using test::lookingAt;
using test::pixelDirection;

// The raster image of a pinhole camera, `views` sub-pixel-jittered views.
Image raster(const Scene& scene, Camera camera, ImageSize size, int views) {
  Camera jittered = camera;
  jittered.lens.apertureRadius = 1e-3;  // only to get a plan with `views` jittered views
  const FramePlan plan =
      makeFramePlan(scene, jittered, size, PlanOptions{AperturePattern::Concentric, views, views, 3});
  camera.lens.apertureRadius = 0.0;
  return Renderer(scene).render(camera, plan, size);
}

TextureImage uniformImage(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  TextureImage image;
  image.name = "uniform";
  image.width = image.height = 4;
  for (int i = 0; i < 16; ++i) image.rgba8.insert(image.rgba8.end(), {r, g, b, 255});
  return image;
}

// A lit, single-sided plane (quadMesh: u along +x, v along −y) placed by `worldFromModel`,
// base colour kBase, with a 4×4 normal map of one texel value and generated tangents.
constexpr glm::vec3 kBase{0.8f, 0.6f, 0.4f};
constexpr std::uint8_t kTexel[3] = {170, 96, 220};

Scene tiltedByMap(const glm::dmat4& worldFromModel, float normalScale) {
  Scene scene;
  scene.source = "normal-mapped plane";
  scene.images.push_back(uniformImage(kTexel[0], kTexel[1], kTexel[2]));
  scene.textures.push_back({0, Sampler{}});
  Material m;
  m.baseColorFactor = glm::vec4(kBase, 1.0f);
  m.normalTexture.texture = 0;
  m.normalScale = normalScale;
  m.metallicFactor = 0.0f;  // a rough dielectric: mostly its diffuse, which the normal turns
  m.roughnessFactor = 0.8f;
  scene.materials.push_back(m);
  Mesh mesh = quadMesh(4.0, 4.0, 0);
  generateTangents(mesh, 0);
  scene.meshes.push_back(mesh);
  scene.instances.push_back({0, worldFromModel});
  scene.bounds = computeBounds(scene);
  return scene;
}

// The closed form: the plane's model frame is ∂P/∂u = +x, ∂P/∂v = −y, n = +z. A glTF normal map's
// +X is right and +Y up in the image (glTF 2.0, material.normalTexture), i.e. along ∂P/∂u and
// −∂P/∂v: its tangent-space normal m is the model direction (m.x, m.y, m.z) of a plane tilted
// that way; into the world by the normal matrix, as any surface normal.
glm::dvec3 tiltedWorldNormal(const glm::dmat4& worldFromModel, double normalScale) {
  glm::dvec3 m = glm::dvec3(kTexel[0], kTexel[1], kTexel[2]) / 255.0 * 2.0 - 1.0;
  m = glm::normalize(glm::dvec3(m.x * normalScale, m.y * normalScale, m.z));
  const glm::dvec3 model(m.x, m.y, m.z);
  return glm::normalize(glm::transpose(glm::inverse(glm::dmat3(worldFromModel))) * model);
}

// Under a non-uniform scale the glTF frame is not the tilted surface's: the specification's
// tangent moves with the surface (worldFromModel's linear part M: a tangent is a difference of
// surface points) and the normal by the normal matrix N = M⁻ᵀ, and the map's normal is taken in
// the frame (M·t, w·cross(N·n, M·t), N·n), each normalised, as the Sample Viewer does.
glm::dvec3 glTFFrameNormal(const glm::dmat4& worldFromModel, double normalScale) {
  glm::dvec3 m = glm::dvec3(kTexel[0], kTexel[1], kTexel[2]) / 255.0 * 2.0 - 1.0;
  m = glm::normalize(glm::dvec3(m.x * normalScale, m.y * normalScale, m.z));
  const glm::dmat3 linear(worldFromModel);
  const glm::dvec3 t = glm::normalize(linear * glm::dvec3(1, 0, 0));
  const glm::dvec3 n = glm::normalize(glm::transpose(glm::inverse(linear)) * glm::dvec3(0, 0, 1));
  const double w = glm::determinant(linear) < 0.0 ? -1.0 : 1.0;  // the quad's own w is +1 (image upright)
  return glm::normalize(t * m.x + w * glm::normalize(glm::cross(n, t)) * m.y + n * m.z);
}

// The radiance the shading gives a surface of kBase (the glTF default metallic-roughness's
// dielectric here: metallic 0 set by tiltedByMap) with normal `n` seen along `v` (unit, toward
// the eye), under the scene's default light and its uniform surround: brdf.glsl's functions,
// which tests/scene/brdf_test.cpp holds to closed forms; here the normal is what is tested.
glm::dvec3 shadedWith(const Scene& scene, const glm::dvec3& n, const glm::dvec3& v) {
  ShadingSurface s;
  s.baseColor = kBase;
  s.metallic = scene.materials[0].metallicFactor;
  s.perceptualRoughness = scene.materials[0].roughnessFactor;
  s.n = glm::vec3(n);
  s.v = glm::vec3(v);
  glm::vec3 c(0.0f);
  for (const ShadingLight& light : shadingLights(scene, glm::dvec3(0.0)))
    c += punctualRadiance(s, light, glm::vec3(0.0f));
  const float ambient = scene.lighting.ambient;
  c += imageLightRadiance(s, glm::vec3(ambient), glm::vec3(ambient),
                          dfgLookup(glm::dot(s.n, s.v), s.perceptualRoughness));
  return glm::dvec3(c);
}

class NormalMap : public ::testing::TestWithParam<int> {};

// 0: placed by a rotation and translation; 1: also mirrored (the bitangent mirrors with it);
// 2: a normal scale of 0.4; 3: scaled 3:1 along a direction in the plane (tangents move by
// worldFromModel's linear part, not the normal matrix: that frame is the expected one);
// 4: plane and camera 1e7 from the world origin (nothing of the map depends on where it is).
TEST_P(NormalMap, APlaneWithAConstantTiltedMapIsShadedLikeATiltedPlaneInBothRenderers) {
  LENSLAB_REQUIRE_GL();
  const int variant = GetParam();
  const glm::dvec3 far = variant == 4 ? glm::dvec3(1e7, 2.5e6, -5e6) : glm::dvec3(0.0);
  glm::dmat4 worldFromModel =
      glm::rotate(glm::translate(glm::dmat4(1.0), far + glm::dvec3(0.2, -0.1, -6.0)), 0.3, glm::dvec3(0.2, 1.0, 0.1));
  if (variant == 1) worldFromModel = worldFromModel * glm::scale(glm::dmat4(1.0), {-1.0, 1.0, 1.0});
  if (variant == 3)
    worldFromModel = worldFromModel * glm::rotate(glm::dmat4(1.0), -0.5, glm::dvec3(0, 0, 1)) *
                     glm::scale(glm::dmat4(1.0), {3.0, 1.0, 1.0}) *
                     glm::rotate(glm::dmat4(1.0), 0.5, glm::dvec3(0, 0, 1));
  const float scale = variant == 2 ? 0.4f : 1.0f;
  const Scene scene = tiltedByMap(worldFromModel, scale);
  const glm::dvec3 normal =
      variant == 3 ? glTFFrameNormal(worldFromModel, scale) : tiltedWorldNormal(worldFromModel, scale);
  if (variant != 3) {
    EXPECT_LE(glm::length(normal - glTFFrameNormal(worldFromModel, scale)), 1e-12) << "the two closed forms agree";
  } else {
    ASSERT_GT(glm::length(normal - tiltedWorldNormal(worldFromModel, scale)), 0.01) << "and here they differ";
  }
  // Against an untilted plane: the map must make a difference the test can see.
  const glm::dvec3 flatNormal =
      glm::normalize(glm::transpose(glm::inverse(glm::dmat3(worldFromModel))) * glm::dvec3(0, 0, 1));
  ASSERT_GT(glm::length(shadedWith(scene, normal, {0, 0, 1}) - shadedWith(scene, flatNormal, {0, 0, 1})), 0.05);

  const PhysicalCamera c = lookingAt(far, far + glm::dvec3(0.0, 0.0, -1.0));
  const Camera camera = toCamera(c, "test");
  const ImageSize size = resolveImageSize(camera, 48, std::nullopt);
  const Image rasterImage = raster(scene, camera, size, 4);
  const Image castImage = RayCaster(scene).render(camera, size, RaycastOptions{4, 3});
  double worstRaster = 0.0, worstCast = 0.0;
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x)
      for (int k = 0; k < 3; ++k) {
        const glm::dvec3 expected = shadedWith(scene, normal, -glm::normalize(pixelDirection(c, x, y, size)));
        worstRaster = std::max(worstRaster, std::abs(rasterImage.at(x, y)[k] - expected[k]));
        worstCast = std::max(worstCast, std::abs(castImage.at(x, y)[k] - expected[k]));
      }
  std::printf("[ measure  ] variant %d: worst |raster − closed form| %.3g, |ray cast − closed form| %.3g\n", variant,
              worstRaster, worstCast);
  // The plane fills the image; float shading and GL's interpolation of the tangent frame over a
  // flat quad leave rounding only.
  EXPECT_LE(worstRaster, 2e-3);
  EXPECT_LE(worstCast, 2e-4);

  // The normal AOV is the mapped normal in camera space (x right, y up, z toward the viewer).
  AovSelection normalOnly;
  normalOnly.normal = true;
  const AovImages aovs = RayCaster(scene).aovImages(camera, size, normalOnly);
  const Frame f = frameOf(c);
  const glm::dvec3 expectedAov(glm::dot(normal, f.right), glm::dot(normal, f.up), glm::dot(normal, -f.forward));
  double worstAov = 0.0;
  for (std::size_t i = 0; i < aovs.normal.size(); ++i)
    worstAov = std::max(worstAov, std::abs(aovs.normal[i] - expectedAov[static_cast<int>(i % 3)]));
  EXPECT_LE(worstAov, 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Placements, NormalMap, ::testing::Values(0, 1, 2, 3, 4));

// A narrow field of view (about 4e-4 rad) is drawn by the double-precision clipping path
// (narrow_field.vert, .geom), which carries the tangent and the second uv set too.
TEST(NormalMapNarrowField, TheDoublePrecisionPathShadesTheMapAlike) {
  LENSLAB_REQUIRE_GL();
  const glm::dmat4 worldFromModel =
      glm::rotate(glm::translate(glm::dmat4(1.0), {0.0, 0.0, -6.0}), 0.3, glm::dvec3(0.2, 1.0, 0.1));
  const Scene scene = tiltedByMap(worldFromModel, 1.0f);
  const glm::dvec3 expected = shadedWith(scene, tiltedWorldNormal(worldFromModel, 1.0), {0.0, 0.0, 1.0});
  PhysicalCamera c = lookingAt({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0});
  c.focalLengthMm = 1e5;
  const Camera camera = toCamera(c, "test");
  ASSERT_TRUE(isNarrowField(clipFromWorld(camera.view)));
  const ImageSize size = resolveImageSize(camera, 16, std::nullopt);
  const Image image = raster(scene, camera, size, 1);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(image.at(size.widthPx / 2, size.heightPx / 2)[k], expected[k], 2e-3);
}

TEST(NormalMapFallback, AMeshWithoutTangentsIsShadedWithItsGeometricNormal) {
  LENSLAB_REQUIRE_GL();
  const glm::dmat4 worldFromModel = glm::translate(glm::dmat4(1.0), {0.0, 0.0, -6.0});
  Scene scene = tiltedByMap(worldFromModel, 1.0f);
  for (Vertex& v : scene.meshes[0].vertices) v.tangent = glm::vec4(0.0f);  // degenerate: zero tangents
  const glm::dvec3 expected = shadedWith(scene, {0.0, 0.0, 1.0}, {0.0, 0.0, 1.0});
  const PhysicalCamera c = lookingAt({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0});
  const Camera camera = toCamera(c, "test");
  const ImageSize size = resolveImageSize(camera, 24, std::nullopt);
  for (const Image& image :
       {raster(scene, camera, size, 1), RayCaster(scene).render(camera, size, RaycastOptions{1, 3})})
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(image.at(size.widthPx / 2, size.heightPx / 2)[k], expected[k], 2e-3);
}

// ---- KHR_texture_transform and TEXCOORD_1

float srgbToLinear(std::uint8_t v) {
  const double x = v / 255.0;
  return static_cast<float>(x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4));
}

// A 4×4 image whose texels are all different, unlit, nearest-filtered.
TextureImage checker() {
  TextureImage image;
  image.name = "texels";
  image.width = image.height = 4;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      image.rgba8.insert(image.rgba8.end(),
                         {static_cast<std::uint8_t>(40 + 60 * i), static_cast<std::uint8_t>(40 + 60 * j),
                          static_cast<std::uint8_t>((i + j) % 2 ? 200 : 30), 255});
  return image;
}

TEST(TextureTransform, EachPixelShowsTheTexelTheTransformOfItsSecondUvSetPicks) {
  LENSLAB_REQUIRE_GL();
  const double offsetU = 0.3, offsetV = -0.2, rotation = 0.5, scaleU = 1.7, scaleV = 0.8;
  Scene scene;
  scene.source = "texture transform";
  scene.images.push_back(checker());
  scene.textures.push_back({0, Sampler{Wrap::Repeat, Wrap::Repeat, Filter::Nearest, Filter::Nearest}});
  Material m;
  m.unlit = true;
  m.baseColorTexture.texture = 0;
  m.baseColorTexture.texCoord = 1;
  // The extension's definition written out (its README): u' = cos·su·u + sin·sv·v + ou, v' = −sin·su·u + cos·sv·v + ov.
  const float cr = static_cast<float>(std::cos(rotation)), sr = static_cast<float>(std::sin(rotation));
  m.baseColorTexture.uvFromTexCoord =
      glm::mat3(glm::vec3(cr * scaleU, -sr * scaleU, 0.0f), glm::vec3(sr * scaleV, cr * scaleV, 0.0f),
                glm::vec3(offsetU, offsetV, 1.0f));
  scene.materials.push_back(m);
  Mesh mesh = quadMesh(1.0, 1.0, 0);
  for (Vertex& v : mesh.vertices) v.uv1 = glm::vec2(1.0f - v.uv.y, v.uv.x);  // set 1 differs from set 0
  scene.meshes.push_back(mesh);
  scene.instances.push_back({0, glm::dmat4(1.0)});  // z = 0, facing +z
  scene.bounds = computeBounds(scene);

  const PhysicalCamera c = lookingAt({0.0, 0.0, 3.0}, {0.0, 0.0, 0.0});
  const Camera camera = toCamera(c, "test");
  const ImageSize size = resolveImageSize(camera, 96, std::nullopt);
  const Image rasterImage = raster(scene, camera, size, 1);
  const Image castImage = RayCaster(scene).render(camera, size, RaycastOptions{1, 3});
  int checked = 0;
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      const glm::dvec3 d = pixelDirection(c, x, y, size);
      const glm::dvec3 p = c.eye + (-c.eye.z / d.z) * d;
      if (std::abs(p.x) > 0.95 || std::abs(p.y) > 0.95) continue;
      const double u0 = 0.5 * (p.x + 1.0), v0 = 0.5 * (1.0 - p.y);  // quadMesh's TEXCOORD_0
      const double u1 = 1.0 - v0, v1 = u0;                          // the set 1 made above
      const double u = std::cos(rotation) * scaleU * u1 + std::sin(rotation) * scaleV * v1 + offsetU;
      const double v = -std::sin(rotation) * scaleU * u1 + std::cos(rotation) * scaleV * v1 + offsetV;
      const double tx = 4.0 * u, ty = 4.0 * v;
      // Pixels within a quarter texel (several pixels) of a texel edge are left out.
      const auto nearEdge = [](double t) { return std::abs(t - std::round(t)) < 0.25; };
      if (nearEdge(tx) || nearEdge(ty)) continue;
      const int i = ((static_cast<int>(std::floor(tx)) % 4) + 4) % 4,
                j = ((static_cast<int>(std::floor(ty)) % 4) + 4) % 4;
      const std::uint8_t* texel = &scene.images[0].rgba8[static_cast<std::size_t>(4 * (j * 4 + i))];
      for (int k = 0; k < 3; ++k) {
        ASSERT_NEAR(rasterImage.at(x, y)[k], srgbToLinear(texel[k]), 2e-3) << "raster pixel " << x << "," << y;
        ASSERT_NEAR(castImage.at(x, y)[k], srgbToLinear(texel[k]), 1e-5) << "ray cast pixel " << x << "," << y;
      }
      ++checked;
    }
  EXPECT_GT(checked, 500);
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

// A 64 × 64 checker of black and white texels; its mean in linear light is ½.
TextureImage oneTexelChecker() {
  TextureImage image;
  image.name = "checker";
  image.width = image.height = 64;
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) {
      const std::uint8_t v = (i + j) % 2 ? 255 : 0;
      image.rgba8.insert(image.rgba8.end(), {v, v, v, 255});
    }
  return image;
}

// A uv transform that scales the texture by 8 shrinks it on screen by 8: its footprint, and so its
// mip level, grows by log2 8 = 3. GL takes the derivatives of the transformed uv; the ray caster
// carries its ray differentials through the transform. A 1-texel checker whose footprint is then
// ~5 texels per pixel filters to an even grey in both; with the untransformed footprint (under a
// texel per pixel) the ray caster would show the checker's texels instead.
TEST(TextureTransform, ScaledUvWidensTheFootprintInBothRenderersAlike) {
  LENSLAB_REQUIRE_GL();
  Scene scene;
  scene.source = "scaled checker";
  scene.images.push_back(oneTexelChecker());
  scene.textures.push_back({0, Sampler{Wrap::Repeat, Wrap::Repeat, Filter::Linear, Filter::LinearMipmapLinear}});
  Material m;
  m.unlit = true;
  m.baseColorTexture.texture = 0;
  m.baseColorTexture.uvFromTexCoord = glm::mat3(glm::vec3(8, 0, 0), glm::vec3(0, 8, 0), glm::vec3(0.1f, 0.3f, 1));
  scene.materials.push_back(m);
  scene.meshes.push_back(quadMesh(1.0, 1.0, 0));
  scene.instances.push_back({0, glm::dmat4(1.0)});
  scene.bounds = computeBounds(scene);
  const PhysicalCamera c = lookingAt({0.0, 0.0, 1.2}, {0.0, 0.0, 0.0});
  const Camera camera = toCamera(c, "test");
  const ImageSize size = resolveImageSize(camera, 96, std::nullopt);
  const Image rasterImage = raster(scene, camera, size, 1);
  const Image castImage = RayCaster(scene).render(camera, size, RaycastOptions{1, 3});
  double difference = 0.0, castSpread = 0.0;
  int pixels = 0;
  for (int y = size.heightPx / 4; y < 3 * size.heightPx / 4; ++y)
    for (int x = size.widthPx / 4; x < 3 * size.widthPx / 4; ++x) {
      difference += std::abs(rasterImage.at(x, y).g - castImage.at(x, y).g);
      castSpread += std::abs(castImage.at(x, y).g - 0.5);  // the checker's mean in linear light
      ++pixels;
    }
  difference /= pixels;
  castSpread /= pixels;
  std::printf("[ measure  ] scaled checker: mean |raster − ray cast| %.3g, ray cast's mean |value − 0.5| %.3g\n",
              difference, castSpread);
  EXPECT_LE(difference, 0.02);
  EXPECT_LE(castSpread, 0.05);
}

// Scaled 10^10 to 10^30 times (repeated or mirrored), the checker repeats far more often
// than a pixel can show: the footprint is the whole texture, and both renderers read the coarsest
// level, the checker's mean. In float such a coordinate has no fraction left, and cast to an int
// it overflowed (the ray caster gave black, NaN or 7.5e30 while the raster stayed right).
TEST(TextureTransform, HugeScalesAndOffsetsReadTheTexturesMeanInBothRenderers) {
  LENSLAB_REQUIRE_GL();
  Scene scene;
  scene.source = "hugely scaled checker";
  scene.images.push_back(oneTexelChecker());
  for (const Wrap wrap : {Wrap::Repeat, Wrap::MirroredRepeat})
    scene.textures.push_back({0, Sampler{wrap, wrap, Filter::Linear, Filter::LinearMipmapLinear}});
  scene.meshes.push_back(quadMesh(1.0, 1.0, 0));
  scene.instances.push_back({0, glm::dmat4(1.0)});
  const PhysicalCamera c = lookingAt({0.0, 0.0, 1.2}, {0.0, 0.0, 0.0});
  const Camera camera = toCamera(c, "test");
  const ImageSize size = resolveImageSize(camera, 48, std::nullopt);
  struct Case {
    float scale, offset;
    int texture;
  };
  // (An offset is brought within one period of the wrap as the file is read: scene/gltf/TextureInfo.h.)
  for (const Case& k : {Case{1e10f, 0.0f, 0}, Case{1e12f, 0.0f, 0}, Case{1e20f, 0.0f, 0}, Case{1e30f, 0.0f, 0},
                        Case{-1e20f, 0.5f, 1}, Case{1e25f, 1.5f, 1}}) {
    Material m;
    m.unlit = true;
    m.baseColorTexture.texture = k.texture;
    m.baseColorTexture.uvFromTexCoord =
        glm::mat3(glm::vec3(k.scale, 0, 0), glm::vec3(0, k.scale, 0), glm::vec3(k.offset, k.offset, 1));
    scene.materials = {m};
    scene.bounds = computeBounds(scene);
    const Image rasterImage = raster(scene, camera, size, 1);
    const Image castImage = RayCaster(scene).render(camera, size, RaycastOptions{1, 3});
    double worstRaster = 0.0, worstCast = 0.0;
    for (int y = size.heightPx / 4; y < 3 * size.heightPx / 4; ++y)
      for (int x = size.widthPx / 4; x < 3 * size.widthPx / 4; ++x) {
        const float r = rasterImage.at(x, y).g, cast = castImage.at(x, y).g;
        worstRaster = std::max(worstRaster, std::isfinite(r) ? std::abs(r - 0.5) : 1e30);
        worstCast = std::max(worstCast, std::isfinite(cast) ? std::abs(cast - 0.5) : 1e30);
      }
    std::printf("[ measure  ] checker scaled %g, offset %g: worst |value - 0.5| raster %.3g, ray cast %.3g\n", k.scale,
                k.offset, worstRaster, worstCast);
    EXPECT_LE(worstRaster, 0.02) << "scale " << k.scale << ", offset " << k.offset;
    EXPECT_LE(worstCast, 0.02) << "scale " << k.scale << ", offset " << k.offset;
  }
}

}  // namespace
}  // namespace lenslab
