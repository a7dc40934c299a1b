#pragma once
// The frame plan: per scene and camera, which passes run and how many aperture samples.
// Nothing a scene does not need: a pinhole camera with no lens effects is one plain scene pass,
// and so is a scene wholly inside the depth of field (every circle of confusion ≤ 1 pixel). Each
// lens effect adds its pass or shader variant only when its strength is not zero:
//   distortion, lateral colour → the "lens" post pass (and an overscanned scene render);
//   axial colour               → three views per aperture sample, one per colour channel;
//   field curvature            → the field-curvature variant: views summed through a warp.
// The last two change nothing through a pinhole, and are left out for one.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "camera/LensMap.h"
#include "lens/AperturePattern.h"
#include "scene/Scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lenslab {

struct PlanOptions {
  AperturePattern pattern = AperturePattern::Concentric;
  int apertureSamples = 0;  // 0 = auto: from the largest circle of confusion in view
  int maxSamples = 256;     // the cap on auto
  std::uint32_t seed = 1;
};

struct PlannedPass {
  std::string name;  // "scene", "accumulate", "resolve", "lens"
  std::string why;   // one line, shown by --stats and `lenslab info`
  std::vector<std::string> variants;  // shader variants in use, e.g. "field-curvature"
};

struct FramePlan {
  std::vector<PlannedPass> passes;
  int apertureSamples = 1;      // scene passes, one per point of the aperture
  std::string samplesWhy;       // why that many
  AperturePattern pattern = AperturePattern::Concentric;
  std::uint32_t seed = 1;
  double cocMinPx = 0.0;        // circle of confusion over the part of the scene in view, pixels
  double cocMaxPx = 0.0;
  double depthMin = 0.0;        // that part's depth range, world units from the PRP along −n
  double depthMax = 0.0;
  std::vector<std::string> warnings;  // what the plan could not honour, for stderr
  int viewsPerSample = 1;       // 3 with axial chromatic aberration: one per colour channel
  bool fieldCurvature = false;  // the views are summed through the curved focal surface's warp
  bool remap = false;           // the lens post pass runs (distortion, lateral colour)
  Overscan overscan;            // what the scene passes render: the image, or more for the lens pass

  bool accumulates() const { return apertureSamples > 1; }
};

// Auto sample count for a largest circle of confusion of `cocPx` pixels: enough aperture points
// that their copies of a point, spread over the circle's area π·c²/4, lie about a pixel apart.
int autoApertureSamples(double cocPx, int maxSamples);

FramePlan makeFramePlan(const Scene& scene, const Camera& camera, ImageSize size,
                        const PlanOptions& options = {});

}  // namespace lenslab
