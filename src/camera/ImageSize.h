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
#include <string>
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

// Pixels count as square when their height and width differ by at most this (relative): a square
// as tall as a 1000-px image is then drawn true to within a pixel. The rounding of a derived side
// to whole pixels stays below it from about 500 px on.
constexpr double kSquarePixelTolerance = 1e-3;

// Throws InputError, naming the option and the window's aspect ratio, for a side outside
// [1, kMaxImageSidePx] (given, or following from the other side and the window) or more than
// kMaxImagePixels pixels. With neither side given the width is `defaultWidthPx`, moved to the
// nearest width whose rounded height keeps pixels square (within kSquarePixelTolerance) where
// one lies within a tenth of it: 320 on a 3:2 window gives 321x214, not 320x213.
ImageSize resolveImageSize(const Window& window, std::optional<int> widthPx, std::optional<int> heightPx,
                           int defaultWidthPx = kDefaultWidthPx);

// The same for an aspect ratio (width / height) that `aspectSource` names in messages, e.g.
// "the window's" or "the calibrated image's".
ImageSize resolveImageSize(double aspect, std::string_view aspectSource, std::optional<int> widthPx,
                           std::optional<int> heightPx, int defaultWidthPx = kDefaultWidthPx);

// How much taller than wide a pixel of `size` is when the image shows something of aspect ratio
// `aspect` (width / height): 0 square, 0.0016 for 320x213 of a 3:2 window, negative when wider.
double pixelStretch(double aspect, ImageSize size);

// A one-line warning when `size`'s pixels are not square against `aspect` (beyond
// kSquarePixelTolerance), else empty. It says by how much and the nearest sizes that keep them
// square: along the width when the width was given (or defaulted), the height when only the
// height was, and both sides when both were ("320x213 makes pixels 0.16 % taller than wide (the
// window is 1.5:1); --width 318 (212 high) or --width 321 (214 high) keeps them square").
// `shapeOf`: what square is measured against, for pixels meant to be non-square ("the
// calibrated 640x480 image's"); empty for square.
std::string pixelShapeWarning(double aspect, ImageSize size, bool widthGiven, bool heightGiven,
                              const std::string& shapeOf = {});

}  // namespace lenslab
