#pragma once
// The image's size in pixels. The window fixes the aspect ratio of what is seen; when only one
// side is given, the other follows the window so that pixels are square.
#include "camera/ViewSpec.h"

#include <optional>

namespace lenslab {

struct ImageSize {
  int widthPx = 0;
  int heightPx = 0;
};

constexpr int kDefaultWidthPx = 960;
constexpr int kMaxImageSidePx = 16384;

// Throws InputError for sizes outside [1, kMaxImageSidePx].
ImageSize resolveImageSize(const Window& window, std::optional<int> widthPx,
                           std::optional<int> heightPx);

// Relative difference between the image's and the window's aspect ratios (0 = square pixels).
double pixelAspectMismatch(const Window& window, ImageSize size);

}  // namespace lenslab
