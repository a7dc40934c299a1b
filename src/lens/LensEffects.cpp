#include "lens/LensEffects.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

std::optional<glm::dvec2> LensEffects::undistortChannel(Channel c, glm::dvec2 distorted, glm::dvec2 guess) const {
  // Lateral colour scales the channel's image about the principal point, after the distortion.
  const glm::dvec2 green = distorted / (1.0 + chromatic.lateral(c));
  return distortion.undistort(green, guess);
}

glm::dvec2 LensEffects::distortChannel(Channel c, glm::dvec2 undistorted) const {
  return distortion.distort(undistorted) * (1.0 + chromatic.lateral(c));
}

double LensEffects::inverseFocusShift(Channel c, glm::dvec2 undistorted) const {
  return chromatic.inverseFocusShift(c) + fieldCurvature.inverseFocusPerRadius2 * glm::dot(undistorted, undistorted);
}

}  // namespace lenslab
