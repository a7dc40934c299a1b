// Golden images: render a bundled scene with its camera, compare with tests/golden/<name>.png.
//
// Tolerance (compared as an 8-bit display shows them, sRGB-encoded):
//   a pixel fails when any channel differs by more than kPixelThreshold;
//   the test fails when more than kMaxFailingFraction of the pixels fail, or any channel of any
//   pixel differs by more than kMaxAbs.
// Why not exact: llvmpipe's rasterisation and texture filtering can move an edge pixel or a
// mipmap blend by a few levels between Mesa versions; a wrong camera or shading moves thousands.
//
// On failure the actual image and an amplified difference are written beside the test binary
// (golden-failures/). A missing golden is a failure. To regenerate after an intended change:
//   tools/update-goldens.sh   (runs this test with LENSLAB_UPDATE_GOLDENS=1)
#include "camera/ImageSize.h"
#include "../common/gl_test_context.h"
#include "io/CameraJson.h"
#include "io/ImageCompare.h"
#include "io/ImageFile.h"
#include "plan/FramePlan.h"
#include "render/Renderer.h"
#include "scene/GltfLoader.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

constexpr double kPixelThreshold = 3.0 / 255.0;
constexpr double kMaxFailingFraction = 0.002;
constexpr double kMaxAbs = 96.0 / 255.0;
constexpr int kGoldenWidth = 480;

struct GoldenCase {
  const char* name;     // tests/golden/<name>.png
  const char* scene;    // under assets/
  const char* camera;   // under assets/
  int maxSamples = 64;  // auto aperture samples, capped to keep the suite quick
};

void PrintTo(const GoldenCase& c, std::ostream* out) { *out << c.name; }

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MatchesTheStoredImage) {
  LENSLAB_REQUIRE_GL();
  const GoldenCase& c = GetParam();
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / c.scene);
  const CameraFile cameraFile = loadCameraJson(assets / c.camera);
  const Camera& camera = cameraFile.camera;
  const ImageSize size = resolveImageSize(camera, kGoldenWidth, std::nullopt);
  Renderer renderer(scene);
  const Image actual = renderer.render(
      camera, makeFramePlan(scene, camera, size, PlanOptions{PlanOptions{}.pattern, 0, c.maxSamples, 1}), size);

  const fs::path golden = fs::path(LENSLAB_GOLDEN_DIR) / (std::string(c.name) + ".png");
  if (const char* update = std::getenv("LENSLAB_UPDATE_GOLDENS"); update && std::string(update) == "1") {
    writeImage(golden, actual);
    GTEST_SKIP() << "wrote " << golden;
  }
  ASSERT_TRUE(fs::exists(golden)) << "missing golden " << golden
                                  << "; run tools/update-goldens.sh and review the image";
  const Image expected = readImage(golden);
  ASSERT_EQ(expected.width, actual.width);
  ASSERT_EQ(expected.height, actual.height);
  const Image a = displayEncoded(actual);
  const Image e = displayEncoded(expected);
  const ImageDifference d = compareImages(a, e, kPixelThreshold);
  const bool pass = d.fractionOver <= kMaxFailingFraction && d.maxAbs <= kMaxAbs;
  if (!pass) {
    const fs::path out = fs::current_path() / "golden-failures";
    fs::create_directories(out);
    writeImage(out / (std::string(c.name) + ".actual.png"), actual);
    writeImage(out / (std::string(c.name) + ".diff.png"), differenceImage(a, e, 8.0f));
    ADD_FAILURE() << c.name << ": " << d.fractionOver * 100.0 << "% of pixels differ by more than "
                  << kPixelThreshold * 255.0 << "/255 (allowed " << kMaxFailingFraction * 100.0 << "%), max difference "
                  << d.maxAbs * 255.0 << "/255 (allowed " << kMaxAbs * 255.0 << "); actual and diff images in " << out;
  }
}

INSTANTIATE_TEST_SUITE_P(
    BundledScenes, Golden,
    ::testing::Values(GoldenCase{"rows", "rows/rows.gltf", "rows/camera.json"},
                      GoldenCase{"occluder", "occluder/occluder.gltf", "occluder/camera.json"},
                      GoldenCase{"grid", "grid/grid.gltf", "grid/camera.json"},
                      GoldenCase{"depth-range", "depth-range/depth-range.gltf", "depth-range/camera.json"},
                      GoldenCase{"rows-dof", "rows/rows.gltf", "rows/camera-dof.json"},
                      GoldenCase{"occluder-dof", "occluder/occluder.gltf", "occluder/camera-dof.json"},
                      // Lens effects: OpenCV-calibrated barrel + tangential on the dots;
                      // every effect (distortion, lateral + axial colour, field curvature) on rows.
                      GoldenCase{"grid-distortion", "grid/grid.gltf", "grid/camera-distortion.json"},
                      GoldenCase{"grid-lens", "grid/grid.gltf", "grid/camera-lens.json"},
                      GoldenCase{"rows-lens", "rows/rows.gltf", "rows/camera-lens.json", 32}),
    [](const ::testing::TestParamInfo<GoldenCase>& param) {
      std::string name = param.param.name;
      for (char& ch : name)
        if (ch == '-') ch = '_';
      return name;
    });

}  // namespace
}  // namespace lenslab
