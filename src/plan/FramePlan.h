#pragma once
// The frame plan: per scene and camera, which passes run and how many aperture samples.
// Nothing a scene does not need: a pinhole camera with no lens effects is one plain scene pass.
#include "camera/Camera.h"
#include "scene/Scene.h"

#include <string>
#include <vector>

namespace lenslab {

struct PlannedPass {
  std::string name;  // "scene", later "accumulate", "resolve", "distortion", ...
  std::string why;   // one line, shown by --stats and `lenslab info`
};

struct FramePlan {
  std::vector<PlannedPass> passes;
  int apertureSamples = 1;      // scene passes, one per point of the aperture
  std::string samplesWhy;       // why that many
  std::vector<std::string> warnings;  // what the plan could not honour, for stderr
};

FramePlan makeFramePlan(const Scene& scene, const Camera& camera);

}  // namespace lenslab
