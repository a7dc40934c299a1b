// The rasterizer against the CPU ray-cast reference: same Camera, Scene and shading, so what
// remains is each method's error (sampling noise, texture-filter approximations).
#include "../common/blend_scene.h"
#include "camera/PhysicalCamera.h"
#include "core/Error.h"
#include "../common/gl_test_context.h"
#include "io/CameraJson.h"
#include "io/EnvironmentFile.h"
#include "io/ImageCompare.h"
#include "plan/FramePlan.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "scene/EnvironmentPrefilter.h"
#include "scene/GltfLoader.h"
#include "scene/Scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

// One scene through one camera both ways: the rasterizer's image and the ray caster's.
struct BothWays {
  Image raster;
  Image reference;
  int views = 0;  // the raster's views: the plan's aperture samples, which may be fewer than asked
};

// The raster from `views` jittered (and, with an aperture, lens) samples, the ray cast with `spp`.
BothWays renderBothWays(const Scene& scene, const Camera& camera, ImageSize size, int views, int spp) {
  Camera planCamera = camera;
  if (planCamera.lens.isPinhole()) planCamera.lens.apertureRadius = 1e-3;  // only to get a plan with `views` samples
  const FramePlan plan =
      makeFramePlan(scene, planCamera, size, PlanOptions{AperturePattern::Concentric, views, views, 3});
  return {Renderer(scene).render(camera, plan, size), RayCaster(scene).render(camera, size, RaycastOptions{spp, 11}),
          plan.apertureSamples};
}

// `scene` lit by the bundled studio environment too, prefiltered coarser than the default to keep
// the tests short.
void addStudio(Scene& scene) {
  PrefilterSettings settings;
  settings.specularWidth = 64;
  settings.diffuseWidth = 32;
  settings.samplesPerTexel = 64;
  const LoadedEnvironment studio =
      loadEnvironment(fs::path(LENSLAB_TEST_ASSET_DIR) / "environments/studio.hdr", settings, std::nullopt);
  scene.environment = std::make_shared<const EnvironmentLookup>(studio.maps, EnvironmentPlacement{30.0, 0.5f});
}

// `camera` made pinhole, so that what remains is sampling: raster 256 views vs ray cast 256 spp.
// The studio's lamps and the bokeh scene's are HDR (radiance 6), so the PSNR's peak is 1 over the
// images clamped at 1 (the subject's range), as a display would show them.
void expectPinholeAlike(const Scene& scene, Camera camera, ImageSize size, const std::string& what) {
  camera.lens.apertureRadius = 0.0;
  BothWays both = renderBothWays(scene, camera, size, 256, 256);
  for (Image* image : {&both.raster, &both.reference})
    for (float& v : image->rgba) v = std::min(v, 1.0f);
  const double psnr = compareImages(both.raster, both.reference, 0.0).psnrDb;
  std::cout << "[ measure  ] " << what << ", pinhole: raster 256 views vs ray cast 256 spp: PSNR " << psnr << " dB\n";
  EXPECT_GE(psnr, 45.0) << what;
}

// Raster with `views` jittered (and, with an aperture, lens) samples vs ray casting with `spp`.
double rasterVsRaycastPsnr(const std::string& sceneName, const std::string& cameraFile, bool pinhole, int views,
                           int spp, ImageSize size) {
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / sceneName);
  Camera camera = loadCameraJson(assets / cameraFile).camera;
  if (pinhole) camera.lens.apertureRadius = 0.0;
  const BothWays both = renderBothWays(scene, camera, size, views, spp);
  const double psnr = compareImages(both.raster, both.reference, 0.0).psnrDb;
  std::cout << "[ measure  ] " << sceneName << (pinhole ? " pinhole" : " thin lens") << ": raster " << views
            << " views vs ray cast " << spp << " spp: PSNR " << psnr << " dB\n";
  return psnr;
}

TEST(RasterVsRaycast, PinholeRows) {
  LENSLAB_REQUIRE_GL();
  EXPECT_GE(rasterVsRaycastPsnr("rows/rows.gltf", "rows/camera.json", true, 256, 256, {240, 160}), 45.0);
}

// The default plan anti-aliases a pinhole frame: with no count asked it draws kAntialiasSamples
// jittered views, the pixel integral the ray caster converges to; one view samples each pixel at
// its centre (jagged edges, moiré on the checker floor).
TEST(RasterVsRaycast, TheDefaultPlanAntialiasesAPinhole) {
  LENSLAB_REQUIRE_GL();
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / "rows/rows.gltf");
  const Camera camera = loadCameraJson(assets / "rows/camera.json").camera;
  const ImageSize size{240, 160};
  const Image reference = RayCaster(scene).render(camera, size, RaycastOptions{256, 11});
  Renderer renderer(scene);
  const FramePlan automatic = makeFramePlan(scene, camera, size);
  ASSERT_EQ(automatic.apertureSamples, kAntialiasSamples) << automatic.samplesWhy;
  const double autoPsnr = compareImages(renderer.render(camera, automatic, size), reference, 0.0).psnrDb;
  const FramePlan one = makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Sobol, 1, 256, 1});
  const double onePsnr = compareImages(renderer.render(camera, one, size), reference, 0.0).psnrDb;
  std::cout << "[ measure  ] rows pinhole 240x160 vs ray cast 256 spp: default plan (" << automatic.apertureSamples
            << " views) " << autoPsnr << " dB, one view " << onePsnr << " dB\n";
  EXPECT_GE(autoPsnr, 36.0);
  EXPECT_GE(autoPsnr - onePsnr, 6.0);
}

// Both images are estimates of the same pixel integral, so their PSNR is bounded by their noise:
// with textures filtered per sample (not per pixel) each carries the texture's own detail, and 256
// ray-cast samples of `rows` through f/1.4 are about 42 dB from converged. Raster views are cheap,
// so the raster takes 1024 and the comparison is bounded by the ray caster's noise.
TEST(RasterVsRaycast, ThinLensRowsAndOccluder) {
  LENSLAB_REQUIRE_GL();
  EXPECT_GE(rasterVsRaycastPsnr("rows/rows.gltf", "rows/camera-dof.json", false, 1024, 256, {240, 160}), 40.0);
  EXPECT_GE(rasterVsRaycastPsnr("occluder/occluder.gltf", "occluder/camera-dof.json", false, 1024, 256, {240, 160}),
            40.0);
}

// Emission (glTF emissiveFactor × KHR_materials_emissive_strength, times the emissive texture) is
// added to the shaded colour by both renderers alike, and kept above 1 in the float image: `rows`
// with its textured materials made to glow (their base colour texture as the emissive one) and
// one unlit material a light of radiance 6.
TEST(RasterVsRaycast, EmissionIsAddedAlikeAndKeptAboveOne) {
  LENSLAB_REQUIRE_GL();
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  Scene scene = loadGltf(assets / "rows/rows.gltf");
  int glowing = 0;
  for (Material& m : scene.materials) {
    if (m.baseColorTexture.present()) {
      m.emissive = glm::vec3(0.5f, 0.25f, 0.125f);
      m.emissiveTexture = m.baseColorTexture;
      ++glowing;
    } else if (m.unlit) {
      m.emissive = glm::vec3(6.0f);
    }
  }
  ASSERT_GT(glowing, 0);
  const Camera camera = loadCameraJson(assets / "rows/camera.json").camera;
  ASSERT_TRUE(camera.lens.isPinhole());
  const BothWays both = renderBothWays(scene, camera, {240, 160}, 256, 128);
  const Image& raster = both.raster;
  const Image& reference = both.reference;
  float brightest = 0.0f;
  for (std::size_t i = 0; i < raster.rgba.size(); i += 4) brightest = std::max(brightest, raster.rgba[i + 1]);
  // PSNR with the peak at the brightest value: the images are HDR.
  double mse = 0.0;
  for (std::size_t i = 0; i < raster.rgba.size(); ++i)
    if (i % 4 != 3) mse += (raster.rgba[i] - reference.rgba[i]) * (raster.rgba[i] - reference.rgba[i]);
  mse /= 0.75 * static_cast<double>(raster.rgba.size());
  const double psnr = 10.0 * std::log10(brightest * brightest / mse);
  std::cout << "[ measure  ] rows glowing: brightest " << brightest << ", raster vs ray cast PSNR (peak the brightest) "
            << psnr << " dB\n";
  EXPECT_GT(brightest, 5.0f) << "radiance above 1 is kept";
  EXPECT_GE(psnr, 45.0);
}

// The bundled bokeh scene's subject carries every map lenslab reads (base colour through a texture
// transform, metallic-roughness, normal, occlusion on TEXCOORD_1) beside metal and dielectric
// spheres, lit by a spot light, a sun and the ambient; both renderers shade it alike, pinhole.
void expectEveryMapAlike(const Scene& scene, const std::string& what) {
  const Camera camera = loadCameraJson(fs::path(LENSLAB_TEST_ASSET_DIR) / "bokeh/camera.json").camera;
  expectPinholeAlike(scene, camera, {240, 160}, "bokeh subject, every map, " + what);
}

TEST(RasterVsRaycast, EveryMapAndLightOnTheBokehSubject) {
  LENSLAB_REQUIRE_GL();
  expectEveryMapAlike(loadGltf(fs::path(LENSLAB_TEST_ASSET_DIR) / "bokeh/bokeh.gltf"), "its lights");
}

// The same lit by the bundled studio environment as well: its diffuse and specular light and its
// background, through both.
TEST(RasterVsRaycast, EveryMapAndLightOnTheBokehSubjectInTheStudio) {
  LENSLAB_REQUIRE_GL();
  Scene scene = loadGltf(fs::path(LENSLAB_TEST_ASSET_DIR) / "bokeh/bokeh.gltf");
  addStudio(scene);
  expectEveryMapAlike(scene, "the studio");
}

// A scene and its camera moved far from the world origin render as they do at the origin: Embree
// gets float coordinates, so the ray caster keeps its geometry relative to the point of the
// scene's bounds nearest the camera (subtracted in double). Before that, `rows` moved by 1e6 lost a column (22.5 dB), by 1e7 18.5 dB.
TEST(RaycastPrecision, ASceneFarFromTheOriginRendersAsAtTheOrigin) {
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / "rows/rows.gltf");
  const Camera camera = loadCameraJson(assets / "rows/camera-dof.json").camera;
  const ImageSize size{160, 107};
  const RaycastOptions options{16, 5};
  const Image atOrigin = RayCaster(scene).render(camera, size, options);
  for (const double distance : {1e6, 1e7, 1e8}) {
    const glm::dvec3 offset(distance, 0.25 * distance, -0.5 * distance);
    Scene moved = scene;
    for (Instance& instance : moved.instances)
      instance.worldFromModel = glm::translate(glm::dmat4(1.0), offset) * instance.worldFromModel;
    moved.bounds = computeBounds(moved);
    Camera far = camera;
    far.view.vrp += offset;
    const double psnr = compareImages(RayCaster(moved).render(far, size, options), atOrigin, 0.0).psnrDb;
    std::cout << "[ measure  ] rows + camera-dof.json moved by " << distance << ": ray cast vs at the origin " << psnr
              << " dB\n";
    EXPECT_GE(psnr, 45.0) << "moved by " << distance;
  }
}

// A camera whose rays overflow (a channel focused at 1e-200 shifts each lens view's window by
// 1e200 aperture radii: directions normalise to zero) is a clear error, never Embree's assertion
// (an abort). Camera files refuse such a plane of focus; this camera is built past that check.
TEST(RaycastPrecision, RaysThatOverflowAreAnErrorNotAnAbort) {
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / "rows/rows.gltf");
  for (const bool curvature : {false, true}) {
    Camera camera = loadCameraJson(assets / "rows/camera-dof.json").camera;
    (curvature ? camera.lens.effects.fieldCurvature.inverseFocusPerRadius2
               : camera.lens.effects.chromatic.inverseFocusShiftRed) = 1e200;
    try {
      RayCaster(scene).render(camera, {24, 16}, RaycastOptions{2, 1});
      ADD_FAILURE() << "rendered" << (curvature ? " (field curvature)" : " (axial colour)");
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("rays that are not finite numbers"), std::string::npos) << e.what();
    }
  }
}

// alphaMode BLEND through both renderers: four blend quads at different depths in front of an
// opaque lit wall (two textured with alpha running from 0 to 1, one emissive, lit and unlit).
// The ray caster composites along each ray; the rasterizer draws the quads back to front over
// each view. The quads do not interpenetrate and lie apart in depth, so the back-to-front order
// is exact for every view and what remains is sampling.
Scene blendQuads() {
  Scene scene;
  scene.source = "blend quads";
  const int texture = test::addAlphaTexture(scene);
  const int wall = test::addMaterial(scene, {0.6f, 0.55f, 0.5f, 1.0f}, false, false);
  const int red = test::addMaterial(scene, {0.8f, 0.3f, 0.2f, 0.5f}, false);
  const int cells = test::addMaterial(scene, {1.0f, 1.0f, 1.0f, 0.9f}, false);
  scene.materials[static_cast<std::size_t>(cells)].baseColorTexture.texture = texture;
  const int glow = test::addMaterial(scene, {0.2f, 0.7f, 0.3f, 0.35f}, true);
  scene.materials[static_cast<std::size_t>(glow)].emissive = glm::vec3(0.6f, 0.5f, 0.1f);
  const int unlitCells = test::addMaterial(scene, {0.9f, 0.9f, 1.0f, 1.0f}, true);
  scene.materials[static_cast<std::size_t>(unlitCells)].baseColorTexture.texture = texture;
  // In no particular order: the rasterizer sorts them.
  test::addQuad(scene, {0.04, -0.02, 0.0}, 0.1, 0.08, cells);
  test::addQuad(scene, {-0.03, -0.04, -0.28}, 0.08, 0.07, unlitCells);
  test::addQuad(scene, {-0.05, 0.03, 0.15}, 0.08, 0.06, red);
  test::addQuad(scene, {0.12, 0.0, -0.45}, 0.2, 0.5, wall);  // the left of the image shows the background
  test::addQuad(scene, {0.06, 0.05, -0.14}, 0.09, 0.05, glow);
  return scene;
}

// f/2, focused on the middle quad.
Camera blendQuadsCamera() {
  PhysicalCamera c;
  c.eye = {0.02, 0.0, 1.0};
  c.target = {0.0, 0.0, 0.0};
  c.focalLengthMm = 85.0;
  c.fNumber = 2.0;
  c.focusDistance = 1.0;
  return toCamera(c, "blend test camera");
}

// The coverage alpha (1 − Π(1 − alpha) where the wall does not show) agrees too.
TEST(RasterVsRaycast, BlendedQuadsThroughTheThinLens) {
  LENSLAB_REQUIRE_GL();
  const Scene scene = blendQuads();
  const Camera camera = blendQuadsCamera();
  ASSERT_FALSE(camera.lens.isPinhole());
  const BothWays both = renderBothWays(scene, camera, {120, 80}, 256, 256);
  ASSERT_EQ(both.views, 256);
  const Image& raster = both.raster;
  const Image& reference = both.reference;
  const double psnr = compareImages(raster, reference, 0.0).psnrDb;
  double alphaSquared = 0.0, lowestAlpha = 1.0;
  for (std::size_t i = 3; i < raster.rgba.size(); i += 4) {
    alphaSquared += (raster.rgba[i] - reference.rgba[i]) * (raster.rgba[i] - reference.rgba[i]);
    lowestAlpha = std::min(lowestAlpha, static_cast<double>(reference.rgba[i]));
  }
  const double alphaPsnr = -10.0 * std::log10(alphaSquared / (0.25 * static_cast<double>(raster.rgba.size())));
  std::cout << "[ measure  ] blend quads f/2: raster 256 views vs ray cast 256 spp: PSNR " << psnr << " dB, alpha "
            << alphaPsnr << " dB\n";
  EXPECT_GE(psnr, 45.0);
  EXPECT_GE(alphaPsnr, 45.0);
  EXPECT_LT(lowestAlpha, 0.9) << "the test must see the background through a blend quad";
}

// The same quads in the studio environment: its background behind them, its light on them.
TEST(RasterVsRaycast, BlendedQuadsInTheStudio) {
  LENSLAB_REQUIRE_GL();
  Scene scene = blendQuads();
  addStudio(scene);
  expectPinholeAlike(scene, blendQuadsCamera(), {120, 80}, "blend quads in the studio");
}

}  // namespace
}  // namespace lenslab
