// Coverage in alpha and the background colour, in both renderers: where no surface is seen the
// pixel is the background with alpha 0, where a surface fills the pixel alpha is 1, and the
// fraction in between is the same in the raster and the ray cast.
#include "../common/gl_test_context.h"
#include "io/CameraJson.h"
#include "plan/FramePlan.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "scene/GltfLoader.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace lenslab {
namespace {

double meanAlpha(const Image& image) {
  double sum = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) sum += image.at(x, y).a;
  return sum / (image.width * image.height);
}

TEST(Coverage, AlphaIsCoverageAndTheBackgroundIsTheGivenColour) {
  LENSLAB_REQUIRE_GL();
  const std::filesystem::path assets = LENSLAB_TEST_ASSET_DIR;
  Scene scene = loadGltf(assets / "rows/rows.gltf");
  scene.lighting.background = glm::vec3(0.9f, 0.1f, 0.3f);
  const Camera camera = loadCameraJson(assets / "rows/camera.json").camera;
  const ImageSize size{120, 80};
  Renderer renderer(scene);
  const Image raster = renderer.render(
      camera, makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, 64, 64, 2}), size);
  const Image raycast = RayCaster(scene).render(camera, size, RaycastOptions{64, 2});
  for (const Image* image : {&raster, &raycast}) {
    const glm::vec4 sky = image->at(size.widthPx / 2, 0);  // above the horizon: nothing there
    EXPECT_NEAR(sky.r, 0.9f, 1e-5f);
    EXPECT_NEAR(sky.g, 0.1f, 1e-5f);
    EXPECT_NEAR(sky.b, 0.3f, 1e-5f);
    EXPECT_EQ(sky.a, 0.0f);
    EXPECT_EQ(image->at(size.widthPx / 2, size.heightPx - 1).a, 1.0f);  // the floor
  }
  const double rasterCoverage = meanAlpha(raster), raycastCoverage = meanAlpha(raycast);
  std::cout << "[ measure  ] rows: mean coverage raster " << rasterCoverage << ", ray cast " << raycastCoverage << "\n";
  EXPECT_GT(rasterCoverage, 0.2);
  EXPECT_LT(rasterCoverage, 0.95);
  EXPECT_NEAR(rasterCoverage, raycastCoverage, 0.005);
}

}  // namespace
}  // namespace lenslab
