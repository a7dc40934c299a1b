// Metallic-roughness materials and punctual lights in the rasterizer against the CPU ray cast:
// both evaluate shaders/common/brdf.glsl on the same inputs (positions relative to each view's
// eye, v toward it), so the images differ only by sampling and texture filtering.
#include "../common/gl_test_context.h"
#include "io/CameraJson.h"
#include "io/ImageCompare.h"
#include "plan/FramePlan.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "scene/GltfLoader.h"
#include "scene/Scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

// `rows` with every lit material made metallic-rough: the textured ones read their own image as
// metallic-roughness (G, B) and occlusion (R) maps, the others get factors; lit by a point light
// and a spot light instead of the default light.
Scene rowsWithMaterialsAndLights() {
  Scene scene = loadGltf(fs::path(LENSLAB_TEST_ASSET_DIR) / "rows/rows.gltf");
  int mapped = 0;
  for (Material& m : scene.materials) {
    if (m.unlit) continue;
    if (m.baseColorTexture.present()) {
      m.metallicFactor = 1.0f;
      m.roughnessFactor = 1.0f;
      m.metallicRoughnessTexture.texture = m.baseColorTexture.texture;
      m.occlusionTexture.texture = m.baseColorTexture.texture;
      m.occlusionStrength = 0.8f;
      ++mapped;
    } else {
      m.metallicFactor = 0.6f;
      m.roughnessFactor = 0.35f;
    }
  }
  EXPECT_GT(mapped, 1);
  PunctualLight point;
  point.type = LightType::Point;
  point.color = glm::vec3(1.0f, 0.85f, 0.7f);
  point.intensity = 4.0f;  // candela
  point.worldPosition = glm::dvec3(0.6, 1.4, 0.5);
  PunctualLight spot;
  spot.type = LightType::Spot;
  spot.intensity = 40.0f;
  spot.range = 12.0;
  spot.innerConeAngleRadians = 0.25f;
  spot.outerConeAngleRadians = 0.5f;
  spot.worldPosition = glm::dvec3(-1.5, 3.0, 0.0);
  spot.worldDirection = glm::normalize(glm::dvec3(0.0, 0.0, -3.0) - spot.worldPosition);
  scene.lights = {point, spot};
  scene.lighting.ambient = 0.1f;
  return scene;
}

TEST(RasterVsRaycast, MetallicRoughnessOcclusionPointAndSpot) {
  LENSLAB_REQUIRE_GL();
  const Scene scene = rowsWithMaterialsAndLights();
  const Camera camera = loadCameraJson(fs::path(LENSLAB_TEST_ASSET_DIR) / "rows/camera.json").camera;
  const ImageSize size{240, 160};
  Camera jittered = camera;
  jittered.lens.apertureRadius = 1e-3;  // only to get a plan with 256 jittered views
  const FramePlan plan = makeFramePlan(scene, jittered, size, PlanOptions{AperturePattern::Concentric, 256, 256, 3});
  const Image raster = Renderer(scene).render(camera, plan, size);
  const Image reference = RayCaster(scene).render(camera, size, RaycastOptions{256, 11});
  float brightest = 0.0f;
  for (std::size_t i = 0; i < reference.rgba.size(); ++i)
    if (i % 4 != 3) brightest = std::max(brightest, reference.rgba[i]);
  const double psnr = compareImages(raster, reference, 0.0).psnrDb;
  std::cout
      << "[ measure  ] rows with metallic-roughness, occlusion, a point and a spot light: raster 256 views vs ray cast "
         "256 spp: PSNR "
      << psnr << " dB (brightest " << brightest << ")\n";
  EXPECT_GE(psnr, 45.0);
  // The lights must show: without them the same scene is darker.
  Scene unlit = scene;
  unlit.lights.clear();
  unlit.lighting.diffuse = 0.0f;
  const Image dark = RayCaster(unlit).render(camera, size, RaycastOptions{4, 11});
  EXPECT_LT(compareImages(dark, reference, 0.0).psnrDb, 30.0) << "the lights change the image";
}

// The same scene and its lights moved 1e7 from the world origin light it as at the origin, in both
// renderers: positions reach the shading relative to each view's eye (the raster) or to a point
// near the camera (the ray caster), composed in double. In float world coordinates a point light
// 1e7 away would be placed to within a unit, and the highlights would wander.
TEST(MaterialsFarFromTheOrigin, ALitSceneMovedBy1e7RendersAsAtTheOrigin) {
  LENSLAB_REQUIRE_GL();
  const Scene scene = rowsWithMaterialsAndLights();
  const Camera camera = loadCameraJson(fs::path(LENSLAB_TEST_ASSET_DIR) / "rows/camera.json").camera;
  const ImageSize size{160, 107};
  const glm::dvec3 offset(1e7, 2.5e6, -5e6);
  Scene moved = scene;
  for (Instance& instance : moved.instances)
    instance.worldFromModel = glm::translate(glm::dmat4(1.0), offset) * instance.worldFromModel;
  for (PunctualLight& light : moved.lights) light.worldPosition += offset;
  moved.bounds = computeBounds(moved);
  Camera far = camera;
  far.view.vrp += offset;
  Camera jittered = camera;
  jittered.lens.apertureRadius = 1e-3;  // only to get a plan with 16 jittered views
  const FramePlan plan = makeFramePlan(scene, jittered, size, PlanOptions{AperturePattern::Concentric, 16, 16, 3});
  const double raster =
      compareImages(Renderer(moved).render(far, plan, size), Renderer(scene).render(camera, plan, size), 0.0).psnrDb;
  const RaycastOptions options{4, 5};
  const double rayCast =
      compareImages(RayCaster(moved).render(far, size, options), RayCaster(scene).render(camera, size, options), 0.0)
          .psnrDb;
  std::cout << "[ measure  ] rows with materials and lights moved by 1e7: raster " << raster << " dB, ray cast "
            << rayCast << " dB vs at the origin\n";
  EXPECT_GE(raster, 50.0);
  EXPECT_GE(rayCast, 50.0);
}

}  // namespace
}  // namespace lenslab
