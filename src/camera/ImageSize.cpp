#include "camera/ImageSize.h"

#include "core/Error.h"
#include "core/Text.h"

#include <cmath>
#include <cstdio>

namespace lenslab {
namespace {

int checked(const char* option, int value) {
  if (value < 1 || value > kMaxImageSidePx)
    throw InputError(cat("--", option, " is ", value, "; give a whole number of pixels from 1 to ", kMaxImageSidePx));
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

// The side across `given` (the height for a width) that keeps pixels square, rounded.
int across(double aspect, int given, bool byWidth) {
  return static_cast<int>(std::lround(byWidth ? given / aspect : given * aspect));
}

ImageSize sizeFrom(double aspect, int given, bool byWidth) {
  const int other = across(aspect, given, byWidth);
  return byWidth ? ImageSize{given, other} : ImageSize{other, given};
}

bool square(double aspect, ImageSize size) {
  return size.widthPx >= 1 && size.heightPx >= 1 && std::abs(pixelStretch(aspect, size)) <= kSquarePixelTolerance;
}

// The nearest sides below and above `given` (along the width, or the height) whose other side,
// rounded, keeps pixels square; none where no such side lies within `reach`.
struct SquareSides {
  std::optional<int> below, above;
};
SquareSides squareSidesNear(double aspect, int given, bool byWidth, int reach) {
  SquareSides s;
  for (int d = 1; d <= reach && (!s.below || !s.above); ++d) {
    if (!s.below && given - d >= 1 && square(aspect, sizeFrom(aspect, given - d, byWidth))) s.below = given - d;
    if (!s.above && given + d <= kMaxImageSidePx && square(aspect, sizeFrom(aspect, given + d, byWidth)))
      s.above = given + d;
  }
  return s;
}

// 0.16, 2.5, 50: two significant digits, no exponent.
std::string percent(double fraction) {
  char text[32];
  const double p = 100.0 * fraction;
  std::snprintf(text, sizeof text, p >= 10.0 ? "%.0f" : "%.2g", p);
  return text;
}

}  // namespace

double pixelStretch(double aspect, ImageSize size) {
  return static_cast<double>(size.widthPx) / (static_cast<double>(size.heightPx) * aspect) - 1.0;
}

std::string pixelShapeWarning(double aspect, ImageSize size, bool widthGiven, bool heightGiven,
                              const std::string& shapeOf) {
  if (!(aspect > 0.0) || !std::isfinite(aspect) || square(aspect, size)) return {};
  const double stretch = pixelStretch(aspect, size);
  // A pixel's height over its width is 1 + stretch.
  const std::string how =
      stretch > 0.0 ? cat(percent(stretch), " % taller") : cat(percent(1.0 / (1.0 + stretch) - 1.0), " % wider");
  const std::string against =
      shapeOf.empty() ? (stretch > 0.0 ? " than wide" : " than tall") : cat(" than in ", shapeOf);
  char ratio[32];
  std::snprintf(ratio, sizeof ratio, "%.4g", aspect);
  std::string text = cat(size.widthPx, "x", size.heightPx, " makes pixels ", how, against,
                         shapeOf.empty() ? cat(" (the window is ", ratio, ":1)") : std::string());
  const std::string keeps = shapeOf.empty() ? " keeps them square" : " keeps their shape";
  const bool byWidth = widthGiven || !heightGiven;
  const int given = byWidth ? size.widthPx : size.heightPx;
  const SquareSides near = squareSidesNear(aspect, given, byWidth, std::max(16, given / 4));
  const auto option = [&](int side) {
    const ImageSize s = sizeFrom(aspect, side, byWidth);
    if (widthGiven && heightGiven) return cat("--width ", s.widthPx, " --height ", s.heightPx);
    return byWidth ? cat("--width ", side, " (", s.heightPx, " high)")
                   : cat("--height ", side, " (", s.widthPx, " wide)");
  };
  if (near.below && near.above)
    text += cat("; ", option(*near.below), " or ", option(*near.above), keeps);
  else if (near.below || near.above)
    text += cat("; ", option(near.below ? *near.below : *near.above), keeps);
  if (widthGiven && heightGiven) text += " (or give only --width or --height: the other side follows)";
  return text;
}

ImageSize resolveImageSize(double aspect, std::string_view aspectSource, std::optional<int> widthPx,
                           std::optional<int> heightPx, int defaultWidthPx) {
  if (widthPx && heightPx)
    return checkedTotal({checked("width", *widthPx), checked("height", *heightPx)}, aspect, aspectSource);
  if (heightPx) {
    const int h = checked("height", *heightPx);
    return checkedTotal({derived(h * aspect, "--height", h, "width", aspect, aspectSource), h}, aspect, aspectSource);
  }
  int w = widthPx ? checked("width", *widthPx) : defaultWidthPx;
  if (!widthPx && std::isfinite(aspect) && aspect > 0.0 && w / aspect >= 0.5 && w / aspect <= kMaxImageSidePx &&
      !square(aspect, sizeFrom(aspect, w, true))) {
    // Nobody asked for this width: take the nearest that keeps pixels square.
    const SquareSides near = squareSidesNear(aspect, w, true, std::max(1, w / 10));
    if (near.below && near.above)
      w = w - *near.below <= *near.above - w ? *near.below : *near.above;
    else if (near.below || near.above)
      w = near.below ? *near.below : *near.above;
  }
  const char* option = widthPx ? "--width" : "the default --width";
  return checkedTotal({w, derived(w / aspect, option, w, "height", aspect, aspectSource)}, aspect, aspectSource);
}

ImageSize resolveImageSize(const Window& window, std::optional<int> widthPx, std::optional<int> heightPx,
                           int defaultWidthPx) {
  return resolveImageSize(window.width() / window.height(), "the window's", widthPx, heightPx, defaultWidthPx);
}

}  // namespace lenslab
