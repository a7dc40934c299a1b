// Views added straight into the sum (render/Accumulator.h): each pixel gets each view's visible
// surface once, and a constant colour comes out to float precision.
#include "camera/Camera.h"
#include "camera/Projection.h"
#include "../common/gl_test_context.h"
#include "io/CameraJson.h"
#include "io/ImageCompare.h"
#include "plan/FramePlan.h"
#include "render/Accumulator.h"
#include "render/GpuScene.h"
#include "render/Renderer.h"
#include "render/ScenePass.h"
#include "scene/GltfLoader.h"
#include "scene/ProceduralScenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace lenslab {
namespace {

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

// Unlit quads of one colour each, `halfSize` wide, at the given depths, in the order given.
Scene quadsAt(const std::vector<std::pair<double, glm::vec3>>& quads, double halfSize, glm::vec3 background) {
  Scene scene;
  scene.source = "quads";
  scene.lighting.background = background;
  for (const auto& [depth, colour] : quads) {
    Material m;
    m.unlit = true;
    m.baseColorFactor = glm::vec4(colour, 1.0f);
    scene.materials.push_back(m);
    const int index = static_cast<int>(scene.materials.size()) - 1;
    scene.meshes.push_back(quadMesh(halfSize, halfSize, index));
    scene.instances.push_back({index, glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -depth))});
  }
  scene.bounds = computeBounds(scene);
  return scene;
}

// Within float's rounding of a sum of up to 64 views of `expected` (each add rounds by up to half
// an ulp: 2e-6 is 32 ulps near 1). Half-float views (2^-11, 0.9 as 0.8999) fail by far.
void expectExact(glm::vec4 got, glm::vec3 expected, float alpha, const char* where) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 2e-6f) << where << " channel " << c;
  EXPECT_NEAR(got.a, alpha, 2e-6f) << where << " alpha";
}

TEST(AddedViews, AConstantBackgroundAndAConstantSurfaceComeOutToFloatPrecision) {
  LENSLAB_REQUIRE_GL();
  // 0.9 is what half-float layers put at 0.8999.
  const glm::vec3 background(0.9f, 0.7f, 0.1f), surface(0.3f, 0.6f, 0.9f);
  const Scene scene = quadsAt({{4.0, surface}}, 0.5, background);
  const Camera camera = lensCamera(4.0, 0.2);
  const ImageSize size{64, 64};
  Renderer renderer(scene);
  const Image image = renderer.render(
      camera, makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, 61, 61, 1}), size);
  expectExact(image.at(32, 32), surface, 1.0f, "the in-focus quad's middle");
  expectExact(image.at(1, 1), background, 0.0f, "the background's corner");
}

TEST(AddedViews, AnOccludedSurfaceAddsNothingWhicheverIsDrawnFirst) {
  LENSLAB_REQUIRE_GL();
  const glm::vec3 background(0.1f), front(0.8f, 0.2f, 0.1f), back(0.1f, 0.9f, 0.3f);
  const Camera camera = lensCamera(2.0, 0.05);
  const ImageSize size{64, 64};
  const FramePlan plan = makeFramePlan(quadsAt({{2.0, front}}, 0.5, background), camera, size,
                                       PlanOptions{AperturePattern::Concentric, 16, 16, 1});
  // Back to front (the back quad passes the depth test first) and front to back.
  for (const bool backFirst : {true, false}) {
    const Scene scene = backFirst ? quadsAt({{3.0, back}, {2.0, front}}, 0.5, background)
                                  : quadsAt({{2.0, front}, {3.0, back}}, 0.5, background);
    Renderer renderer(scene);
    const Image image = renderer.render(camera, plan, size);
    expectExact(image.at(32, 32), front, 1.0f, backFirst ? "back drawn first" : "front drawn first");
  }
}

TEST(AddedViews, TwoSurfacesAtTheSameDepthAddOnce) {
  LENSLAB_REQUIRE_GL();
  // The same quad twice, in the same place: a plain pass keeps the first (GREATER); an added
  // view must add one of them, not both.
  const glm::vec3 background(0.2f), colour(0.25f, 0.5f, 0.75f);
  const Scene scene = quadsAt({{2.0, colour}, {2.0, colour}}, 0.5, background);
  const Camera camera = lensCamera(2.0, 0.05);
  const ImageSize size{64, 64};
  Renderer renderer(scene);
  const Image image = renderer.render(
      camera, makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, 16, 16, 1}), size);
  expectExact(image.at(32, 32), colour, 1.0f, "the doubled quad's middle");
}

// The bundled rows scene, 16 views: added into the sum and drawn in layers, with channel masks
// and a region of boxes (the per-tile budgets' way), give the same sums.
TEST(AddedViews, MatchTheLayeredViewsWithChannelMasksAndRegions) {
  LENSLAB_REQUIRE_GL();
  const Scene scene = loadGltf(std::string(LENSLAB_TEST_ASSET_DIR) + "/rows/rows.gltf");
  const Camera camera = loadCameraJson(std::string(LENSLAB_TEST_ASSET_DIR) + "/rows/camera-dof.json").camera;
  const ImageSize size{160, 96};
  GpuScene gpuScene(scene);
  ScenePass pass;
  const std::vector<PixelBox> region{{0, 0, 64, 96}, {96, 32, 64, 64}};
  const std::vector<glm::vec3> masks{glm::vec3(1.0f), {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const auto sums = [&](bool layered) {
    Accumulator sum;
    sum.setLayered(layered);
    sum.start(size.widthPx, size.heightPx);
    EXPECT_EQ(sum.addsViews(), !layered);
    for (int i = 0; i < 16; ++i) {
      if (i == 8) sum.setRegion(&region);
      ViewSpec v = camera.view;
      v.prp.x += 0.01 * (i % 4 - 1.5);  // a different PRP per view: different occlusions
      const Accumulator::View view = sum.nextView(scene.lighting.background, masks[static_cast<std::size_t>(i % 4)]);
      pass.draw(gpuScene, clipFromWorld(v), view.target, 0.0f, i >= 8 ? &region : nullptr,
                view.addWeight ? &*view.addWeight : nullptr);
    }
    gl::RenderTarget out(size.widthPx, size.heightPx);
    sum.setRegion(nullptr);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    Image image(size.widthPx, size.heightPx);
    glGetTextureImage(sum.sumTexture(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(image.rgba.size() * sizeof(float)),
                      image.rgba.data());
    return image;
  };
  const Image added = sums(false), layered = sums(true);
  float worst = 0.0f;
  for (std::size_t i = 0; i < added.rgba.size(); ++i)
    worst = std::max(worst, std::abs(added.rgba[i] - layered.rgba[i]));
  // Sums of up to 16 views of values up to about 1: float's rounding of them, and the odd edge
  // pixel where EQUAL and GREATER see a triangle's edge alike but the order of adds differs.
  EXPECT_LT(worst, 1e-4f);
}

// A narrow field (ScenePass's double-precision path, with its geometry shader): the checker quad
// seen through a window 2e-3 wide from 4 away, added and layered alike.
TEST(AddedViews, MatchTheLayeredViewsInANarrowField) {
  LENSLAB_REQUIRE_GL();
  const Scene scene =
      quadsAt({{4.0, glm::vec3(0.7f, 0.3f, 0.2f)}, {4.5, glm::vec3(0.2f, 0.3f, 0.9f)}}, 0.0006, glm::vec3(0.5f));
  Camera camera = lensCamera(4.0, 1e-4);
  camera.view.window = {-1e-3, -1e-3, 1e-3, 1e-3};
  ASSERT_TRUE(isNarrowField(clipFromWorld(camera.view)));
  const ImageSize size{64, 64};
  GpuScene gpuScene(scene);
  ScenePass pass;
  const auto sums = [&](bool layered) {
    Accumulator sum;
    sum.setLayered(layered);
    sum.start(size.widthPx, size.heightPx);
    for (int i = 0; i < 8; ++i) {
      ViewSpec v = camera.view;
      v.prp.x += 2e-4 * (i - 3.5);  // the front quad hides a different part of the back one
      const Accumulator::View view = sum.nextView(scene.lighting.background);
      pass.draw(gpuScene, clipFromWorld(v), view.target, 0.0f, nullptr, view.addWeight ? &*view.addWeight : nullptr);
    }
    std::vector<float> image(static_cast<std::size_t>(size.widthPx) * size.heightPx * 4);
    glGetTextureImage(sum.sumTexture(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(image.size() * sizeof(float)),
                      image.data());
    return image;
  };
  const std::vector<float> added = sums(false), layered = sums(true);
  float worst = 0.0f, total = 0.0f;
  for (std::size_t i = 0; i < added.size(); ++i) {
    worst = std::max(worst, std::abs(added[i] - layered[i]));
    total += layered[i];
  }
  EXPECT_GT(total, 0.0f);
  EXPECT_LT(worst, 1e-4f);
}

}  // namespace
}  // namespace lenslab
