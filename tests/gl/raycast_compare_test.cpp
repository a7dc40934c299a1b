// The rasterizer against the CPU ray-cast reference: same Camera, Scene and shading, so what
// remains is each method's error (sampling noise, texture-filter approximations).
#include "gl_test_context.h"
#include "io/CameraJson.h"
#include "io/ImageCompare.h"
#include "plan/FramePlan.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "scene/GltfLoader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

// Raster with `views` jittered (and, with an aperture, lens) samples vs ray casting with `spp`.
double rasterVsRaycastPsnr(const std::string& sceneName, const std::string& cameraFile, bool pinhole, int views, int spp,
                           ImageSize size) {
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / sceneName);
  Camera camera = loadCameraJson(assets / cameraFile).camera;
  Camera lensCamera = camera;
  if (lensCamera.isPinhole()) lensCamera.apertureRadius = 1e-3;  // only to get a plan with `views` samples
  const FramePlan plan = makeFramePlan(scene, lensCamera, size, PlanOptions{AperturePattern::Concentric, views, views, 3});
  if (pinhole) camera.apertureRadius = 0.0;
  Renderer renderer(scene);
  const Image raster = renderer.render(camera, plan, size);
  const RayCaster caster(scene);
  const Image reference = caster.render(camera, size, RaycastOptions{spp, 11});
  const double psnr = compareImages(raster, reference, 0.0).psnrDb;
  std::cout << "[ measure  ] " << sceneName << (pinhole ? " pinhole" : " thin lens") << ": raster " << views
            << " views vs ray cast " << spp << " spp: PSNR " << psnr << " dB\n";
  return psnr;
}

TEST(RasterVsRaycast, PinholeRows) {
  LENSLAB_REQUIRE_GL();
  EXPECT_GE(rasterVsRaycastPsnr("rows/rows.gltf", "rows/camera.json", true, 256, 256, {240, 160}), 45.0);
}

TEST(RasterVsRaycast, ThinLensRowsAndOccluder) {
  LENSLAB_REQUIRE_GL();
  EXPECT_GE(rasterVsRaycastPsnr("rows/rows.gltf", "rows/camera-dof.json", false, 256, 256, {240, 160}), 40.0);
  EXPECT_GE(rasterVsRaycastPsnr("occluder/occluder.gltf", "occluder/camera-dof.json", false, 256, 256, {240, 160}), 40.0);
}

}  // namespace
}  // namespace lenslab
