#include "render/RasterDepth.h"

#include "camera/Projection.h"
#include "camera/SubWindow.h"
#include "render/Renderer.h"

#include <vector>

namespace lenslab {

DepthAtPixel rasterDepth(Renderer& renderer) {
  return [&renderer](const Camera& camera, ImageSize size, int x, int y) {
    // Only pixel (x, y) is needed: it is rendered alone, through its own sub-window (camera/SubWindow.h),
    // which sees along the same ray through its centre at any image size.
    const Camera pixel = subWindowCamera(camera, size, {x, y, x + 1, y + 1});
    const std::vector<float> depth = renderer.pinholeDepth(pixel, {1, 1});
    return depthFromReverseZ(pixel.view, depth[0]);
  };
}

}  // namespace lenslab
