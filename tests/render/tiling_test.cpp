// A tiled render equals the untiled one: each tile is the same camera through a sub-window (same
// rays, same aperture samples, same sub-pixel jitter), rendered with margins for what the lens
// gather and the field-curvature warp read from outside it. Small forced tiles (at most 64 px,
// here 50 x 45) put tile edges everywhere, including through the distortion's strongest part.
#include "../common/gl_test_context.h"
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
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>
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

// PSNR over the pixels on either side of every tile edge inside the image: a seam (a tile's
// table or overscan off at its edge, a pixel's shift between neighbours) shows there first, and
// is diluted in the whole image's figure.
double seamPsnrDb(const Image& a, const Image& b, const TilePlan& tiles) {
  std::vector<char> onSeam(static_cast<std::size_t>(a.width) * static_cast<std::size_t>(a.height), 0);
  const auto mark = [&](int x, int y) {
    if (x >= 0 && y >= 0 && x < a.width && y < a.height) onSeam[static_cast<std::size_t>(y) * a.width + x] = 1;
  };
  for (const Tile& t : tiles.tiles) {
    for (int y = t.rect.y0; y < t.rect.y1; ++y)
      for (const int x : {t.rect.x0 - 1, t.rect.x0, t.rect.x1 - 1, t.rect.x1}) mark(x, y);
    for (int x = t.rect.x0; x < t.rect.x1; ++x)
      for (const int y : {t.rect.y0 - 1, t.rect.y0, t.rect.y1 - 1, t.rect.y1}) mark(x, y);
  }
  double sum = 0.0;
  std::int64_t count = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      if (!onSeam[static_cast<std::size_t>(y) * a.width + x]) continue;
      const glm::vec4 e = glm::clamp(a.at(x, y), 0.0f, 1.0f) - glm::clamp(b.at(x, y), 0.0f, 1.0f);
      sum += static_cast<double>(e.r * e.r + e.g * e.g + e.b * e.b);
      count += 3;
    }
  if (count == 0 || sum == 0.0) return 200.0;
  return -10.0 * std::log10(sum / static_cast<double>(count));
}

void expectTiledEqualsUntiled(const std::string& name, const Image& untiled, const Image& tiled, const TilePlan& tiles,
                              const FramePlan& plan) {
  ASSERT_EQ(untiled.width, tiled.width);
  ASSERT_EQ(untiled.height, tiled.height);
  const ImageDifference d = compareImages(untiled, tiled, 1.0 / 255.0);
  const double seams = seamPsnrDb(untiled, tiled, tiles);
  // Where the largest difference is: on a tile edge it would point at the tiling, not at rounding.
  glm::ivec2 worst(0);
  float worstDifference = 0.0f;
  for (int y = 0; y < untiled.height; ++y)
    for (int x = 0; x < untiled.width; ++x) {
      const glm::vec4 e = glm::abs(untiled.at(x, y) - tiled.at(x, y));
      if (std::max({e.r, e.g, e.b}) > worstDifference) worstDifference = std::max({e.r, e.g, e.b}), worst = {x, y};
    }
  std::cout << "[ tiling   ] " << name << " " << untiled.width << "x" << untiled.height << ", " << tiles.tiles.size()
            << " tiles of " << tiles.tileWidthPx << "x" << tiles.tileHeightPx << ", " << plan.apertureSamples
            << " samples: PSNR " << d.psnrDb << " dB (" << seams << " dB on the tile seams), max " << d.maxAbs << ", "
            << d.fractionOver * 100.0 << "% of pixels over 1/255 (largest at pixel " << worst.x << "," << worst.y
            << ")\n";
  EXPECT_GE(d.psnrDb, 60.0) << name;
  EXPECT_GE(seams, 60.0) << name;
  if (d.psnrDb < 60.0 || seams < 60.0) {
    const fs::path out = fs::current_path() / "tiling-failures";
    fs::create_directories(out);
    writeImage(out / (name + ".untiled.png"), untiled);
    writeImage(out / (name + ".tiled.png"), tiled);
    writeImage(out / (name + ".diff.png"), differenceImage(untiled, tiled, 16.0f));
  }
}

TEST_P(Tiling, EqualsTheUntiledRender) {
  LENSLAB_REQUIRE_GL();
  const TilingCase& c = GetParam();
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / c.scene);
  const Camera camera = loadCameraJson(assets / c.camera).camera;
  const ImageSize size = resolveImageSize(camera, 200, std::nullopt);
  const FramePlan plan = makeFramePlan(
      scene, camera, size, PlanOptions{AperturePattern::Concentric, c.apertureSamples, c.apertureSamples, 3});
  Renderer renderer(scene);
  const Image untiled = renderer.render(camera, plan, size);
  const TilePlan tiles = planTiles(camera, size, plan, queryRenderTargetLimits(), 64);
  ASSERT_TRUE(tiles.tiled);
  ASSERT_GE(tiles.tiles.size(), 12u);
  const Image tiled = renderTiled(renderer, camera, plan, size, tiles);
  expectTiledEqualsUntiled(c.name, untiled, tiled, tiles, plan);
}

// The tiles `render` makes itself for a lens frame over its memory budget (plan/TilePlan.h
// TileMemory; here scaled down to a small image): tiles of uneven sizes, short ones where the
// strip budget cuts the rows, each building the lens tables for its own pixels and overscan. The
// same image as one render, on the seams too.
TEST(TilingBudget, LensTilesFromTheMemoryBudgetEqualTheUntiledRender) {
  LENSLAB_REQUIRE_GL();
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / "rows/rows.gltf");
  const Camera camera = loadCameraJson(assets / "rows/camera-lens.json").camera;
  const ImageSize size = resolveImageSize(camera, 243, std::nullopt);
  const FramePlan plan = makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, 8, 8, 5});
  ASSERT_TRUE(plan.remap);
  TileMemory memory;
  memory.tileBytes = std::int64_t{1} << 20;
  memory.stripBytes = std::int64_t{size.widthPx} * 37 * 16;  // rows of at most 37 pixels
  const TilePlan tiles = planTiles(camera, size, plan, queryRenderTargetLimits(), 0, &memory);
  ASSERT_TRUE(tiles.tiled);
  ASSERT_GE(tiles.tiles.size(), 12u);
  ASSERT_LT(tiles.tileWidthPx, size.widthPx / 2);
  for (const Tile& t : tiles.tiles) ASSERT_LE(t.rect.height(), 37);
  Renderer renderer(scene);
  const Image untiled = renderer.render(camera, plan, size);
  const Image tiled = renderTiled(renderer, camera, plan, size, tiles);
  // Each tile built its own tables (its own window), once.
  EXPECT_GE(renderer.lensTablesBuilt(), static_cast<int>(tiles.tiles.size()));
  expectTiledEqualsUntiled("lens_memory_budget", untiled, tiled, tiles, plan);
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
