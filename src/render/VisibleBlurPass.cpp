#include "render/VisibleBlurPass.h"

#include "camera/Projection.h"
#include "render/Renderer.h"

#include <limits>

namespace lenslab {

VisibleBlur measureVisibleBlur(Renderer& renderer, const Camera& camera, ImageSize image) {
  const ImageSize prepass = prepassSizeFor(image);
  const std::vector<float> zNdc = renderer.pinholeDepth(camera, prepass);
  std::vector<double> depth(zNdc.size());
  for (std::size_t i = 0; i < zNdc.size(); ++i)
    depth[i] = zNdc[i] > 0.0f ? depthFromReverseZ(camera.view, zNdc[i]) : std::numeric_limits<double>::infinity();
  return visibleBlur(camera, image, prepass, depth, renderer.scene().environment != nullptr);
}

}  // namespace lenslab
