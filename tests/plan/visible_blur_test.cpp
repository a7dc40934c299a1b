// plan/VisibleBlur: each pixel's circle from its depth, and the dilation by nearer circles only.
#include "plan/VisibleBlur.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace lenslab {
namespace {

// Focused at 3 (the view plane), window 2.2 wide: 100 image pixels ↔ 2.2 window units.
Camera camera(double apertureRadius) {
  ViewSpec v;
  v.vrp = {0.0, 0.0, -3.0};
  v.vpn = {0.0, 0.0, 1.0};
  v.prp = {0.0, 0.0, 3.0};
  v.window = {-1.1, -1.1, 1.1, 1.1};
  v.nearDistance = 0.1;
  v.farDistance = 100.0;
  return cameraFocusedOnViewPlane(v, apertureRadius, "test");
}

constexpr double kInf = std::numeric_limits<double>::infinity();
const ImageSize kImage{100, 100};

TEST(VisibleBlur, EachPixelsCircleIsTheCameraFormulaAtItsDepth) {
  const Camera c = camera(0.1);
  std::vector<double> depth(100 * 100, 3.0);  // in focus
  depth[0] = 6.0;                             // one pixel far behind
  depth[1] = kInf;                            // one pixel of background
  const VisibleBlur b = visibleBlur(c, kImage, kImage, depth);
  EXPECT_EQ(b.ownPx[5000], 0.0f);
  EXPECT_NEAR(b.ownPx[0], cocDiameterOnWindow(c, 6.0) * 100 / 2.2, 1e-4);
  EXPECT_EQ(b.ownPx[1], 0.0f) << "the background has no circle";
  EXPECT_EQ(b.ownMinPx, 0.0);
  // The far pixel's circle reaches the background pixel beside it (farther still), not the nearer
  // in-focus ones: two pixels blurred.
  EXPECT_NEAR(b.fractions[0], 0.9998, 1e-9);
  EXPECT_GE(b.reachingPx[1], b.ownPx[0]);
  EXPECT_EQ(b.reachingPx[100], 0.0f);
}

TEST(VisibleBlur, APinholeSeesNoBlur) {
  std::vector<double> depth(100 * 100, 0.5);
  const VisibleBlur b = visibleBlur(camera(0.0), kImage, kImage, depth);
  EXPECT_EQ(b.maxPx, 0.0);
  EXPECT_EQ(b.fractions[0], 1.0);
}

TEST(VisibleBlur, ANearBlurredSquareSpreadsOverWhatIsBehindItButAFarOneDoesNot) {
  const Camera c = camera(0.05);
  // Depth 1.5: circle 2R·d·|1/3 − 1/1.5| = 0.1·3·(1/3) = 0.1 window units = 4.55 px; use a nearer
  // one for a wide circle: depth 0.6 → 0.1·3·(1/0.6 − 1/3) = 0.4 → 18.2 px (radius 9.1).
  std::vector<double> depth(100 * 100, 3.0);
  for (int y = 40; y < 60; ++y)
    for (int x = 40; x < 60; ++x) depth[static_cast<std::size_t>(y * 100 + x)] = 0.6;
  const VisibleBlur b = visibleBlur(c, kImage, kImage, depth);
  const float own = b.ownPx[50 * 100 + 50];
  EXPECT_NEAR(own, 0.4 * 100 / 2.2, 1e-3);
  // In focus but within the near square's radius of it: reached.
  EXPECT_GE(b.reachingPx[50 * 100 + 35], own);
  EXPECT_GE(b.reachingPx[30 * 100 + 30], own) << "a square neighbourhood: conservative at the corners";
  // Far beyond: untouched.
  EXPECT_EQ(b.reachingPx[50 * 100 + 5], 0.0f);
  EXPECT_EQ(b.reachingPx[5 * 100 + 50], 0.0f);
  EXPECT_NEAR(b.maxOver(0, 0, 10, 10), 0.0, 0.0);
  EXPECT_NEAR(b.maxOver(40, 40, 41, 41), own, 1e-6);

  // Now the square is sharp and in front, the rest blurred far behind: the far blur does not
  // reach over the square's pixels.
  std::vector<double> behind(100 * 100, 30.0);
  for (int y = 40; y < 60; ++y)
    for (int x = 40; x < 60; ++x) behind[static_cast<std::size_t>(y * 100 + x)] = 3.0;
  const VisibleBlur f = visibleBlur(c, kImage, kImage, behind);
  EXPECT_EQ(f.reachingPx[50 * 100 + 50], 0.0f);
  EXPECT_GT(f.reachingPx[5 * 100 + 5], 1.0f);
}

TEST(VisibleBlur, ALowResolutionPrepassCountsInImagePixels) {
  const Camera c = camera(0.05);
  const ImageSize prepass = prepassSizeFor({400, 400}, 100);
  ASSERT_EQ(prepass.widthPx, 100);
  std::vector<double> depth(100 * 100, 3.0);
  for (int y = 40; y < 60; ++y)
    for (int x = 40; x < 60; ++x) depth[static_cast<std::size_t>(y * 100 + x)] = 0.6;
  const VisibleBlur b = visibleBlur(c, {400, 400}, prepass, depth);
  EXPECT_NEAR(b.ownPx[50 * 100 + 50], 0.4 * 400 / 2.2, 1e-2);  // 72.7 image px: radius 9.1 pre-pass px
  EXPECT_GE(b.reachingPx[50 * 100 + 32], b.ownPx[50 * 100 + 50]);
  EXPECT_EQ(b.reachingPx[50 * 100 + 10], 0.0f);
  EXPECT_NEAR(b.maxOver(160, 160, 200, 200), b.ownPx[50 * 100 + 50], 1e-3);
}

TEST(VisibleBlur, TheHistogramAddsUpAndThePercentilesAreOrdered) {
  const Camera c = camera(0.05);
  std::vector<double> depth(100 * 100);
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 100; ++x) depth[static_cast<std::size_t>(y * 100 + x)] = 0.5 + 0.05 * y;
  const VisibleBlur b = visibleBlur(c, kImage, kImage, depth);
  double total = 0.0;
  for (double f : b.fractions) total += f;
  EXPECT_NEAR(total, 1.0, 1e-9);
  EXPECT_LE(b.p50Px, b.p90Px);
  EXPECT_LE(b.p90Px, b.p99Px);
  EXPECT_LE(b.p99Px, b.maxPx);
  EXPECT_GT(b.maxPx, 16.0);
}

}  // namespace
}  // namespace lenslab
