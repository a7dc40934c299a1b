#pragma once
// Tiles are sub-windows (../shared/ARCHITECTURE.md). In the lecture's model the projection is fixed
// by the PRP and the window, a rectangle on the view plane. A rectangle of the image's pixels is
// then the same camera looking through the matching smaller rectangle of the window: the same VRP,
// VPN, VUP and PRP, only the window replaced. The sub-window is off-centre (an oblique projection,
// which clipFromEye already handles), and every pixel of it sees along exactly the rays of the
// full image's pixel at the same place: same pixel pitch on the view plane, so the same sub-pixel
// jitter, and viewThroughLens moves the PRP and the window of the sub-window as it does the full
// one's, so the same thin-lens views.
//
// A parallel projection's direction DOP = CW − PRP depends on the window's centre CW: the
// sub-window's PRP moves with its centre, so that DOP, and with it every ray, is unchanged.
#include "camera/Camera.h"
#include "camera/ImageSize.h"

#include <algorithm>

namespace lenslab {

// Pixels [x0, x1) × [y0, y1) of an image, rows from the top. May reach past the image's edges
// (an overscan margin).
struct PixelRect {
  int x0 = 0;
  int y0 = 0;
  int x1 = 0;
  int y1 = 0;

  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  ImageSize size() const { return {width(), height()}; }
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  bool operator==(const PixelRect&) const = default;
};

inline PixelRect intersect(const PixelRect& a, const PixelRect& b) {
  return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

// `rect` grown by `marginPx` (x: left and right, y: top and bottom).
inline PixelRect grown(const PixelRect& rect, int marginXPx, int marginYPx) {
  return {rect.x0 - marginXPx, rect.y0 - marginYPx, rect.x1 + marginXPx, rect.y1 + marginYPx};
}

// The window on the view plane that pixels `rect` of a `size` image of `window` cover.
Window subWindow(const Window& window, ImageSize size, const PixelRect& rect);

// `camera` seen through pixels `rect` of its `size` image: the window replaced by subWindow (and,
// for a parallel projection, the PRP moved with the window's centre). Lens effects stay attached:
// they are functions of the normalised position about the principal point, which does not move.
// The result has no calibrated size (its size is rect.size()).
Camera subWindowCamera(const Camera& camera, ImageSize size, const PixelRect& rect);

}  // namespace lenslab
