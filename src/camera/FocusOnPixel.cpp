#include "camera/FocusOnPixel.h"

#include "camera/ImageMap.h"
#include "core/Error.h"
#include "core/Text.h"

#include <cmath>

namespace lenslab {

SelectedCamera focusOnPixel(const SelectedCamera& selected, ImageSize size, glm::dvec2 pixel,
                            const DepthAtPixel& depthAt, const std::string& asked) {
  const Camera& camera = selected.camera;
  const int x = static_cast<int>(std::floor(pixel.x)), y = static_cast<int>(std::floor(pixel.y));
  if (x < 0 || y < 0 || x >= size.widthPx || y >= size.heightPx)
    throw InputError(cat(asked, " ", pixel.x, ",", pixel.y, ": the pixel is outside the ", size.widthPx, "x",
                         size.heightPx, " image"));
  double distance = 0.0;
  if (camera.lens.effects.needsRemap()) {
    const glm::dvec2 centre(x + 0.5, y + 0.5);
    const ThinLensMap map = ThinLensMap(camera, size).overscanned();
    const Overscan& o = map.overscan();
    const glm::dvec2 p = map.renderPixelFromOutput(centre);
    distance = depthAt(o.camera, o.size, static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)));
  } else {
    distance = depthAt(camera, size, x, y);
  }
  if (!std::isfinite(distance) || !(distance > 0.0))
    throw InputError(cat(asked, " ", pixel.x, ",", pixel.y, ": nothing of the scene is under that pixel to focus on"));
  SelectedCamera c = refocused(selected, distance, cat(asked, " ", pixel.x, ",", pixel.y));
  c.camera.source += cat(", focused at pixel ", pixel.x, ",", pixel.y, " (depth ", distance, ")");
  return c;
}

}  // namespace lenslab
