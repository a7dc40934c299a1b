#pragma once
// The image's size in pixels. The window fixes the aspect ratio of what is seen; when only one
// side is given, the other follows the window so that pixels are square.
//
// Sizes are computed in double and 64-bit integers and checked before they become `int` sides:
// an extreme window (1e-9 wide, 1.37 tall) asks for more rows than an int holds, and that must be
// refused, never wrapped. The raster renders images larger than one GL render target in tiles
// (plan/TilePlan.h), so the limits below are the output's, not the GPU's.
#include "camera/ViewSpec.h"

#include <cstdint>
#include <optional>
#include <string_view>

namespace lenslab {

struct ImageSize {
  int widthPx = 0;
  int heightPx = 0;

  std::int64_t pixelCount() const { return std::int64_t{widthPx} * std::int64_t{heightPx}; }
};

constexpr int kDefaultWidthPx = 960;
// The longest side: PNG and EXR allow more, but 65536 keeps every pixel index of a row and every
// side × 16 bytes far from int overflow.
constexpr int kMaxImageSidePx = 65536;
// The most pixels in all: 2^30 (e.g. 40000 × 26843). A tiled raster image streams to its file a
// strip at a time, so this bounds time rather than memory.
constexpr std::int64_t kMaxImagePixels = std::int64_t{1} << 30;

// Throws InputError, naming the option and the window's aspect ratio, for a side outside
// [1, kMaxImageSidePx] (given, or following from the other side and the window) or more than
// kMaxImagePixels pixels.
ImageSize resolveImageSize(const Window& window, std::optional<int> widthPx, std::optional<int> heightPx);

// The same for an aspect ratio (width / height) that `aspectSource` names in messages, e.g.
// "the window's" or "the calibrated image's".
ImageSize resolveImageSize(double aspect, std::string_view aspectSource, std::optional<int> widthPx,
                           std::optional<int> heightPx);

// Relative difference between the image's and the window's aspect ratios (0 = square pixels).
double pixelAspectMismatch(const Window& window, ImageSize size);

}  // namespace lenslab
