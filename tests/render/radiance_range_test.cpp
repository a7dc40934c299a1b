// Radiance stays finite from the material to the pixel: an emissive wall of 1e38 (a float holds
// up to 3.4e38) in focus reads 1e38 in both renderers at any number of aperture views. Summed as
// they were drawn, four views of it made 4e38, which is a float's infinity; the accumulator now
// scales each view by 1 / (the views expected, to a power of two) as it adds it.
#include "../common/gl_test_context.h"
#include "../common/looking_at.h"
#include "camera/PhysicalCamera.h"
#include "plan/FramePlan.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "scene/ProceduralScenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lenslab {
namespace {

Scene emissiveWall(float radiance) {
  Scene scene;
  scene.source = "emissive wall";
  Material m;
  m.unlit = true;
  m.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  m.emissive = glm::vec3(radiance);
  scene.materials.push_back(m);
  scene.meshes.push_back(quadMesh(4.0, 4.0, 0));
  scene.instances.push_back({0, glm::dmat4(1.0)});
  scene.bounds = computeBounds(scene);
  return scene;
}

TEST(RadianceRange, AnEmissiveWallNearAFloatsLargestStaysFiniteThroughAccumulation) {
  LENSLAB_REQUIRE_GL();
  constexpr float kRadiance = 1e38f;
  const Scene scene = emissiveWall(kRadiance);
  PhysicalCamera c = test::lookingAt({0.0, 0.0, 2.0}, {0.0, 0.0, 0.0});
  c.fNumber = 2.0;
  c.focusDistance = 2.0;  // the wall in focus: every view sees it whole
  const Camera camera = toCamera(c, "test");
  const ImageSize size{32, 24};
  Renderer renderer(scene);
  for (const int views : {1, 4, 13, 64}) {
    const FramePlan plan = makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Sobol, views, views, 3});
    const Image image = renderer.render(camera, plan, size);
    for (int y = 4; y < size.heightPx - 4; ++y)
      for (int x = 4; x < size.widthPx - 4; ++x) {
        const float v = image.at(x, y).g;
        ASSERT_TRUE(std::isfinite(v)) << views << " views, pixel " << x << "," << y;
        ASSERT_NEAR(v / kRadiance, 1.0, 1e-5) << views << " views, pixel " << x << "," << y;
      }
  }
  const Image cast = RayCaster(scene).render(camera, size, RaycastOptions{4, 3});
  EXPECT_NEAR(cast.at(size.widthPx / 2, size.heightPx / 2).g / kRadiance, 1.0, 1e-5);
}

}  // namespace
}  // namespace lenslab
