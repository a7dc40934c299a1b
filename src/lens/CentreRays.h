#pragma once
// The line each pixel of a real lens's image lies on: for ground truth (the AOVs) one ray per
// pixel that lines up with the image the lens makes. A real lens has no single ray per film
// point: the bundle that leaves the lens from it fills the exit pupil, cut by the stop and by the
// rims (the cat's eye), and the pixel shows the bundle's blur. Its centre is where the pixel's
// image is: the bundle's mean line (each ray weighted by the light it carries), the same line the
// fitted thin lens's distortion is fitted to (lens/LensFitBundles.h). The pixel centre's AOVs are
// the first surface on that line.
//
// The lens is symmetric about its axis, so the mean line of a film point depends on its radius
// only: it is traced once per radius over the film, and turned to each pixel's azimuth.
// Pure math (GLM + std), no GL.
#include "lens/LensCamera.h"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace lenslab {

class CentreRays {
 public:
  // The mean lines of `camera`'s film points for `channel` (green's, 1, for the AOVs), traced
  // through an n × n grid of each radius's exit-pupil box at `radii` radii from the centre to the
  // sensor's corner.
  explicit CentreRays(const LensCamera& camera, int channel = 1, int radii = 257, int pupilSamples = 48);

  // The mean line through continuous pixel position `pixel` of a width × height image, as a
  // world ray leaving the first vertex's plane (its weight: the film point's relative
  // illumination); nullopt where the lens passes no light from there.
  std::optional<LensCamera::WorldRay> at(glm::dvec2 pixel, int widthPx, int heightPx) const;

 private:
  struct Line {
    double a = 0.0;      // mm off the axis where the line crosses the entrance pupil's plane
    double b = 0.0;      // its slope: mm off the axis per mm of depth in front of the pupil
    double share = 0.0;  // relative illumination; 0: nothing passes
  };
  LensCamera camera_;
  double stepMm_ = 0.0;
  std::vector<Line> lines_;  // at radius i · stepMm_ along the film's x axis
};

}  // namespace lenslab
