#include "camera/ImageSize.h"

#include "core/Error.h"
#include "core/Text.h"

#include <algorithm>
#include <cmath>

namespace lenslab {
namespace {

int checked(const char* option, int value) {
  if (value < 1 || value > kMaxImageSidePx)
    throw InputError(cat("--", option, " is ", value, "; give a whole number of pixels from 1 to ",
                         kMaxImageSidePx));
  return value;
}

int fromAspect(double pixels) {
  return std::clamp(static_cast<int>(std::lround(pixels)), 1, kMaxImageSidePx);
}

}  // namespace

ImageSize resolveImageSize(const Window& window, std::optional<int> widthPx,
                           std::optional<int> heightPx) {
  const double aspect = window.width() / window.height();
  if (widthPx && heightPx) return {checked("width", *widthPx), checked("height", *heightPx)};
  if (heightPx) {
    const int h = checked("height", *heightPx);
    return {fromAspect(h * aspect), h};
  }
  const int w = widthPx ? checked("width", *widthPx) : kDefaultWidthPx;
  return {w, fromAspect(w / aspect)};
}

double pixelAspectMismatch(const Window& window, ImageSize size) {
  const double windowAspect = window.width() / window.height();
  const double imageAspect = static_cast<double>(size.widthPx) / size.heightPx;
  return std::abs(imageAspect / windowAspect - 1.0);
}

}  // namespace lenslab
