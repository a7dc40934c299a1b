#include "camera/ImageSize.h"

#include "core/Error.h"
#include "core/Text.h"

#include <cmath>

namespace lenslab {
namespace {

int checked(const char* option, int value) {
  if (value < 1 || value > kMaxImageSidePx)
    throw InputError(cat("--", option, " is ", value, "; give a whole number of pixels from 1 to ",
                         kMaxImageSidePx));
  return value;
}

// The side that follows from the given one: computed in double, checked before it becomes an int.
int derived(double pixels, const char* givenOption, int given, const char* side, double aspect,
            std::string_view aspectSource) {
  const double rounded = std::round(pixels);
  if (!(rounded >= 1.0 && rounded <= kMaxImageSidePx))
    throw InputError(cat(givenOption, " ", given, " with ", aspectSource, " aspect ratio ", aspect,
                         " (width / height) gives a ", side, " of ", pixels, " px; the ", side, " must be 1 to ",
                         kMaxImageSidePx, " px: give both --width and --height, or a less extreme window"));
  return static_cast<int>(rounded);
}

ImageSize checkedTotal(ImageSize size, double aspect, std::string_view aspectSource) {
  if (size.pixelCount() > kMaxImagePixels)
    throw InputError(cat("--width/--height: ", size.widthPx, "x", size.heightPx, " (", aspectSource, " aspect ratio ",
                         aspect, ") is ", size.pixelCount(), " pixels; at most ", kMaxImagePixels,
                         " (2^30) pixels in all: give a smaller --width or --height"));
  return size;
}

}  // namespace

ImageSize resolveImageSize(double aspect, std::string_view aspectSource, std::optional<int> widthPx,
                           std::optional<int> heightPx) {
  if (widthPx && heightPx) return checkedTotal({checked("width", *widthPx), checked("height", *heightPx)}, aspect, aspectSource);
  if (heightPx) {
    const int h = checked("height", *heightPx);
    return checkedTotal({derived(h * aspect, "--height", h, "width", aspect, aspectSource), h}, aspect, aspectSource);
  }
  const int w = widthPx ? checked("width", *widthPx) : kDefaultWidthPx;
  const char* option = widthPx ? "--width" : "the default --width";
  return checkedTotal({w, derived(w / aspect, option, w, "height", aspect, aspectSource)}, aspect, aspectSource);
}

ImageSize resolveImageSize(const Window& window, std::optional<int> widthPx, std::optional<int> heightPx) {
  return resolveImageSize(window.width() / window.height(), "the window's", widthPx, heightPx);
}

double pixelAspectMismatch(const Window& window, ImageSize size) {
  const double windowAspect = window.width() / window.height();
  const double imageAspect = static_cast<double>(size.widthPx) / size.heightPx;
  return std::abs(imageAspect / windowAspect - 1.0);
}

}  // namespace lenslab
