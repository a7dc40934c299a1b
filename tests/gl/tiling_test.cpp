// A tiled render equals the untiled one: each tile is the same camera through a sub-window (same
// rays, same aperture samples, same sub-pixel jitter), rendered with margins for what the lens
// gather and the field-curvature warp read from outside it. Small forced tiles (at most 64 px,
// here 50 x 45) put tile edges everywhere, including through the distortion's strongest part.
#include "gl_test_context.h"
#include "io/CameraJson.h"
#include "io/ImageCompare.h"
#include "io/ImageFile.h"
#include "plan/FramePlan.h"
#include "plan/TilePlan.h"
#include "render/Renderer.h"
#include "render/TiledRender.h"
#include "scene/GltfLoader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

struct TilingCase {
  const char* name;
  const char* scene;
  const char* camera;
  int apertureSamples;  // 1: one view; more: accumulated (pinhole: jittered anti-aliasing views)
};

void PrintTo(const TilingCase& c, std::ostream* out) { *out << c.name; }

class Tiling : public ::testing::TestWithParam<TilingCase> {};

TEST_P(Tiling, EqualsTheUntiledRender) {
  LENSLAB_REQUIRE_GL();
  const TilingCase& c = GetParam();
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / c.scene);
  const Camera camera = loadCameraJson(assets / c.camera).camera;
  const ImageSize size = resolveImageSize(camera, 200, std::nullopt);
  const FramePlan plan = makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, c.apertureSamples, c.apertureSamples, 3});
  Renderer renderer(scene);
  const Image untiled = renderer.render(camera, plan, size);
  const TilePlan tiles = planTiles(camera, size, plan, queryRenderTargetLimits(), 64);
  ASSERT_TRUE(tiles.tiled);
  ASSERT_GE(tiles.tiles.size(), 12u);
  const Image tiled = renderTiled(renderer, camera, plan, size, tiles);
  const ImageDifference d = compareImages(untiled, tiled, 1.0 / 255.0);
  // Where the largest difference is: on a tile edge it would point at the tiling, not at rounding.
  glm::ivec2 worst(0);
  float worstDifference = 0.0f;
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      const glm::vec4 e = glm::abs(untiled.at(x, y) - tiled.at(x, y));
      if (std::max({e.r, e.g, e.b}) > worstDifference) worstDifference = std::max({e.r, e.g, e.b}), worst = {x, y};
    }
  std::cout << "[ tiling   ] " << c.name << " " << size.widthPx << "x" << size.heightPx << ", " << tiles.tiles.size()
            << " tiles of " << tiles.tileWidthPx << "x" << tiles.tileHeightPx << ", " << plan.apertureSamples
            << " samples: PSNR " << d.psnrDb << " dB, max " << d.maxAbs << ", " << d.fractionOver * 100.0
            << "% of pixels over 1/255 (largest at pixel " << worst.x << "," << worst.y << ")\n";
  EXPECT_GE(d.psnrDb, 60.0) << c.name;
  if (d.psnrDb < 60.0) {
    const fs::path out = fs::current_path() / "tiling-failures";
    fs::create_directories(out);
    writeImage(out / (std::string(c.name) + ".untiled.png"), untiled);
    writeImage(out / (std::string(c.name) + ".tiled.png"), tiled);
    writeImage(out / (std::string(c.name) + ".diff.png"), differenceImage(untiled, tiled, 16.0f));
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cameras, Tiling,
    ::testing::Values(TilingCase{"pinhole", "rows/rows.gltf", "rows/camera.json", 1},
                      TilingCase{"pinhole_jittered", "rows/rows.gltf", "rows/camera.json", 8},
                      TilingCase{"dof", "rows/rows.gltf", "rows/camera-dof.json", 16},
                      TilingCase{"distortion_one_view", "grid/grid.gltf", "grid/camera-distortion.json", 1},
                      TilingCase{"distortion_jittered", "grid/grid.gltf", "grid/camera-distortion.json", 8},
                      // distortion, lateral and axial colour, field curvature, thin lens
                      TilingCase{"every_lens_effect", "rows/rows.gltf", "rows/camera-lens.json", 16}),
    [](const ::testing::TestParamInfo<TilingCase>& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace lenslab
