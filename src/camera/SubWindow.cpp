#include "camera/SubWindow.h"

#include "camera/Projection.h"

namespace lenslab {

Window subWindow(const Window& window, ImageSize size, const PixelRect& rect) {
  // Image rows run down, v runs up: the rect's top edge (y0) is its vmax.
  const glm::dvec2 topLeft = windowFromPixel(window, {rect.x0, rect.y0}, size.widthPx, size.heightPx);
  const glm::dvec2 bottomRight = windowFromPixel(window, {rect.x1, rect.y1}, size.widthPx, size.heightPx);
  return {topLeft.x, bottomRight.y, bottomRight.x, topLeft.y};
}

Camera subWindowCamera(const Camera& camera, ImageSize size, const PixelRect& rect) {
  Camera c = camera;
  c.view.window = subWindow(camera.view.window, size, rect);
  if (c.view.projection == Projection::Parallel) {
    const glm::dvec2 move = c.view.window.center() - camera.view.window.center();
    c.view.prp.x += move.x;
    c.view.prp.y += move.y;
  }
  c.calibratedSize.reset();
  return c;
}

}  // namespace lenslab
