// Image sizes in 64-bit: extreme windows are refused with one line, never wrapped into an int.
#include "camera/ImageSize.h"
#include "core/Error.h"

#include <gtest/gtest.h>

#include <cstdint>
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

}  // namespace
}  // namespace lenslab
