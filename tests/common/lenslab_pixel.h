#pragma once
// Where lenslab puts a world point in the image of a camera: its own chain, world → the lecture's
// projection onto the window → normalised image coordinates → the lens's distortion → pixel
// (lenslab's pixel coordinates: the image's top-left corner at (0, 0), pixel centres at i + 0.5).
// Tests compare it with formulas written out from OpenCV's and COLMAP's documentation.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "camera/Projection.h"

#include <glm/glm.hpp>

namespace lenslab::test {

inline glm::dvec2 lenslabPixel(const Camera& camera, const glm::dvec3& world, ImageSize size) {
  const glm::dvec2 ideal = normalisedFromWindow(camera.view, projectToWindow(camera.view, world));
  const glm::dvec2 distorted = camera.lens.effects.distortion.distort(ideal);
  return pixelFromWindow(camera.view.window, windowFromNormalised(camera.view, distorted), size.widthPx, size.heightPx);
}

}  // namespace lenslab::test
