#include "plan/FramePlan.h"

#include "core/Text.h"

namespace lenslab {

FramePlan makeFramePlan(const Scene& scene, const Camera& camera) {
  FramePlan plan;
  plan.apertureSamples = 1;
  if (camera.apertureRadius > 0.0) {
    // Depth of field by accumulating aperture samples is issue #3; until then say so rather than
    // pretend: the image is the pinhole view from the lens centre.
    plan.samplesWhy = "depth of field is not implemented yet: the lens is rendered as a pinhole";
    plan.warnings.push_back(cat("the camera has an aperture (radius ", camera.apertureRadius,
                                " world units) but depth of field is not implemented yet; rendering it as a pinhole"));
  } else {
    plan.samplesWhy = "pinhole camera: one view from the PRP";
  }
  const std::size_t triangles = scene.triangleCount();
  plan.passes.push_back({"scene", cat("one view of ", triangles, " triangles into a float target")});
  return plan;
}

}  // namespace lenslab
