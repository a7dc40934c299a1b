// Tiles are sub-windows: the same rays per pixel, and a plan that covers the image once, within
// the render-target limits, with margins for the lens.
#include "camera/Camera.h"
#include "camera/ImageMap.h"
#include "camera/LensMap.h"
#include "camera/Projection.h"
#include "camera/SubWindow.h"
#include "io/CameraJson.h"
#include "plan/FramePlan.h"
#include "plan/TilePlan.h"
#include "scene/Scene.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace lenslab {
namespace {

Camera obliqueCamera(Projection projection) {
  ViewSpec v;
  v.projection = projection;
  v.vrp = {0.2, -0.1, -2.0};
  v.vpn = {0.1, 0.2, 1.0};
  v.vup = {0.0, 1.0, 0.1};
  v.prp = {0.15, -0.05, 2.0};  // off the window's centre: oblique already
  v.window = {-1.2, -0.7, 1.0, 0.8};
  v.nearDistance = 0.05;
  v.farDistance = 50.0;
  return cameraFocusedOnViewPlane(v, 0.1, "test camera");
}

// Pixel position of a world point in an image of `camera` at `size`, seen from lens offset
// `lens` with sub-pixel jitter `jitterPx` (the renderer's viewThroughLens).
glm::dvec2 pixelOf(const Camera& camera, ImageSize size, glm::dvec2 lens, glm::dvec2 jitterPx,
                   const glm::dvec3& world) {
  const Window& w = camera.view.window;
  const glm::dvec2 pitch(w.width() / size.widthPx, w.height() / size.heightPx);
  const ViewSpec view = viewThroughLens(camera, lens, {jitterPx.x * pitch.x, -jitterPx.y * pitch.y});
  return pixelFromWindow(view.window, projectToWindow(view, world), size.widthPx, size.heightPx);
}

class SubWindowRays : public ::testing::TestWithParam<Projection> {};

TEST_P(SubWindowRays, ATilePixelSeesWhatTheFullImagesPixelSees) {
  const Camera camera = obliqueCamera(GetParam());
  const ImageSize size{640, 436};
  const PixelRect rect{448, 50, 512, 114};
  const Camera tile = subWindowCamera(camera, size, rect);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coordinate(-1.5, 1.5), depth(-6.0, -0.5), unit(-0.5, 0.5);
  for (int i = 0; i < 500; ++i) {
    const glm::dvec3 world(coordinate(rng), coordinate(rng), depth(rng));
    const glm::dvec2 lens(0.1 * unit(rng), 0.1 * unit(rng)), jitter(unit(rng), unit(rng));
    const glm::dvec2 full = pixelOf(camera, size, lens, jitter, world);
    const glm::dvec2 inTile = pixelOf(tile, rect.size(), lens, jitter, world) + glm::dvec2(rect.x0, rect.y0);
    ASSERT_NEAR(inTile.x, full.x, 1e-9);
    ASSERT_NEAR(inTile.y, full.y, 1e-9);
  }
  // Same depth mapping: the tile's clip z of a point is the full image's.
  const glm::dvec4 a = clipFromWorld(camera.view) * glm::dvec4(0.3, 0.2, -3.0, 1.0);
  const glm::dvec4 b = clipFromWorld(tile.view) * glm::dvec4(0.3, 0.2, -3.0, 1.0);
  EXPECT_NEAR(a.z / a.w, b.z / b.w, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Projections, SubWindowRays, ::testing::Values(Projection::Perspective, Projection::Parallel));

// Every pixel in exactly one tile (inside the image, no two overlapping, areas adding up); every
// tile's render within the limits and holding its tile.
void expectCovers(const TilePlan& tiles, ImageSize size, const RenderTargetLimits& limits) {
  const PixelRect image{0, 0, size.widthPx, size.heightPx};
  std::int64_t area = 0;
  int lastY0 = 0;
  for (std::size_t i = 0; i < tiles.tiles.size(); ++i) {
    const Tile& t = tiles.tiles[i];
    ASSERT_FALSE(t.rect.empty());
    EXPECT_EQ(intersect(t.rect, image), t.rect);
    EXPECT_GE(t.rect.y0, lastY0);  // row by row, for the strip writer
    lastY0 = t.rect.y0;
    EXPECT_LE(t.rendered.width(), limits.maxSidePx);
    EXPECT_LE(t.rendered.height(), limits.maxSidePx);
    EXPECT_LE(std::int64_t{t.rendered.width()} * t.rendered.height(), limits.maxPixels);
    EXPECT_EQ(intersect(t.rendered, t.rect), t.rect);
    for (std::size_t j = 0; j < i; ++j) EXPECT_TRUE(intersect(t.rect, tiles.tiles[j].rect).empty()) << i << " " << j;
    area += t.rect.size().pixelCount();
  }
  EXPECT_EQ(area, size.pixelCount());
}

TEST(TilePlan, AnImageOneTargetHoldsIsNotTiled) {
  const Camera camera = obliqueCamera(Projection::Perspective);
  const ImageSize size{960, 654};
  const TilePlan tiles = planTiles(camera, size, makeFramePlan(Scene{}, camera, size), RenderTargetLimits{});
  EXPECT_FALSE(tiles.tiled);
  ASSERT_EQ(tiles.tiles.size(), 1u);
  EXPECT_EQ(tiles.tiles[0].rect, (PixelRect{0, 0, 960, 654}));
}

// The decision `lenslab render --width 16384` and 20000 make on llvmpipe (16384 a side).
TEST(TilePlan, BeyondTheLimitsTilesWithinThem) {
  const Camera camera = obliqueCamera(Projection::Perspective);
  const RenderTargetLimits llvmpipe{16384, RenderTargetLimits::kTargetBudgetBytes / 16};
  for (const ImageSize size : {ImageSize{16384, 10923}, ImageSize{20000, 13333}}) {
    const TilePlan tiles = planTiles(camera, size, makeFramePlan(Scene{}, camera, size), llvmpipe);
    EXPECT_TRUE(tiles.tiled) << size.widthPx;
    EXPECT_LE(tiles.tileWidthPx, 4096);
    EXPECT_GT(tiles.tileWidthPx, 2048);
    expectCovers(tiles, size, llvmpipe);
  }
  // A small GL limit alone also tiles.
  const ImageSize size{3000, 2000};
  const RenderTargetLimits small{1024, std::int64_t{1} << 40};
  const TilePlan tiles = planTiles(camera, size, makeFramePlan(Scene{}, camera, size), small);
  EXPECT_TRUE(tiles.tiled);
  expectCovers(tiles, size, small);
}

TEST(TilePlan, ForcedTilesAreAtMostThatSizeAndNearlyEqual) {
  const Camera camera = obliqueCamera(Projection::Perspective);
  const ImageSize size{200, 136};
  const TilePlan tiles = planTiles(camera, size, makeFramePlan(Scene{}, camera, size), RenderTargetLimits{}, 64);
  EXPECT_TRUE(tiles.tiled);
  EXPECT_EQ(tiles.tileWidthPx, 50);
  EXPECT_EQ(tiles.tileHeightPx, 46);
  EXPECT_EQ(tiles.tiles.size(), 12u);
  for (const Tile& t : tiles.tiles) EXPECT_EQ(t.rendered, t.rect);  // no lens: no margins
  expectCovers(tiles, size, RenderTargetLimits{});
}

// With distortion each tile renders its pre-image (and the gather's reach) around it, never more
// than the full frame's overscan.
TEST(TilePlan, LensTilesRenderTheirPreImageWithinTheFramesOverscan) {
  const Camera camera = parseCameraJson(R"({"eye": [0, 0, 3], "target": [0, 0, 0], "near": 0.1, "far": 100,
      "intrinsics": {"fx": 686, "fy": 686, "cx": 482.5, "cy": 317.5, "width": 960, "height": 640},
      "distortion": [-0.22, 0.05, 0.002, -0.001]})",
                                        "test.json")
                            .camera;
  const ImageSize size{480, 320};
  const FramePlan plan = makeFramePlan(Scene{}, camera, size);
  ASSERT_TRUE(plan.remap);
  const TilePlan tiles = planTiles(camera, size, plan, RenderTargetLimits{}, 100);
  expectCovers(tiles, size, RenderTargetLimits{});
  const glm::ivec2 pad = plan.overscan.padPx;
  const PixelRect frame{-pad.x, -pad.y, size.widthPx + pad.x, size.heightPx + pad.y};
  for (const Tile& t : tiles.tiles) {
    EXPECT_EQ(intersect(t.rendered, frame), t.rendered);
    // It holds the tile and the pre-image of every pixel of it (sampled here inside the tile, on
    // the pixel grid and between), on GL's 2 x 2 quads of the frame.
    EXPECT_EQ(intersect(t.rendered, t.rect), t.rect);
    for (double y = t.rect.y0; y <= t.rect.y1; y += 0.25 * t.rect.height())
      for (double x = t.rect.x0; x <= t.rect.x1; x += 0.25 * t.rect.width()) {
        const glm::dvec2 p = ThinLensMap(camera, size).undistorted(Channel::Green, {x, y}).pixel;
        EXPECT_GE(p.x, t.rendered.x0 + 2);
        EXPECT_LE(p.x, t.rendered.x1 - 2);
        EXPECT_GE(p.y, t.rendered.y0 + 2);
        EXPECT_LE(p.y, t.rendered.y1 - 2);
      }
    EXPECT_EQ((t.rendered.x0 - frame.x0) % 2, 0);
    EXPECT_EQ((frame.y1 - t.rendered.y1) % 2, 0);
  }
  // Barrel distortion pulls a corner tile's pixels from outside the image, out to the frame's
  // overscan, and an inner side's margin is small.
  EXPECT_EQ(tiles.tiles.front().rendered.x0, -pad.x);
  EXPECT_EQ(tiles.tiles.front().rendered.y0, -pad.y);
  EXPECT_LT(tiles.tiles.front().rendered.x1 - tiles.tiles.front().rect.x1, pad.x / 2);
}

// Memory bounded by the tile, not the frame: a lens render that one render target could hold but
// whose render would hold more than a tile's budget is tiled, every tile within the budget and every
// strip of tile rows within the strip's; without a budget the same frame is one render.
TEST(TilePlan, ALensFrameOverTheMemoryBudgetIsTiledWithinIt) {
  const Camera camera =
      parseCameraJson(R"({"eye": [0, 0, 3], "target": [0, 0, 0], "near": 0.1, "far": 100, "f_number": 2.8,
      "focal_length_mm": 35, "sensor_mm": [36, 24], "focus_distance": 3, "distortion": {"k1": -0.15, "k2": 0.03},
      "chromatic": {"lateral_red": 0.004, "lateral_blue": -0.004}})",
                      "test.json")
          .camera;
  const ImageSize size{1200, 800};
  const FramePlan plan = makeFramePlan(Scene{}, camera, size, PlanOptions{AperturePattern::Concentric, 16, 16, 1});
  ASSERT_TRUE(plan.remap);
  EXPECT_FALSE(planTiles(camera, size, plan, RenderTargetLimits{}).tiled);
  TileMemory memory;
  memory.tileBytes = std::int64_t{48} << 20;
  memory.stripBytes = std::int64_t{4} << 20;
  memory.fileBytesPerPixel = 16;
  const Tile whole{{0, 0, size.widthPx, size.heightPx},
                   {0, 0, plan.overscan.size.widthPx, plan.overscan.size.heightPx}};
  // The whole frame: ~1.1 Mpx rendered, each pixel with its view layers (8 × 16 bytes), the forward
  // tables (32), the inverse tables (24), sums and read-back: over 200 bytes a pixel.
  EXPECT_GT(tileMemoryBytes(plan, whole), std::int64_t{200} * size.pixelCount());
  const TilePlan tiles = planTiles(camera, size, plan, RenderTargetLimits{}, 0, &memory);
  EXPECT_TRUE(tiles.tiled);
  EXPECT_NE(tiles.why.find("a tile may hold"), std::string::npos) << tiles.why;
  expectCovers(tiles, size, RenderTargetLimits{});
  for (const Tile& t : tiles.tiles) {
    EXPECT_LE(tileMemoryBytes(plan, t), memory.tileBytes);
    EXPECT_LE(std::int64_t{size.widthPx} * t.rect.height() * memory.fileBytesPerPixel, memory.stripBytes);
  }
  // A PNG's strip is 3 bytes a pixel: the same strip budget allows taller tile rows.
  TileMemory png = memory;
  png.fileBytesPerPixel = 3;
  EXPECT_GT(planTiles(camera, size, plan, RenderTargetLimits{}, 0, &png).tileHeightPx, tiles.tileHeightPx);
  // A larger budget, fewer tiles (each tile's margins cost render time).
  TileMemory larger = memory;
  larger.tileBytes *= 4;
  larger.stripBytes *= 4;
  EXPECT_LT(planTiles(camera, size, plan, RenderTargetLimits{}, 0, &larger).tiles.size(), tiles.tiles.size());
}

// A budget that only tiny tiles could meet is given up for the render-target limits, not refused.
TEST(TilePlan, AnUnmeetableMemoryBudgetFallsBackToTheTargetLimits) {
  const Camera camera = obliqueCamera(Projection::Perspective);
  const ImageSize size{960, 654};
  const FramePlan plan = makeFramePlan(Scene{}, camera, size);
  TileMemory memory;
  memory.tileBytes = 1;
  const TilePlan tiles = planTiles(camera, size, plan, RenderTargetLimits{}, 0, &memory);
  EXPECT_TRUE(tiles.tiled);
  expectCovers(tiles, size, RenderTargetLimits{});
}

}  // namespace
}  // namespace lenslab
