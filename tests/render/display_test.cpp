// HDR end to end: renders keep linear radiance above 1 all the way to the EXR; the PNG and the
// viewer's display apply the same exposure and view transform (shaders/common/view_transform.glsl,
// compiled as GLSL here and as C++ in io/ToneMap.cpp).
#include "camera/Camera.h"
#include "gl/Framebuffer.h"
#include "gl/ImageTexture.h"
#include "../common/gl_test_context.h"
#include "io/ImageFile.h"
#include "io/ToneMap.h"
#include "plan/FramePlan.h"
#include "raycast/RayCaster.h"
#include "render/ImageDrawer.h"
#include "render/Renderer.h"
#include "scene/ProceduralScenes.h"

#include "../common/temp_dir_test.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

// The display shader against the C++ of the same GLSL, on random linear values from 0 to 16 (a
// quarter below 1, where the toe and the identity part act; the rest through the compression).
TEST(DisplayShader, MatchesTheCpuViewTransformOnRandomValues) {
  LENSLAB_REQUIRE_GL();
  const int w = 64, h = 64;
  Image image(w, h);
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (std::size_t i = 0; i < image.rgba.size(); ++i)
    image.rgba[i] = i % 4 == 3 ? 1.0f : (u(rng) < 0.25f ? u(rng) : 16.0f * u(rng));
  gl::ImageTexture texture(w, h);
  texture.upload(image);
  gl::RenderTarget target(w, h);
  const ImageDrawer drawer;
  for (const DisplayEncoding encoding : {DisplayEncoding{}, DisplayEncoding{std::exp2(1.5f), ViewTransform::None},
                                         DisplayEncoding{1.0f, ViewTransform::PbrNeutral},
                                         DisplayEncoding{std::exp2(-2.0f), ViewTransform::PbrNeutral}}) {
    target.bind();
    drawer.draw(texture, {0, 0, w, h}, 1.0f, encoding);
    const Image shown = target.readColor();
    float worst = 0.0f;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const glm::vec4 in = image.at(x, y);
        const glm::vec3 expected = displayEncoded(glm::vec3(in), encoding);
        const glm::vec4 got = shown.at(x, y);
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(got[c] - expected[c]));
      }
    // Both sides are float: the same operations, with GLSL's pow and division allowed a few ulps.
    EXPECT_LE(worst, 1e-5f) << viewTransformName(encoding.transform) << " at scale " << encoding.exposureScale;
  }
}

// Camera at the origin looking down −z, focused at `focus`, window 2 wide.
Camera lensCamera(double focus, double apertureRadius) {
  ViewSpec v;
  v.vrp = {0.0, 0.0, -focus};
  v.vpn = {0.0, 0.0, 1.0};
  v.prp = {0.0, 0.0, focus};
  v.window = {-1.0, -1.0, 1.0, 1.0};
  v.nearDistance = 0.01;
  return cameraFocusedOnViewPlane(v, apertureRadius, "test");
}

// glTF cannot hold an unlit base colour above 1, so the scene is made here: an emitter-like unlit
// quad of radiance (4, 2, 0.5) filling the middle of the view.
Scene brightQuad(glm::vec3 radiance) {
  Scene scene;
  scene.source = "bright quad";
  scene.lighting.background = glm::vec3(0.0f);
  addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -4.0)), 0.6, 0.6, radiance);
  scene.bounds = computeBounds(scene);
  return scene;
}

// The code value (0 to 255) an 8-bit sRGB file stores for `linear`, and the one it holds for a
// value readImage decoded from it (decoding and encoding again give back the stored byte).
int codeValue(float linear) { return static_cast<int>(std::lround(255.0f * srgbFromLinear(linear))); }

class HdrOutput : public test::TempDirTest {};

TEST_F(HdrOutput, TheRasterizersExrKeepsRadianceAboveOneAndThePngIsExposed) {
  LENSLAB_REQUIRE_GL();
  const glm::vec3 radiance(4.0f, 2.0f, 0.5f);
  const Scene scene = brightQuad(radiance);
  const Camera camera = lensCamera(4.0, 0.05);
  const ImageSize size{32, 32};
  Renderer renderer(scene);
  // Several aperture samples: the accumulation and its resolve must not clamp either.
  Image image = renderer.render(
      camera, makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, 8, 8, 1}), size);
  writeImage(dir_ / "a.exr", image);
  const glm::vec4 centre = readImage(dir_ / "a.exr").at(16, 16);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], radiance[c], 1e-4f) << "channel " << c;

  // −2 EV: (1, 0.5, 0.125), each within the clip.
  const DisplayEncoding minusTwo{std::exp2(-2.0f), ViewTransform::None};
  applyDisplayForFile(dir_ / "a.png", image, minusTwo);
  writeImage(dir_ / "a.png", image);
  const glm::vec4 shown = readImage(dir_ / "a.png").at(16, 16);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(codeValue(shown[c]), codeValue(radiance[c] / 4.0f), 1) << "channel " << c;
}

TEST_F(HdrOutput, TheLensPassKeepsRadianceAboveOne) {
  LENSLAB_REQUIRE_GL();
  // Distortion and lateral colour: the remap pass between the accumulation and the image.
  const glm::vec3 radiance(4.0f, 2.0f, 0.5f);
  const Scene scene = brightQuad(radiance);
  Camera camera = lensCamera(4.0, 0.05);
  camera.lens.effects.distortion.k1 = -0.05;
  camera.lens.effects.chromatic.lateralRed = 0.002;
  camera.lens.effects.chromatic.lateralBlue = -0.002;
  ASSERT_TRUE(camera.lens.effects.needsRemap());
  const ImageSize size{32, 32};
  Renderer renderer(scene);
  const Image image = renderer.render(
      camera, makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, 8, 8, 1}), size);
  writeImage(dir_ / "l.exr", image);
  const glm::vec4 centre = readImage(dir_ / "l.exr").at(16, 16);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], radiance[c], 1e-4f) << "channel " << c;
}

TEST_F(HdrOutput, TheRayCastersImageKeepsRadianceAboveOne) {
  const glm::vec3 radiance(4.0f, 2.0f, 0.5f);
  const Scene scene = brightQuad(radiance);
  const RayCaster caster(scene);
  const Image image = caster.render(lensCamera(4.0, 0.05), {16, 16}, RaycastOptions{4, 1});
  writeImage(dir_ / "r.exr", image);
  const glm::vec4 centre = readImage(dir_ / "r.exr").at(8, 8);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], radiance[c], 1e-4f) << "channel " << c;
}

}  // namespace
}  // namespace lenslab
