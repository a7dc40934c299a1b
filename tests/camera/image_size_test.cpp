// Image sizes in 64-bit: extreme windows are refused with one line, never wrapped into an int.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "core/Error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

namespace lenslab {
namespace {

Window windowOf(double width, double height) { return {0.0, 0.0, width, height}; }

std::string messageOf(const Window& window, std::optional<int> width, std::optional<int> height) {
  try {
    const ImageSize size = resolveImageSize(window, width, height);
    return "no error: " + std::to_string(size.widthPx) + "x" + std::to_string(size.heightPx);
  } catch (const InputError& e) {
    return e.what();
  }
}

TEST(ImageSize, FollowsTheWindowsAspect) {
  const ImageSize size = resolveImageSize(windowOf(3.0, 2.0), std::nullopt, std::nullopt);
  EXPECT_EQ(size.widthPx, kDefaultWidthPx);
  EXPECT_EQ(size.heightPx, 640);
  const ImageSize byHeight = resolveImageSize(windowOf(3.0, 2.0), std::nullopt, 100);
  EXPECT_EQ(byHeight.widthPx, 150);
  EXPECT_EQ(byHeight.pixelCount(), 15000);
}

// Was 240x1: 240 / (1e-9 / 1.37) = 3.3e11 rows wrapped through an int.
TEST(ImageSize, RefusesAHeightBeyondTheMaximumForANarrowWindow) {
  const std::string message = messageOf(windowOf(1e-9, 1.37), 240, std::nullopt);
  EXPECT_NE(message.find("--width 240"), std::string::npos) << message;
  EXPECT_NE(message.find("aspect ratio"), std::string::npos) << message;
  EXPECT_NE(message.find("1 to 65536"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// Was 240x500: 2^32 + 500 rows wrapped to 500.
TEST(ImageSize, RefusesTwoToThe32PlusFiveHundredRows) {
  const double rows = 4294967296.0 + 500.0;
  EXPECT_THROW(resolveImageSize(windowOf(240.0, rows), 240, std::nullopt), InputError);
  EXPECT_THROW(resolveImageSize(windowOf(rows, 240.0), std::nullopt, 240), InputError);
}

TEST(ImageSize, RefusesASideBelowOnePixel) {
  const std::string message = messageOf(windowOf(1000.0, 1.0), 100, std::nullopt);
  EXPECT_NE(message.find("height of 0.1 px"), std::string::npos) << message;
  EXPECT_THROW(resolveImageSize(windowOf(1.0, 1.0), 0, std::nullopt), InputError);
  EXPECT_THROW(resolveImageSize(windowOf(1.0, 1.0), std::nullopt, -3), InputError);
}

TEST(ImageSize, RefusesMoreThanTheTotalPixelBound) {
  // Each side is allowed, the product is not.
  const std::string message = messageOf(windowOf(1.0, 1.0), kMaxImageSidePx, std::nullopt);
  EXPECT_NE(message.find("4294967296 pixels"), std::string::npos) << message;
  EXPECT_THROW(resolveImageSize(windowOf(1.0, 1.0), 40000, 40000), InputError);
  // The README's 20000-wide image fits.
  const ImageSize big = resolveImageSize(windowOf(36.0, 24.0), 20000, std::nullopt);
  EXPECT_EQ(big.heightPx, 13333);
  EXPECT_EQ(big.pixelCount(), std::int64_t{20000} * 13333);
}

// Was silent: 320 on the 3:2 rows camera rounds the height to 213 and fx, fy part by 0.16 %.
TEST(ImageSize, SaysWhenPixelsAreNotSquareAndWhichSizesKeepThemSquare) {
  const double aspect = 1.5;
  EXPECT_NEAR(pixelStretch(aspect, {320, 213}), 320.0 / 319.5 - 1.0, 1e-15);
  EXPECT_EQ(pixelShapeWarning(aspect, {320, 213}, true, false),
            "320x213 makes pixels 0.16 % taller than wide (the window is 1.5:1); --width 318 (212 high) or --width 321 "
            "(214 high) keeps them square");
  // Only the height given: heights to try.
  EXPECT_EQ(
      pixelShapeWarning(aspect, {320, 213}, false, true),
      "320x213 makes pixels 0.16 % taller than wide (the window is 1.5:1); --height 212 (318 wide) or --height 214 "
      "(321 wide) keeps them square");
  // Both given: both sides of the nearest square sizes, and the other way out.
  const std::string both = pixelShapeWarning(aspect, {320, 320}, true, true);
  EXPECT_EQ(both.rfind("320x320 makes pixels 50 % wider than tall", 0), 0u) << both;
  EXPECT_NE(both.find("--width 318 --height 212 or --width 321 --height 214"), std::string::npos) << both;
  EXPECT_NE(both.find("give only --width or --height"), std::string::npos) << both;
  // Square, or off by less than the tolerance: nothing to say.
  for (const ImageSize ok : {ImageSize{318, 212}, ImageSize{321, 214}, ImageSize{960, 640}, ImageSize{20000, 13333}})
    EXPECT_EQ(pixelShapeWarning(aspect, ok, true, false), "") << ok.widthPx << "x" << ok.heightPx;
  EXPECT_EQ(pixelShapeWarning(aspect, {1000, 667}, true, false), "");  // 0.05 %: under the tolerance
  EXPECT_NE(pixelShapeWarning(aspect, {100, 67}, true, false), "");    // 0.5 %
  // The sizes it names keep pixels square, for an aspect that no whole sizes meet exactly.
  const double irrational = std::sqrt(2.0);
  const std::string w = pixelShapeWarning(irrational, {100, 71}, true, false);
  ASSERT_NE(w, "");
  int below = 0, belowHigh = 0, above = 0, aboveHigh = 0;
  ASSERT_EQ(std::sscanf(w.substr(w.find("; ")).c_str(), "; --width %d (%d high) or --width %d (%d high)", &below,
                        &belowHigh, &above, &aboveHigh),
            4)
      << w;
  EXPECT_LT(below, 100);
  EXPECT_GT(above, 100);
  EXPECT_LE(std::abs(pixelStretch(irrational, {below, belowHigh})), kSquarePixelTolerance);
  EXPECT_LE(std::abs(pixelStretch(irrational, {above, aboveHigh})), kSquarePixelTolerance);
}

TEST(ImageSize, ADefaultWidthMovesToTheNearestThatKeepsPixelsSquare) {
  const ImageSize sweep = resolveImageSize(windowOf(3.0, 2.0), std::nullopt, std::nullopt, 320);
  EXPECT_EQ(sweep.widthPx, 321);
  EXPECT_EQ(sweep.heightPx, 214);
  const ImageSize render = resolveImageSize(windowOf(3.0, 2.0), std::nullopt, std::nullopt);
  EXPECT_EQ(render.widthPx, 960);  // already square
  // A width the user gives is kept as given (the command warns instead).
  EXPECT_EQ(resolveImageSize(windowOf(3.0, 2.0), 320, std::nullopt).heightPx, 213);
}

TEST(ImageSize, ACalibratedCameraKeepsItsOwnPixelShape) {
  Camera camera;
  camera.view.window = windowOf(4.0, 3.0);
  camera.calibratedSize = ImageSize{640, 360};  // pixels a third taller than wide, by calibration
  // Its own size, and scalings of it, keep the calibrated shape: nothing to say.
  EXPECT_EQ(pixelShapeWarning(camera, std::nullopt, std::nullopt, resolveImageSize(camera, std::nullopt, std::nullopt)),
            "");
  EXPECT_EQ(pixelShapeWarning(camera, 320, std::nullopt, resolveImageSize(camera, 320, std::nullopt)), "");
  // Both sides given against it: measured against the calibration, not against square.
  const std::string w = pixelShapeWarning(camera, 640, 480, {640, 480});
  EXPECT_NE(w.find("than in the calibrated 640x360 image"), std::string::npos) << w;
  // A square-pixel calibration is simply square.
  camera.calibratedSize = ImageSize{640, 480};
  EXPECT_NE(pixelShapeWarning(camera, 640, 470, {640, 470}).find("2.1 % taller than wide (the window is 1.333:1)"),
            std::string::npos);
}

}  // namespace
}  // namespace lenslab
