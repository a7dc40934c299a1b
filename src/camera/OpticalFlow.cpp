#include "camera/OpticalFlow.h"

#include <cmath>
#include <limits>

namespace lenslab {

std::vector<float> opticalFlow(const ThinLensMap& now, const AovImages& surfaces, const ThinLensMap* next,
                               const NodeMotion& motion) {
  const ImageSize size = now.size();
  const std::size_t pixels = static_cast<std::size_t>(size.pixelCount());
  std::vector<float> flow(2 * pixels, std::numeric_limits<float>::quiet_NaN());
  if (!next) return flow;
  const glm::dvec3 axis = -viewBasis(now.camera().view).n;
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(size.widthPx) + x;
      const double depth = surfaces.depth[i];
      if (!std::isfinite(depth)) continue;
      const std::optional<CameraRay> r = now.centreRay({x + 0.5, y + 0.5});
      if (!r) continue;
      // The depth AOV is measured along the axis from the lens centre, where the ray starts.
      const double along = glm::dot(r->ray.direction, axis);
      if (!(along > 0.0)) continue;
      const glm::dvec3 p = r->ray.origin + r->ray.direction * (depth / along);
      glm::dvec3 moved = p;
      if (const auto m = motion.find(static_cast<int>(surfaces.instance[i])); m != motion.end())
        moved = glm::dvec3(m->second * glm::dvec4(p, 1.0));
      const std::optional<glm::dvec2> from = now.pixelOfPoint(p);
      const std::optional<glm::dvec2> to = next->pixelOfPoint(moved);
      if (!from || !to) continue;
      flow[2 * i] = static_cast<float>(to->x - from->x);
      flow[2 * i + 1] = static_cast<float>(to->y - from->y);
    }
  return flow;
}

}  // namespace lenslab
