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
        ASSERT_EQ(covered[static_cast<std::size_t>(y * 300 + x)], selected[static_cast<std::size_t>(tile)] ? 1 : 0)
            << x << "," << y;
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

TEST(TileBudget, WholeViewsGoOnUntilTheFrameMeetsTheTarget) {
  const TileGrid g = makeTileGrid({64, 32}, 32);
  // c = 1e-2 and 3e-2 over equal areas: the frame meets 1e-4 at n = (1e-2 + 3e-2) / 2 / 1e-4 = 200,
  // counted from the most any tile has (16).
  EXPECT_EQ(wholeFrameMoreSamples(g, {{16, 8, 1e-2 / 16}, {8, 8, 3e-2 / 8}}, 1e-4, 1000), 200 - 16);
  EXPECT_EQ(wholeFrameMoreSamples(g, {{16, 8, 1e-2 / 16}, {8, 8, 3e-2 / 8}}, 1e-4, 100), 100 - 16) << "capped";
  EXPECT_EQ(wholeFrameMoreSamples(g, {{16, 8, 1e-6}, {16, 8, 1e-6}}, 1e-4, 1000), 0) << "met";
}

TEST(TileBudget, TilesPayOnlyWhereTheirErrorsDiffer) {
  const TileGrid g = makeTileGrid({320, 320}, 32);  // 100 tiles
  // Every tile alike: the allocations are the same, and a tile's pixel costs more: whole views.
  std::vector<TileState> alike(100, TileState{16, 8, 1e-3});
  EXPECT_FALSE(perTilePays(g, alike, 1e-4, 256, 1.3));
  EXPECT_TRUE(perTilePays(g, alike, 1e-4, 256, 0.9)) << "were a tile's pixel cheaper, tiles would pay";
  // One blurred tile in a frame in focus: tiles pay even at twice the cost a pixel.
  std::vector<TileState> one(100, TileState{16, 8, 1e-7});
  one[42].mse = 1e-2;
  EXPECT_TRUE(perTilePays(g, one, 1e-4, 256, 2.0));
  // Half the frame a hundred times noisier than the other half: the √c rule saves 1 − (1 + √100)² / (2·(1 + 100))
  // = 40 % of the views; at 1.5 times the cost a pixel that does not pay, at 1.3 it does.
  std::vector<TileState> half(100, TileState{16, 8, 1e-4});
  for (int t = 0; t < 50; ++t) half[static_cast<std::size_t>(t)].mse = 1e-2;
  EXPECT_FALSE(perTilePays(g, half, 1e-4, 100000, 1.8));
  EXPECT_TRUE(perTilePays(g, half, 1e-4, 100000, 1.5));
}

TEST(TileBudget, PooledEstimatesShareTheNeighboursErrorTimesSamples) {
  const TileGrid g = makeTileGrid({96, 96}, 32);  // 3 × 3 tiles of equal size
  std::vector<int> samples(9, 16);
  std::vector<double> mse(9, 1e-3);
  // Alike everywhere: pooling changes nothing.
  for (const double m : pooledMse(g, samples, mse, 1)) EXPECT_DOUBLE_EQ(m, 1e-3);
  // The centre's own draw came out at nothing: it gets its neighbours' error, not zero (a tile
  // that stopped on a lucky draw would keep it).
  mse[4] = 0.0;
  EXPECT_NEAR(pooledMse(g, samples, mse, 1)[4], 8.0 / 9.0 * 1e-3, 1e-15);
  // The neighbourhood's c = error × samples, over the tile's own count: four times the samples,
  // a quarter of the error.
  mse[4] = 1e-3;
  samples[4] = 64;
  mse[4] = 1e-3 * 16 / 64;
  EXPECT_NEAR(pooledMse(g, samples, mse, 1)[4], 1e-3 * 16 / 64, 1e-15);
  // A corner pools its own 2 × 2; radius 0 is the tile's own estimate.
  mse[0] = 4e-3;
  EXPECT_NEAR(pooledMse(g, samples, mse, 1)[0], (4e-3 + 2 * 1e-3 + 1e-3 * 16 / 64 * 64 / 16) / 4, 1e-15);
  const std::vector<double> own = pooledMse(g, samples, mse, 0);
  for (std::size_t t = 0; t < own.size(); ++t) EXPECT_DOUBLE_EQ(own[t], mse[t]);
}

TEST(TileBudget, PsnrAndMseAreInverse) {
  EXPECT_NEAR(psnrFromMse(mseFromPsnr(37.5)), 37.5, 1e-12);
  EXPECT_NEAR(psnrFromMse(1e-4), 40.0, 1e-12);
}

}  // namespace
}  // namespace lenslab
