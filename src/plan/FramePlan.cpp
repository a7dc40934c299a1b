#include "plan/FramePlan.h"

#include "core/Text.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lenslab {

int autoApertureSamples(double cocPx, int maxSamples) {
  if (!(cocPx > 1.0)) return 1;
  const double n = std::ceil(std::numbers::pi / 4.0 * cocPx * cocPx);
  return static_cast<int>(std::clamp(n, 2.0, static_cast<double>(std::max(maxSamples, 1))));
}

namespace {

// Depth range of the scene's bounds seen from the PRP, clipped to [near, far].
void depthRange(const Scene& scene, const Camera& camera, FramePlan& plan) {
  const ViewBasis b = viewBasis(camera.view);
  const glm::dvec3 prp = prpWorld(camera.view);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  if (!scene.bounds.empty())
    for (int corner = 0; corner < 8; ++corner) {
      const glm::dvec3 p((corner & 1) ? scene.bounds.max.x : scene.bounds.min.x,
                         (corner & 2) ? scene.bounds.max.y : scene.bounds.min.y,
                         (corner & 4) ? scene.bounds.max.z : scene.bounds.min.z);
      const double depth = glm::dot(p - prp, -b.n);
      lo = std::min(lo, depth);
      hi = std::max(hi, depth);
    }
  plan.depthMin = std::max(lo, camera.view.nearDistance);
  plan.depthMax = std::min(hi, camera.view.farDistance);
}

}  // namespace

FramePlan makeFramePlan(const Scene& scene, const Camera& camera, ImageSize size, const PlanOptions& options) {
  FramePlan plan;
  plan.pattern = options.pattern;
  plan.seed = options.seed;
  const std::size_t triangles = scene.triangleCount();
  depthRange(scene, camera, plan);
  const bool visible = plan.depthMax >= plan.depthMin && plan.depthMax > 0.0;

  if (camera.isPinhole()) {
    plan.apertureSamples = 1;
    plan.samplesWhy = "pinhole camera: one view from the PRP";
  } else {
    const double pxPerWindowUnit = size.widthPx / camera.view.window.width();
    if (visible) {
      const double atNear = cocDiameterOnWindow(camera, plan.depthMin) * pxPerWindowUnit;
      const double atFar = cocDiameterOnWindow(camera, plan.depthMax) * pxPerWindowUnit;
      plan.cocMaxPx = std::max(atNear, atFar);
      // The circle shrinks to nothing on the plane of focus, and grows away from it on both sides.
      const double focus = camera.focusAtInfinity ? std::numeric_limits<double>::infinity()
                         : camera.view.projection == Projection::Parallel ? camera.view.prp.z
                                                                          : 1.0 / camera.inverseFocusDistance();
      plan.cocMinPx = (focus >= plan.depthMin && focus <= plan.depthMax) ? 0.0 : std::min(atNear, atFar);
    }
    const std::string range = cat("circle of confusion ", plan.cocMinPx, " to ", plan.cocMaxPx,
                                  " px over depths ", plan.depthMin, " to ", plan.depthMax);
    if (options.pattern == AperturePattern::Lecture17) {
      plan.apertureSamples = 17;
      plan.samplesWhy = cat("the lecture's 17-point pattern (", range, ")");
    } else if (options.apertureSamples > 0) {
      plan.apertureSamples = options.apertureSamples;
      plan.samplesWhy = cat("as asked (", range, ")");
    } else {
      plan.apertureSamples = autoApertureSamples(plan.cocMaxPx, options.maxSamples);
      if (plan.apertureSamples == 1)
        plan.samplesWhy = cat("the scene lies inside the depth of field: ", range);
      else
        plan.samplesWhy = cat("auto: ceil(pi/4 x ", plan.cocMaxPx, "^2)", 
                              plan.apertureSamples == options.maxSamples ? cat(" capped at --max-samples ", options.maxSamples) : std::string(),
                              " (", range, ")");
    }
  }

  if (plan.apertureSamples == 1) {
    plan.passes.push_back({"scene", cat("one view of ", triangles, " triangles into a float target")});
  } else {
    plan.passes.push_back({"scene", cat(plan.apertureSamples, " views of ", triangles, " triangles, one from each ",
                                        patternName(plan.pattern), " aperture point, with sub-pixel jitter")});
    plan.passes.push_back({"accumulate", cat("adds each view into a float sum (", plan.apertureSamples, " times)")});
    plan.passes.push_back({"resolve", "divides the sum by the sample count"});
  }
  return plan;
}

}  // namespace lenslab
