#include "raycast/AovRender.h"

#include "camera/ViewSpec.h"
#include "core/Error.h"
#include "core/Text.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

namespace lenslab {

void requireExactInstances(const Scene& scene) {
  // Float holds every integer to 2^24 exactly, and skips odd ones beyond.
  for (const Instance& instance : scene.instances)
    if (instance.gltfNode > kMaxExactInstance)
      throw InputError(cat(scene.source, ": node ", instance.gltfNode, " has an index beyond 2^24 = ",
                           kMaxExactInstance, ", the largest the float instance AOV holds exactly"));
}

AovImages aovImagesThrough(const ImageMap& map, const AovSelection& selection,
                           const std::function<AovSurface(glm::dvec2 pixel)>& firstSurface) {
  const ImageSize size = map.size();
  AovImages out;
  out.widthPx = size.widthPx;
  out.heightPx = size.heightPx;
  const auto pixels = static_cast<std::size_t>(size.pixelCount());
  if (selection.depth) out.depth.resize(pixels);
  if (selection.normal) out.normal.resize(3 * pixels);
  if (selection.albedo) out.albedo.resize(3 * pixels);
  if (selection.instance) out.instance.resize(pixels);
  const ViewBasis basis = viewBasis(map.camera().view);
  tbb::parallel_for(tbb::blocked_range<int>(0, size.heightPx), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < size.widthPx; ++x) {
        const AovSurface hit = firstSurface({x + 0.5, y + 0.5});
        const std::size_t i = static_cast<std::size_t>(y) * size.widthPx + x;
        if (selection.depth)
          out.depth[i] = std::isinf(hit.depth) ? std::numeric_limits<float>::infinity() : static_cast<float>(hit.depth);
        if (selection.normal && hit.surface) {
          // Camera space: the world normal's components along u, v and n.
          const glm::dvec3 n(hit.normal);
          const glm::dvec3 cameraNormal(glm::dot(n, basis.u), glm::dot(n, basis.v), glm::dot(n, basis.n));
          for (int k = 0; k < 3; ++k) out.normal[3 * i + k] = static_cast<float>(cameraNormal[k]);
        }
        if (selection.albedo && hit.surface)
          for (int k = 0; k < 3; ++k) out.albedo[3 * i + k] = hit.albedo[k];
        if (selection.instance) out.instance[i] = hit.surface ? static_cast<float>(hit.gltfNode) : kNoSurfaceInstance;
      }
  });
  return out;
}

}  // namespace lenslab
