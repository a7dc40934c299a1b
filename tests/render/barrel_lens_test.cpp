// The lens barrel (cat's-eye vignetting) through a lens that distorts the image and moves the
// colours apart. The barrel stops rays, and the rays are the thin lens's: from an aperture point
// toward the plane of focus along the true perspective (undistorted) direction; the distortion and
// lateral colour only move where on the film each ray lands. So a pixel's cat's eye is the one of
// its undistorted field position, per colour channel, in both renderers: checked in closed form on
// a wall in focus, and raster against ray cast on a scene with depth of field.
#include "camera/Camera.h"
#include "camera/ImageMap.h"
#include "camera/LensMap.h"
#include "camera/Projection.h"
#include "core/Text.h"
#include "../common/gl_test_context.h"
#include "io/CameraJson.h"
#include "io/ImageCompare.h"
#include "lens/LensBarrel.h"
#include "plan/FramePlan.h"
#include "plan/TilePlan.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "render/TiledRender.h"
#include "scene/GltfLoader.h"
#include "scene/ProceduralScenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace lenslab {
namespace {

constexpr double kFocus = 2.0;

// Camera at the origin looking down −z, focused on its view plane at kFocus, window 2 wide
// (normalised coordinates ±0.5), aperture radius 0.1 and a barrel {0.2, 0.13}: seen in the
// opening's plane the aperture has radius 0.09 about 0.2·n, whole at the centre, half or less
// past |n| = 0.65, the corners of the undistorted field. `k1` distorts (< 0: barrel, > 0:
// pincushion); red and blue are magnified by ∓`lateral`.
Camera wallCamera(double k1, double lateral) {
  ViewSpec v;
  v.vrp = {0.0, 0.0, -kFocus};
  v.vpn = {0.0, 0.0, 1.0};
  v.prp = {0.0, 0.0, kFocus};
  v.window = {-1.0, -1.0, 1.0, 1.0};
  v.nearDistance = 0.01;
  Camera c = cameraFocusedOnViewPlane(v, 0.1, "barrel lens test");
  c.lens.barrel = LensBarrel{0.2, 0.13};
  c.lens.effects.distortion.k1 = k1;
  c.lens.effects.chromatic.lateralRed = -lateral;
  c.lens.effects.chromatic.lateralBlue = lateral;
  return c;
}

// An unlit white wall on the plane of focus, wider than any undistorted field the tests see:
// every aperture point sees the same white at every pixel, so a channel's value at a pixel is the
// share of the aperture the barrel lets through from that channel's ray direction.
Scene whiteWall() {
  Scene scene;
  scene.source = "white wall";
  scene.lighting.background = glm::vec3(0.0f);
  addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -kFocus)), 6.0, 6.0, glm::vec3(1.0f));
  return scene;
}

struct WallCase {
  const char* name;
  double k1;
  double lateral;
};

class CatsEyeThroughALens : public ::testing::TestWithParam<WallCase> {};

// (b) Each pixel of each channel has the two circles' overlap computed at that channel's
// undistorted field position (the pixel centre's; the overlap varies little over a pixel), not at
// the distorted one: at the corners the two differ by several times the tolerance.
TEST_P(CatsEyeThroughALens, APixelSeesTheOverlapAtItsUndistortedFieldPosition) {
  LENSLAB_REQUIRE_GL();
  const WallCase wall = GetParam();
  const Scene scene = whiteWall();
  const Camera camera = wallCamera(wall.k1, wall.lateral);
  const ImageSize size{48, 48};
  Renderer renderer(scene);
  const FramePlan plan = makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Sobol, 1024, 1024, 3});
  ASSERT_TRUE(plan.remap);
  const Image raster = renderer.render(camera, plan, size);
  const Image raycast = RayCaster(scene).render(camera, size, RaycastOptions{1024, 4});
  const auto shareAt = [&](glm::dvec2 n) {
    return roundApertureThroughBarrel(camera.lens.barrel, camera.lens.apertureRadius, n, camera.inverseFocusDistance());
  };
  const ThinLensMap lensMap(camera, size);
  double worstRaster = 0.0, worstRaycast = 0.0, cornerGap = 0.0;
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x)
      for (const Channel c : {Channel::Red, Channel::Green, Channel::Blue}) {
        const glm::dvec2 pixel(x + 0.5, y + 0.5);
        const double share = shareAt(lensMap.undistorted(c, pixel).normalised);
        const int k = static_cast<int>(c);
        worstRaster = std::max(worstRaster, std::abs(static_cast<double>(raster.at(x, y)[k]) - share));
        worstRaycast = std::max(worstRaycast, std::abs(static_cast<double>(raycast.at(x, y)[k]) - share));
        const glm::dvec2 distorted =
            (windowFromPixel(camera.view.window, pixel, size.widthPx, size.heightPx) - glm::dvec2(camera.view.prp)) /
            camera.view.prp.z;
        cornerGap = std::max(cornerGap, std::abs(shareAt(distorted) - share));
      }
  const double corner = shareAt(lensMap.undistorted(Channel::Green, {0.5, 0.5}).normalised);
  std::printf(
      "  %s: corner share %.3f; worst |image - overlap at the undistorted position| raster %.4f, ray cast %.4f; "
      "overlap at the distorted position differs by up to %.3f\n",
      wall.name, corner, worstRaster, worstRaycast, cornerGap);
  EXPECT_GT(cornerGap, 0.1) << "the test's lens should move the cat's eye by more than the tolerance";
  EXPECT_GT(corner, 0.02) << "the corner should be clipped, not dark";
  EXPECT_LT(corner, 0.6) << "the corner should be clipped";
  EXPECT_LT(worstRaster, 0.03);
  EXPECT_LT(worstRaycast, 0.03);
}

INSTANTIATE_TEST_SUITE_P(Lenses, CatsEyeThroughALens,
                         ::testing::Values(WallCase{"barrel distortion", -0.25, 0.02},
                                           WallCase{"pincushion", 0.3, 0.02}),
                         [](const ::testing::TestParamInfo<WallCase>& param) {
                           return param.param.k1 < 0.0 ? "Barrel" : "Pincushion";
                         });

// Field curvature focuses each radius r at 1/z_f + κr²: the ray from p toward the curved surface
// crosses the opening at p·(1 − L·(1/z_f + κr²)) + L·n. The raster draws flat-focused views and
// shows at x what a view has at x − shift·r²; that flat ray is the same line from p, so the mask
// must be tested there (accumulate.frag without distortion, gather_lens.frag with it). On the
// white wall the pixel's value is then the overlap for the curved focus at its undistorted position.
class CatsEyeOnACurvedFocus : public ::testing::TestWithParam<double> {};

TEST_P(CatsEyeOnACurvedFocus, APixelSeesTheOverlapForItsRadiusFocus) {
  LENSLAB_REQUIRE_GL();
  const Scene scene = whiteWall();
  Camera camera = wallCamera(GetParam(), 0.0);
  camera.lens.effects.fieldCurvature.inverseFocusPerRadius2 = 1.0;  // the corners (r² = 0.5) focus at 1 m
  // An opening far out (0.6 in front, radius 0.4), where the focus moves the aperture's image in
  // its plane most: radius 0.1·(1 − 0.6·(0.5 + r²)), 0.07 flat; clipped past r ≈ 0.55. At r = 0.7
  // the overlap is 0.19 for the curved focus, 0.31 for the flat one.
  camera.lens.barrel = LensBarrel{0.6, 0.4};
  const ImageSize size{48, 48};
  Renderer renderer(scene);
  const FramePlan plan = makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Sobol, 1024, 1024, 3});
  ASSERT_TRUE(plan.fieldCurvature);
  const Image raster = renderer.render(camera, plan, size);
  const Image raycast = RayCaster(scene).render(camera, size, RaycastOptions{1024, 4});
  const ThinLensMap lensMap(camera, size);
  double worstRaster = 0.0, worstRaycast = 0.0, flatGap = 0.0;
  const double inverseFocus = camera.inverseFocusDistance();
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      // The overlap changes fast across the clipped band: its mean over 4 × 4 points of the pixel.
      double share = 0.0, flat = 0.0;
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
          const ChannelSample s = lensMap.undistorted(Channel::Green, {x + (i + 0.5) / 4.0, y + (j + 0.5) / 4.0});
          share += roundApertureThroughBarrel(camera.lens.barrel, camera.lens.apertureRadius, s.normalised,
                                              inverseFocus + s.inverseFocusShift) /
                   16.0;
          flat +=
              roundApertureThroughBarrel(camera.lens.barrel, camera.lens.apertureRadius, s.normalised, inverseFocus) /
              16.0;
        }
      flatGap = std::max(flatGap, std::abs(flat - share));
      worstRaster = std::max(worstRaster, std::abs(static_cast<double>(raster.at(x, y).g) - share));
      worstRaycast = std::max(worstRaycast, std::abs(static_cast<double>(raycast.at(x, y).g) - share));
    }
  std::printf(
      "  k1 %.2f: worst |image - overlap for the curved focus| raster %.4f, ray cast %.4f; the flat focus's overlap "
      "differs by up to %.3f\n",
      GetParam(), worstRaster, worstRaycast, flatGap);
  EXPECT_GT(flatGap, 0.06) << "the curvature should change the cat's eye by more than the tolerance";
  EXPECT_LT(worstRaster, 0.03);
  EXPECT_LT(worstRaycast, 0.03);
}

INSTANTIATE_TEST_SUITE_P(Lenses, CatsEyeOnACurvedFocus, ::testing::Values(0.0, -0.25),
                         [](const ::testing::TestParamInfo<double>& param) {
                           return param.param < 0.0 ? "Distorted" : "Straight";
                         });

// (a) The bundled rows scene through a 35 mm f/2.8 lens focused at 2 m, with a barrel that clips
// the corners, strong distortion, lateral and axial colour and field curvature: the raster (each
// view's samples masked at their own rays as the lens gather sums them) converges to the ray
// caster's exact lens. As lens_effects_test's comparison: the ray caster's noise is measured (two
// independent casts) and taken out.
std::string rowsCamera(double k1) {
  return cat(R"({"eye": [0, 1, 3], "target": [0, 0.55, -2], "up": [0, 1, 0], "focal_length_mm": 35,
      "sensor_mm": [36, 24], "focus_distance": 2.0, "near": 0.05, "far": "infinity", "f_number": 2.8,
      "distortion": {"k1": )",
             k1, R"(, "k2": 0.0, "p1": 0.001, "p2": -0.0005},
      "chromatic": {"lateral_red": 0.006, "lateral_blue": -0.006, "focus_distance_red": 2.2, "focus_distance_blue": 1.85},
      "field_curvature": {"corner_focus_distance": 1.6},
      "barrel": {"distance_mm": 40, "diameter_mm": 44}})");
}

class BarrelThroughRows : public ::testing::TestWithParam<double> {};

TEST_P(BarrelThroughRows, RasterConvergesToTheExactRayCastLens) {
  LENSLAB_REQUIRE_GL();
  const std::filesystem::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / "rows" / "rows.gltf");
  const Camera camera = parseCameraJson(rowsCamera(GetParam()), "barrel rows camera").camera;
  ASSERT_TRUE(camera.lens.hasBarrel());
  const ImageSize size = resolveImageSize(camera, 120, std::nullopt);
  Renderer renderer(scene);
  const FramePlan plan = makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, 1024, 1024, 1});
  ASSERT_TRUE(plan.remap);
  ASSERT_EQ(plan.viewsPerSample, 3);
  const Image raster = renderer.render(camera, plan, size);
  const RayCaster caster(scene);
  const Image exactA = caster.render(camera, size, RaycastOptions{256, 3});
  const Image exactB = caster.render(camera, size, RaycastOptions{256, 4});
  const double raw = compareImages(raster, exactA, 0.0).rmse, noise = compareImages(exactA, exactB, 0.0).rmse;
  const double corrected = std::sqrt(std::max(raw * raw - 0.5 * noise * noise, 1e-12));
  const double psnr = -20.0 * std::log10(corrected);
  // The barrel matters here: the same raster without it is far from the exact lens with it.
  Camera open = camera;
  open.lens.barrel = {};
  const Image withoutBarrel = renderer.render(
      open, makeFramePlan(scene, open, size, PlanOptions{AperturePattern::Concentric, 256, 256, 1}), size);
  const double withoutDb = compareImages(withoutBarrel, exactA, 0.0).psnrDb;
  std::cout << "[ measure  ] rows, k1 " << GetParam()
            << ", barrel 40/44 mm: raster 1024 views vs exact ray cast 256 spp: " << -20.0 * std::log10(raw)
            << " dB as measured, " << psnr << " dB with the ray caster's noise taken out; " << withoutDb
            << " dB without the barrel\n";
  RecordProperty("psnr_db", cat(psnr));
  EXPECT_GE(psnr, 45.0);
  EXPECT_LT(withoutDb, psnr - 8.0);
}

INSTANTIATE_TEST_SUITE_P(Lenses, BarrelThroughRows, ::testing::Values(-0.3, 0.25),
                         [](const ::testing::TestParamInfo<double>& param) {
                           return param.param < 0.0 ? "Barrel" : "Pincushion";
                         });

// Tiles build their own lens tables and overscan windows; the barrel's mask follows each tile's
// window, so the tiled frame is the same image as one render (as tiling_test's 60 dB).
TEST(BarrelTiles, ATiledFrameWithTheBarrelAndEveryLensEffectEqualsOneRender) {
  LENSLAB_REQUIRE_GL();
  const std::filesystem::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / "rows" / "rows.gltf");
  const Camera camera = parseCameraJson(rowsCamera(-0.3), "barrel rows camera").camera;
  const ImageSize size = resolveImageSize(camera, 200, std::nullopt);
  const FramePlan plan = makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, 16, 16, 3});
  ASSERT_TRUE(plan.remap);
  const TilePlan tiles = planTiles(camera, size, plan, queryRenderTargetLimits(), 64);
  ASSERT_TRUE(tiles.tiled);
  Renderer renderer(scene);
  const Image untiled = renderer.render(camera, plan, size);
  const Image tiled = renderTiled(renderer, camera, plan, size, tiles);
  Camera open = camera;
  open.lens.barrel = {};
  // Its own plan: with distortion the renderer draws the plan's overscan camera, barrel included.
  const Image withoutBarrel = renderer.render(
      open, makeFramePlan(scene, open, size, PlanOptions{AperturePattern::Concentric, 16, 16, 3}), size);
  const double psnr = compareImages(untiled, tiled, 0.0).psnrDb,
               withoutDb = compareImages(untiled, withoutBarrel, 0.0).psnrDb;
  std::cout << "[ measure  ] rows with the barrel and every lens effect, " << tiles.tiles.size()
            << " tiles: tiled vs one render " << psnr << " dB; without the barrel " << withoutDb << " dB\n";
  EXPECT_GE(psnr, 60.0);
  EXPECT_LT(withoutDb, 40.0) << "the barrel should change the image";
}

}  // namespace
}  // namespace lenslab
