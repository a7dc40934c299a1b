// alphaMode BLEND in both renderers against closed forms: the ray caster composites along each
// ray, the rasterizer draws blend instances back to front `over` what is behind. Two parallel
// unlit planes of alphas a1 (near), a2 (far) and colours c1, c2 over a background bg show
// a1·c1 + (1 − a1)·(a2·c2 + (1 − a2)·bg), with coverage alpha 1 − (1 − a1)(1 − a2).
#include "../common/blend_scene.h"
#include "camera/PhysicalCamera.h"
#include "camera/Projection.h"
#include "core/Error.h"
#include "../common/gl_test_context.h"
#include "plan/FramePlan.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "render/ScenePass.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace lenslab {
namespace {

constexpr glm::vec3 kBackground{0.1f, 0.2f, 0.3f};
constexpr glm::vec4 kNear{0.9f, 0.2f, 0.1f, 0.3f};  // c1, a1
constexpr glm::vec4 kFar{0.1f, 0.3f, 0.8f, 0.6f};   // c2, a2
constexpr ImageSize kSize{48, 32};

glm::vec3 over(const glm::vec4& front, const glm::vec3& behind) {
  return glm::vec3(front) * front.a + (1.0f - front.a) * behind;
}

// The two planes, wider than the view, at z = 0 (near, node 1) and z = −1 (far, node 2); the near
// one first in the scene's order when `nearFirst` (so that drawing in scene order is wrong).
Scene twoPlanes(bool nearFirst) {
  Scene scene;
  scene.source = "two blend planes";
  scene.lighting.background = kBackground;
  const int nearMaterial = test::addMaterial(scene, kNear, true), farMaterial = test::addMaterial(scene, kFar, true);
  if (nearFirst) test::addQuad(scene, {0.0, 0.0, 0.0}, 10.0, 10.0, nearMaterial, 1);
  test::addQuad(scene, {0.0, 0.0, -1.0}, 10.0, 10.0, farMaterial, 2);
  if (!nearFirst) test::addQuad(scene, {0.0, 0.0, 0.0}, 10.0, 10.0, nearMaterial, 1);
  return scene;
}

Camera pinholeAt(double distance, double focalLengthMm = 35.0) {
  PhysicalCamera c;
  c.eye = {0.0, 0.0, distance};
  c.focalLengthMm = focalLengthMm;
  c.focusDistance = std::numeric_limits<double>::infinity();
  return toCamera(c, "test camera");
}

// The largest difference of any pixel's RGB from `rgb`, and of its alpha from `alpha`.
struct Worst {
  float colour = 0.0f;
  float alpha = 0.0f;
};
Worst worstFrom(const Image& image, const glm::vec3& rgb, float alpha) {
  Worst w;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const glm::vec4 p = image.at(x, y);
      for (int k = 0; k < 3; ++k) w.colour = std::max(w.colour, std::abs(p[k] - rgb[k]));
      w.alpha = std::max(w.alpha, std::abs(p.a - alpha));
    }
  return w;
}

const glm::vec3 kExpected = over(kNear, over(kFar, kBackground));
const float kExpectedCoverage = 1.0f - (1.0f - kNear.a) * (1.0f - kFar.a);

TEST(AlphaBlendRaycast, TwoPlanesOverTheBackgroundAreTheClosedForm) {
  for (const bool nearFirst : {true, false}) {
    const Scene scene = twoPlanes(nearFirst);
    const Image image = RayCaster(scene).render(pinholeAt(5.0), kSize, RaycastOptions{4, 1});
    const Worst w = worstFrom(image, kExpected, kExpectedCoverage);
    EXPECT_LT(w.colour, 1e-5f) << "near first " << nearFirst;
    EXPECT_LT(w.alpha, 1e-5f) << "near first " << nearFirst;
  }
}

TEST(AlphaBlendRaycast, AnOpaqueSurfaceBehindCoversThePixel) {
  Scene scene = twoPlanes(true);
  const glm::vec4 wall{0.5f, 0.4f, 0.3f, 1.0f};
  test::addQuad(scene, {0.0, 0.0, -2.0}, 10.0, 10.0, test::addMaterial(scene, wall, true, false), 3);
  const Image image = RayCaster(scene).render(pinholeAt(5.0), kSize, RaycastOptions{4, 1});
  const Worst w = worstFrom(image, over(kNear, over(kFar, glm::vec3(wall))), 1.0f);
  EXPECT_LT(w.colour, 1e-5f);
  EXPECT_LT(w.alpha, 1e-6f);
}

// Every blend surface along a ray is composited (docs/materials.md): 24 planes of alpha ½ leave
// 2^−24 of the background, in both renderers alike. (Composited 16 at most, the ray cast left 2^−16.)
TEST(AlphaBlendRaycast, CompositesEveryLayerAsTheRasterDoes) {
  LENSLAB_REQUIRE_GL();
  Scene scene;
  scene.source = "twenty-four planes";
  scene.lighting.background = glm::vec3(1.0f);
  const int black = test::addMaterial(scene, {0.0f, 0.0f, 0.0f, 0.5f}, true);
  for (int i = 0; i < 24; ++i) test::addQuad(scene, {0.0, 0.0, -0.1 * i}, 10.0, 10.0, black);
  const Image cast = RayCaster(scene).render(pinholeAt(5.0), kSize, RaycastOptions{1, 1});
  const float left = std::ldexp(1.0f, -24);
  EXPECT_LT(worstFrom(cast, glm::vec3(left), 1.0f - left).colour, 1e-7f);
  const Camera camera = pinholeAt(5.0);
  const Image raster = Renderer(scene).render(camera, makeFramePlan(scene, camera, kSize, PlanOptions{}), kSize);
  EXPECT_LT(worstFrom(raster, glm::vec3(left), 1.0f - left).colour, 1e-6f);
  // A ray through more surfaces than the ray caster follows is refused in one line naming its pixel.
  // (Faint ones, that the transmittance does not end: 4100 of alpha 10⁻⁴ leave 0.66.)
  scene.instances.clear();
  const int faint = test::addMaterial(scene, {0.0f, 0.0f, 0.0f, 1e-4f}, true);
  for (int i = 0; i < 4100; ++i) test::addQuad(scene, {0.0, 0.0, -0.001 * i}, 10.0, 10.0, faint);
  try {
    (void)RayCaster(scene).render(pinholeAt(5.0), {4, 4}, RaycastOptions{1, 1});
    ADD_FAILURE() << "a ray through 4100 surfaces was rendered";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("more than 4096 surfaces lie along the ray at pixel"), std::string::npos)
        << e.what();
  }
}

// The AOVs see the nearest surface whose alpha is at least ½ (Cycles' pass alpha threshold):
// through the faint near plane (a1 = 0.3) to the far one (a2 = 0.6); with the near plane made
// 0.7, the near one; through both faint ones to nothing.
TEST(AlphaBlendRaycast, AovsSeeTheNearestSurfaceAtLeastHalfOpaque) {
  AovSelection all;
  all.depth = all.normal = all.albedo = all.instance = true;
  const auto centre = [&](const Scene& scene) {
    const AovImages aovs = RayCaster(scene).aovImages(pinholeAt(5.0), kSize, all);
    const std::size_t i = static_cast<std::size_t>(kSize.heightPx / 2) * kSize.widthPx + kSize.widthPx / 2;
    return std::tuple(aovs.depth[i], aovs.instance[i],
                      glm::vec3(aovs.albedo[3 * i], aovs.albedo[3 * i + 1], aovs.albedo[3 * i + 2]),
                      aovs.normal[3 * i + 2]);
  };
  {
    const auto [depth, instance, albedo, normalZ] = centre(twoPlanes(true));
    EXPECT_NEAR(depth, 6.0f, 1e-4f);
    EXPECT_EQ(instance, 2.0f);
    EXPECT_NEAR(albedo.b, kFar.b, 1e-6f);
    EXPECT_NEAR(normalZ, 1.0f, 1e-5f);
  }
  {
    Scene scene = twoPlanes(true);
    scene.materials[0].baseColorFactor.a = 0.7f;
    const auto [depth, instance, albedo, normalZ] = centre(scene);
    EXPECT_NEAR(depth, 5.0f, 1e-4f);
    EXPECT_EQ(instance, 1.0f);
    EXPECT_NEAR(albedo.r, kNear.r, 1e-6f);
  }
  {
    Scene scene = twoPlanes(true);
    scene.materials[1].baseColorFactor.a = 0.4f;
    const auto [depth, instance, albedo, normalZ] = centre(scene);
    EXPECT_TRUE(std::isinf(depth));
    EXPECT_EQ(instance, kNoSurfaceInstance);
  }
}

// The rasterizer draws blend instances back to front whatever the scene's order: with the near
// plane listed first, drawing in scene order would put the far plane over the near one.
// Pinhole with one view (drawn straight into the output), with 16 jittered views (layers summed by
// the accumulator), per-tile budget boxes, and a narrow field (the double-precision path).
TEST(AlphaBlendRaster, DrawsBackToFrontWhateverTheSceneOrder) {
  LENSLAB_REQUIRE_GL();
  const glm::vec3 sceneOrder = over(kFar, over(kNear, kBackground));
  ASSERT_GT(glm::length(sceneOrder - kExpected), 0.05f) << "the test must tell the orders apart";
  struct Case {
    const char* what;
    int views;
    double focalLengthMm;
    bool budget;
  };
  for (const Case c : {Case{"one view", 1, 35.0, false}, Case{"16 views", 16, 35.0, false},
                       Case{"per-tile budgets", 16, 35.0, true}, Case{"narrow field", 16, 1e5, false}})
    for (const bool nearFirst : {true, false}) {
      const Scene scene = twoPlanes(nearFirst);
      const Camera camera = pinholeAt(5.0, c.focalLengthMm);
      ASSERT_EQ(isNarrowField(clipFromWorld(camera.view)), c.focalLengthMm > 1e4) << c.what;
      Camera jittered = camera;
      jittered.lens.apertureRadius = c.views > 1 ? 1e-3 : 0.0;  // only to get a plan with `views` jittered samples
      PlanOptions options{AperturePattern::Concentric, c.views, c.views, 3};
      if (c.budget) {
        options.targetPsnrDb = 60.0;
        options.tileSizePx = 16;
        options.pattern = AperturePattern::Sobol;
      }
      const FramePlan plan = makeFramePlan(scene, jittered, kSize, options);
      ASSERT_EQ(plan.adaptive.has_value(), c.budget) << c.what;
      const Image image = Renderer(scene).render(camera, plan, kSize);
      const Worst w = worstFrom(image, kExpected, kExpectedCoverage);
      EXPECT_LT(w.colour, 1e-4f) << c.what << ", near first " << nearFirst;
      EXPECT_LT(w.alpha, 1e-4f) << c.what << ", near first " << nearFirst;
    }
}

// An opaque wall behind the planes: the view's coverage is 1, and a blend plane behind the wall
// is hidden by the depth test although it is drawn after it.
TEST(AlphaBlendRaster, OpaqueSurfacesHideBlendOnesBehindThem) {
  LENSLAB_REQUIRE_GL();
  Scene scene = twoPlanes(true);
  const glm::vec4 wall{0.5f, 0.4f, 0.3f, 1.0f};
  test::addQuad(scene, {0.0, 0.0, -0.5}, 10.0, 10.0, test::addMaterial(scene, wall, true, false));
  const Camera camera = pinholeAt(5.0);
  const FramePlan plan = makeFramePlan(scene, camera, kSize, PlanOptions{AperturePattern::Concentric, 1, 1, 3});
  const Image image = Renderer(scene).render(camera, plan, kSize);
  const Worst w = worstFrom(image, over(kNear, glm::vec3(wall)), 1.0f);
  EXPECT_LT(w.colour, 1e-4f);
  EXPECT_LT(w.alpha, 1e-6f);
}

}  // namespace
}  // namespace lenslab
