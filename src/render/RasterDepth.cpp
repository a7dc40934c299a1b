#include "render/RasterDepth.h"

#include "camera/Projection.h"
#include "render/Renderer.h"

#include <vector>

namespace lenslab {

DepthAtPixel rasterDepth(Renderer& renderer) {
  return [&renderer](const Camera& camera, ImageSize size, int x, int y) {
    const std::vector<float> depth = renderer.pinholeDepth(camera, size);
    const double zNdc = depth[static_cast<std::size_t>(y) * static_cast<std::size_t>(size.widthPx) + static_cast<std::size_t>(x)];
    return depthFromReverseZ(camera.view, zNdc);
  };
}

}  // namespace lenslab
