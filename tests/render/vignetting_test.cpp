// Vignetting in both renderers: every channel of the finished pixel, background included, times
// 1 + a1 r² + a2 r⁴ + a3 r⁶ at the pixel's place on the film (its centre, normalised, distorted
// coordinates). Checked in closed form on a flat scene (an unlit wall in the middle, a constant
// background round it), through each way the raster finishes a frame (one view, the lens remap,
// the resolve of many views, the lens gather, per-tile budgets), raster against ray cast, and a
// tiled frame against one render.
#include "camera/Camera.h"
#include "camera/Projection.h"
#include "core/Text.h"
#include "../common/gl_test_context.h"
#include "io/ImageCompare.h"
#include "plan/FramePlan.h"
#include "plan/TilePlan.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "render/TiledRender.h"
#include "scene/ProceduralScenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace lenslab {
namespace {

constexpr double kFocus = 2.0;
const glm::vec3 kWall(0.8f), kBackground(0.6f);
const Vignetting kLens{-0.6, 0.1, -0.02};  // corner (r² = 0.5): gain 0.7225

// Camera at the origin looking down −z, focused on its view plane at kFocus, window ±1
// (normalised ±0.5, corner radius 0.707).
Camera flatCamera(double k1, double apertureRadius) {
  ViewSpec v;
  v.vrp = {0.0, 0.0, -kFocus};
  v.vpn = {0.0, 0.0, 1.0};
  v.prp = {0.0, 0.0, kFocus};
  v.window = {-1.0, -1.0, 1.0, 1.0};
  v.nearDistance = 0.01;
  Camera c = cameraFocusedOnViewPlane(v, apertureRadius, "vignetting test");
  c.lens.effects.distortion.k1 = k1;
  c.lens.effects.vignetting = kLens;
  return c;
}

// An unlit wall on the plane of focus covering normalised |x|, |y| ≤ 0.2; the background round it.
Scene flatScene() {
  Scene scene;
  scene.source = "flat wall";
  scene.lighting.background = kBackground;
  addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -kFocus)), 0.4, 0.4, kWall);
  return scene;
}

glm::dvec2 filmPosition(const Camera& camera, int x, int y, ImageSize size) {
  return normalisedFromWindow(camera.view,
                              windowFromPixel(camera.view.window, {x + 0.5, y + 0.5}, size.widthPx, size.heightPx));
}

// The largest |pixel − colour · gain(r_d²)| over the pixels well inside the wall or well inside
// the background (away from its edge, where pixels mix the two). The wall's edge is at undistorted
// 0.2; barrel distortion (k1 < 0) only draws a distorted position inward of its true one.
double worstAgainstGain(const Image& image, const Camera& camera, ImageSize size, int* checked) {
  double worst = 0.0;
  *checked = 0;
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      const glm::dvec2 n = filmPosition(camera, x, y, size);
      const double m = std::max(std::abs(n.x), std::abs(n.y));
      glm::vec3 colour;
      if (m < 0.12)
        colour = kWall;
      else if (m > 0.3)
        colour = kBackground;
      else
        continue;
      ++*checked;
      const double gain = camera.lens.effects.vignetting.gain(glm::dot(n, n));
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(image.at(x, y)[c] - colour[c] * gain));
    }
  return worst;
}

struct Case {
  const char* name;
  double k1;
  double apertureRadius;
  int samples;
  bool adaptive;
};

class VignettingFrames : public ::testing::TestWithParam<Case> {};

TEST_P(VignettingFrames, EveryPixelIsTimesTheGainAtItsPlaceOnTheFilm) {
  LENSLAB_REQUIRE_GL();
  const Case k = GetParam();
  const Scene scene = flatScene();
  const Camera camera = flatCamera(k.k1, k.apertureRadius);
  const ImageSize size{49, 49};  // odd: the centre pixel's centre is the principal point
  PlanOptions options{AperturePattern::Sobol, k.samples, k.samples, 3};
  if (k.adaptive) options.targetPsnrDb = 40.0;
  const FramePlan plan = makeFramePlan(scene, camera, size, options);
  ASSERT_TRUE(plan.vignetting);
  // Multiplied in by the resolve of many views, else a pass of its own.
  const bool inResolve = k.samples > 1 && !k.adaptive;
  ASSERT_EQ(plan.passes.back().name == "vignetting", !inResolve);
  ASSERT_EQ(plan.remap, k.k1 != 0.0);
  Renderer renderer(scene);
  renderer.begin(camera, plan, size);
  renderer.complete();
  const Image raster = renderer.resolve();
  // Resolving again applies the gain once, not twice (progressive frames resolve often).
  EXPECT_EQ(compareImages(raster, renderer.resolve(), 0.0).maxAbs, 0.0);
  const Image raycast = RayCaster(scene).render(camera, size, RaycastOptions{64, 4});
  Camera unvignetted = camera;
  unvignetted.lens.effects.vignetting = {};
  const Image plain = renderer.render(unvignetted, makeFramePlan(scene, unvignetted, size, options), size);

  int checked = 0;
  const double worstRaster = worstAgainstGain(raster, camera, size, &checked);
  const double worstRaycast = worstAgainstGain(raycast, camera, size, &checked);
  const double psnr = compareImages(raster, raycast, 0.0).psnrDb;
  const double plainDb = compareImages(plain, raycast, 0.0).psnrDb;
  const glm::vec4 centre = raster.at(24, 24), corner = raster.at(0, 0);
  const double cornerGain = kLens.gain(glm::dot(filmPosition(camera, 0, 0, size), filmPosition(camera, 0, 0, size)));
  std::cout << "[ measure  ] " << k.name << ": " << checked << " flat pixels, worst |pixel - colour x gain| raster "
            << worstRaster << ", ray cast " << worstRaycast << "; raster vs ray cast " << psnr
            << " dB (without vignetting " << plainDb << " dB); corner " << corner.g << " for "
            << kBackground.g * cornerGain << "\n";
  EXPECT_GT(checked, 1000);
  EXPECT_LT(worstRaster, 2e-3);
  EXPECT_LT(worstRaycast, 2e-3);
  // The centre keeps its light; the corner (background) is darkened by the analytic gain.
  EXPECT_NEAR(centre.g, kWall.g, 1e-3);
  EXPECT_LT(cornerGain, 0.8);
  EXPECT_NEAR(corner.g, kBackground.g * cornerGain, 2e-3);
  EXPECT_NEAR(corner.r, corner.b, 1e-6);  // the same gain for every channel
  // Raster and ray cast agree (the wall's edge pixels differ by their sampling), and both far
  // better than the raster without vignetting does with the ray cast.
  EXPECT_GE(psnr, k.samples > 1 ? 35.0 : 25.0);
  EXPECT_LT(plainDb, psnr - 5.0);
}

INSTANTIATE_TEST_SUITE_P(Paths, VignettingFrames,
                         ::testing::Values(Case{"OneView", 0.0, 0.0, 1, false},
                                           Case{"OneViewThroughTheLensRemap", -0.25, 0.0, 1, false},
                                           Case{"ResolvedViews", 0.0, 0.05, 64, false},
                                           Case{"LensGather", -0.25, 0.05, 64, false},
                                           Case{"PerTileBudgets", 0.0, 0.05, 64, true}),
                         [](const ::testing::TestParamInfo<Case>& param) { return std::string(param.param.name); });

// A tile knows where its pixels sit in the whole image: its sub-window camera gives the gain's
// positions, so the tiled frame is the same image as one render (tiling_test's 60 dB).
TEST(VignettingTiles, ATiledFrameEqualsOneRender) {
  LENSLAB_REQUIRE_GL();
  const Scene scene = flatScene();
  for (const double k1 : {0.0, -0.25}) {
    const Camera camera = flatCamera(k1, 0.05);
    const ImageSize size{200, 200};
    const FramePlan plan = makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, 16, 16, 3});
    const TilePlan tiles = planTiles(camera, size, plan, queryRenderTargetLimits(), 64);
    ASSERT_TRUE(tiles.tiled);
    Renderer renderer(scene);
    const Image untiled = renderer.render(camera, plan, size);
    const Image tiled = renderTiled(renderer, camera, plan, size, tiles);
    const double psnr = compareImages(untiled, tiled, 0.0).psnrDb;
    std::cout << "[ measure  ] k1 = " << k1 << ", " << tiles.tiles.size() << " tiles: tiled vs one render " << psnr
              << " dB\n";
    EXPECT_GE(psnr, 60.0);
  }
}

}  // namespace
}  // namespace lenslab
