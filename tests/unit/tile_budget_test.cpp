// plan/TileBudget: the rectangles cover exactly the selected tiles; the allocation goes on where
// the error is and stops at the target or the cap.
#include "plan/TileBudget.h"

#include <gtest/gtest.h>

#include <random>

namespace lenslab {
namespace {

TEST(TileGrid, EdgeTilesAreClippedToTheImage) {
  const TileGrid g = makeTileGrid({100, 70}, 32);
  EXPECT_EQ(g.columns, 4);
  EXPECT_EQ(g.rows, 3);
  EXPECT_EQ(g.box(3), (PixelBox{96, 0, 4, 32}));
  EXPECT_EQ(g.box(11), (PixelBox{96, 64, 4, 6}));
  double pixels = 0.0;
  for (int t = 0; t < g.count(); ++t) pixels += g.pixels(t);
  EXPECT_EQ(pixels, 7000.0);
}

TEST(TileGrid, MergedBoxesCoverExactlyTheSelectedTiles) {
  const TileGrid g = makeTileGrid({300, 200}, 16);
  std::mt19937 rng(4);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<char> selected(static_cast<std::size_t>(g.count()));
    for (char& s : selected) s = rng() % 3 == 0;
    std::vector<int> covered(300 * 200, 0);
    for (const PixelBox& b : mergedBoxes(g, selected))
      for (int y = b.y; y < b.y + b.height; ++y)
        for (int x = b.x; x < b.x + b.width; ++x) ++covered[static_cast<std::size_t>(y * 300 + x)];
    for (int y = 0; y < 200; ++y)
      for (int x = 0; x < 300; ++x) {
        const int tile = (y / 16) * g.columns + x / 16;
        ASSERT_EQ(covered[static_cast<std::size_t>(y * 300 + x)], selected[static_cast<std::size_t>(tile)] ? 1 : 0) << x << "," << y;
      }
  }
  std::vector<char> all(static_cast<std::size_t>(g.count()), 1);
  EXPECT_EQ(mergedBoxes(g, all).size(), 1u) << "everything is one rectangle";
}

TEST(TileBudget, TilesUnderTheirMinimumGoOnFirst) {
  const TileGrid g = makeTileGrid({64, 32}, 32);
  const std::vector<TileState> tiles = {{8, 16, 0.0}, {16, 16, 1e-2}};
  const std::vector<int> go = tilesToContinue(g, tiles, 1e-4, 256);
  EXPECT_TRUE(go[0]);
  EXPECT_FALSE(go[1]) << "the estimates wait until every tile has its minimum";
}

TEST(TileBudget, TheNoisyTileGoesOnAndTheConvergedOneStops) {
  const TileGrid g = makeTileGrid({64, 32}, 32);
  const std::vector<TileState> tiles = {{16, 8, 1e-7}, {16, 8, 1e-3}};
  const std::vector<int> go = tilesToContinue(g, tiles, 1e-4, 256);
  EXPECT_FALSE(go[0]);
  EXPECT_TRUE(go[1]);
}

TEST(TileBudget, NothingGoesOnOnceTheTargetIsMetOrAtTheCap) {
  const TileGrid g = makeTileGrid({64, 32}, 32);
  EXPECT_FALSE(tilesToContinue(g, {{16, 8, 1e-5}, {16, 8, 1e-5}}, 1e-4, 256)[1]);
  EXPECT_FALSE(tilesToContinue(g, {{256, 8, 1e-2}, {256, 8, 1e-2}}, 1e-4, 256)[1]);
  // Beyond reach within the cap: every tile below the cap goes on.
  const std::vector<int> go = tilesToContinue(g, {{64, 8, 1e-2}, {256, 8, 1e-2}}, 1e-6, 256);
  EXPECT_TRUE(go[0]);
  EXPECT_FALSE(go[1]);
}

TEST(TileBudget, TheAllocationFollowsTheSquareRootRule) {
  // Two tiles with c = 1e-2 and 4e-2 (error × samples): the optimum gives the second twice the samples.
  // After a round at the optimum's samples, the rule stops both together.
  const TileGrid g = makeTileGrid({64, 32}, 32);
  const double target = 0.5 * (1e-2 / 100 + 4e-2 / 200);
  EXPECT_FALSE(tilesToContinue(g, {{100, 8, 1e-2 / 100}, {200, 8, 4e-2 / 200}}, target * 1.001, 1000)[0]);
  const std::vector<int> go = tilesToContinue(g, {{50, 8, 1e-2 / 50}, {50, 8, 4e-2 / 50}}, target, 1000);
  EXPECT_TRUE(go[0]);
  EXPECT_TRUE(go[1]);
  const std::vector<int> later = tilesToContinue(g, {{100, 8, 1e-2 / 100}, {100, 8, 4e-2 / 100}}, target, 1000);
  EXPECT_FALSE(later[0]) << "tile 0 has its share";
  EXPECT_TRUE(later[1]);
}

TEST(TileBudget, PsnrAndMseAreInverse) {
  EXPECT_NEAR(psnrFromMse(mseFromPsnr(37.5)), 37.5, 1e-12);
  EXPECT_NEAR(psnrFromMse(1e-4), 40.0, 1e-12);
}

}  // namespace
}  // namespace lenslab
