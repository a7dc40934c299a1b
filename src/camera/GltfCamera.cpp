#include "camera/GltfCamera.h"

#include <cmath>

namespace lenslab {
namespace {

// The node transform may carry scale; only its placement and orientation matter for a camera.
ViewSpec placed(const glm::dmat4& worldFromCamera, double focusDistance) {
  const glm::dvec3 eye(worldFromCamera[3]);
  const glm::dvec3 forward = glm::normalize(-glm::dvec3(worldFromCamera[2]));
  const glm::dvec3 up = glm::normalize(glm::dvec3(worldFromCamera[1]));
  ViewSpec spec;
  spec.vrp = eye + focusDistance * forward;
  spec.vpn = -forward;
  spec.vup = up;
  spec.prp = {0.0, 0.0, focusDistance};
  return spec;
}

}  // namespace

ViewSpec viewSpecFromGltfPerspective(const glm::dmat4& worldFromCamera, double yfovRadians, double aspectRatio,
                                     double znear, double zfar, double focusDistance) {
  ViewSpec spec = placed(worldFromCamera, focusDistance);
  spec.projection = Projection::Perspective;
  const double halfHeight = focusDistance * std::tan(0.5 * yfovRadians);
  const double halfWidth = aspectRatio * halfHeight;
  spec.window = {-halfWidth, -halfHeight, halfWidth, halfHeight};
  spec.nearDistance = znear;
  spec.farDistance = zfar;
  return spec;
}

ViewSpec viewSpecFromGltfOrthographic(const glm::dmat4& worldFromCamera, double xmag, double ymag, double znear,
                                      double zfar, double focusDistance) {
  ViewSpec spec = placed(worldFromCamera, focusDistance);
  spec.projection = Projection::Parallel;
  spec.window = {-xmag, -ymag, xmag, ymag};
  spec.nearDistance = znear;
  spec.farDistance = zfar;
  return spec;
}

}  // namespace lenslab
