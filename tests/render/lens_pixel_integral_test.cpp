// The lens pass integrates each output pixel's pre-image: small squares' centroids at the image's
// own resolution land where the box-filtered OpenCV model puts them, and no pixel leaves the
// range of the scene's values (no ringing, no point-sampling of a band-limited image).
#include "../common/opencv_model.h"
#include "camera/ImageSize.h"
#include "core/Text.h"
#include "../common/gl_test_context.h"
#include "io/CameraJson.h"
#include "plan/FramePlan.h"
#include "render/Renderer.h"
#include "scene/GltfLoader.h"
#include "scene/ProceduralScenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>

namespace lenslab {
namespace {

using test::OpenCvCamera;

constexpr int kWidth = 320, kHeight = 240;
constexpr double kDepth = 3.0;

std::string intrinsicsJson(const OpenCvCamera& c) {
  return cat(R"({"eye": [0, 0, 0], "target": [0, 0, -1], "near": 0.1, "far": 10, "intrinsics": {"fx": )", c.fx,
             R"(, "fy": )", c.fy, R"(, "cx": )", c.cx, R"(, "cy": )", c.cy, R"(, "width": )", kWidth, R"(, "height": )",
             kHeight, R"(}, "distortion": [)", c.k1, ", ", c.k2, ", ", c.p1, ", ", c.p2, ", ", c.k3, "]}");
}

struct Square {
  glm::dvec2 centre;  // normalised, y up
  double half;        // normalised half-size
};

// 4-pixel squares (at the centre's scale) over the image, off the pixel grid by varied fractions.
std::vector<Square> squares(const OpenCvCamera& cv) {
  std::vector<Square> out;
  const double half = 2.0 / cv.fx;
  for (int j = -2; j <= 2; ++j)
    for (int i = -3; i <= 3; ++i) out.push_back({{0.17 * i + 0.0011 * j, 0.19 * j + 0.0007 * i}, half});
  return out;
}

Scene squareScene(const std::vector<Square>& list) {
  Scene scene;
  scene.source = "small squares";
  scene.lighting.background = glm::vec3(0.0f);
  for (const Square& s : list)
    addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(s.centre * kDepth, -kDepth)), s.half * kDepth,
                 s.half * kDepth, glm::vec3(1.0f));
  return scene;
}

// The centroid that a perfect box-filtered image of OpenCV's distorted square has, sampled at the
// pixel centres: the square's area carried through the model (forward, weighted by |det J|) and
// binned into pixels; the centroid of those pixel integrals at the pixel centres.
glm::dvec2 boxFilteredCentroid(const OpenCvCamera& cv, const Square& s) {
  const auto pixel = [&](glm::dvec2 n) { return cv.project({n.x, -n.y, 1.0}) + glm::dvec2(0.5); };
  constexpr int kN = 400;
  const double h = 2.0 * s.half / kN;
  std::map<std::pair<int, int>, double> coverage;
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) {
      const glm::dvec2 n = s.centre + glm::dvec2(-s.half + (i + 0.5) * h, -s.half + (j + 0.5) * h);
      const glm::dvec2 dx = (pixel(n + glm::dvec2(1e-7, 0)) - pixel(n - glm::dvec2(1e-7, 0))) / 2e-7;
      const glm::dvec2 dy = (pixel(n + glm::dvec2(0, 1e-7)) - pixel(n - glm::dvec2(0, 1e-7))) / 2e-7;
      const glm::dvec2 p = pixel(n);
      coverage[{static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y))}] +=
          std::abs(dx.x * dy.y - dx.y * dy.x);
    }
  double total = 0.0;
  glm::dvec2 sum(0.0);
  for (const auto& [at, w] : coverage) {
    total += w;
    sum += w * glm::dvec2(at.first + 0.5, at.second + 0.5);
  }
  return sum / total;
}

glm::dvec2 measuredCentroid(const Image& image, glm::dvec2 near) {
  double total = 0.0;
  glm::dvec2 sum(0.0);
  for (int y = static_cast<int>(near.y) - 6; y <= static_cast<int>(near.y) + 6; ++y)
    for (int x = static_cast<int>(near.x) - 6; x <= static_cast<int>(near.x) + 6; ++x) {
      if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
      const double w = image.at(x, y).g;
      total += w;
      sum += w * glm::dvec2(x + 0.5, y + 0.5);
    }
  return sum / total;
}

class SmallSquares : public ::testing::TestWithParam<OpenCvCamera> {};

TEST_P(SmallSquares, CentroidsAtTheImageResolutionMatchTheBoxFilteredModel) {
  LENSLAB_REQUIRE_GL();
  const OpenCvCamera cv = GetParam();
  const Camera camera = parseCameraJson(intrinsicsJson(cv), "test camera").camera;
  const std::vector<Square> list = squares(cv);
  const Scene scene = squareScene(list);
  const ImageSize size{kWidth, kHeight};
  Renderer renderer(scene);
  // A pinhole with 256 sub-pixel-jittered views: the box-filtered pixel integral.
  const Image image = renderer.render(
      camera, makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, 1024, 1024, 3}), size);
  double worst = 0.0;
  for (const Square& s : list) {
    const glm::dvec2 expected = boxFilteredCentroid(cv, s);
    if (expected.x < 8 || expected.y < 8 || expected.x > kWidth - 8 || expected.y > kHeight - 8) continue;
    const glm::dvec2 got = measuredCentroid(image, expected);
    worst = std::max({worst, std::abs(got.x - expected.x), std::abs(got.y - expected.y)});
    EXPECT_NEAR(got.x, expected.x, 0.03) << "square at normalised (" << s.centre.x << ", " << s.centre.y << ")";
    EXPECT_NEAR(got.y, expected.y, 0.03) << "square at normalised (" << s.centre.x << ", " << s.centre.y << ")";
  }
  std::cout << "[ measure  ] 4-px squares at 1x, worst centroid error " << worst << " px\n";
}

INSTANTIATE_TEST_SUITE_P(Barrel, SmallSquares, ::testing::Values(OpenCvCamera{260, 258, 161.3, 118.2, -0.28, 0.09}));
INSTANTIATE_TEST_SUITE_P(Pincushion, SmallSquares, ::testing::Values(OpenCvCamera{262, 262, 159.5, 119.5, 0.16, 0.02}));

// The bundled grid through its calibrated barrel lens: every pixel within the range of the
// scene's own values (those of the undistorted pinhole view), one view or many.
TEST(LensPixelIntegral, NoValueLeavesTheScenesRange) {
  LENSLAB_REQUIRE_GL();
  const std::filesystem::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / "grid" / "grid.gltf");
  const Camera camera = loadCameraJson(assets / "grid" / "camera-distortion.json").camera;
  const ImageSize size = resolveImageSize(camera, std::nullopt, std::nullopt);
  Renderer renderer(scene);
  Camera straight = camera;
  straight.lens.effects = {};
  const auto range = [](const Image& image) {
    float lo = 1e30f, hi = -1e30f;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        for (int c = 0; c < 3; ++c) {
          lo = std::min(lo, image.at(x, y)[c]);
          hi = std::max(hi, image.at(x, y)[c]);
        }
    return std::pair{lo, hi};
  };
  const auto [sceneLo, sceneHi] =
      range(renderer.render(straight, makeFramePlan(scene, straight, size, PlanOptions{}), size));
  for (const int samples : {1, 16}) {
    const Image image = renderer.render(
        camera, makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, samples, samples, 1}),
        size);
    const auto [lo, hi] = range(image);
    std::cout << "[ measure  ] grid through camera-distortion.json, " << samples << " view(s): values " << lo << " to "
              << hi << " (scene " << sceneLo << " to " << sceneHi << ")\n";
    EXPECT_GE(lo, sceneLo - 0.005f) << samples << " view(s)";
    EXPECT_LE(hi, sceneHi + 0.005f) << samples << " view(s)";
  }
}

}  // namespace
}  // namespace lenslab
