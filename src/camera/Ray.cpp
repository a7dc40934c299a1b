#include "camera/Ray.h"

#include "camera/Projection.h"

namespace lenslab {

glm::dvec3 viewPlanePoint(const ViewSpec& spec, glm::dvec2 uv) {
  const ViewBasis b = viewBasis(spec);
  return spec.vrp + uv.x * b.u + uv.y * b.v;
}

Ray primaryRay(const ViewSpec& spec, glm::dvec2 uv) {
  const ViewBasis b = viewBasis(spec);
  Ray ray;
  if (spec.projection == Projection::Perspective) {
    ray.origin = prpWorld(spec);
    // From the PRP toward the view-plane point, built from the window point's offset over the PRP's
    // distance, (uv − PRP.uv) / PRP.n, and never as target − origin: with the view plane 1e-15 from
    // the PRP those two world points agree in all but their last digits, and their difference would
    // keep none of the window's.
    const glm::dvec2 slope = normalisedFromWindow(spec, uv);
    ray.direction = glm::normalize(slope.x * b.u + slope.y * b.v - b.n);
  } else {
    const glm::dvec3 target = viewPlanePoint(spec, uv);
    const glm::dvec3 dop = directionOfProjection(spec);
    const glm::dvec3 dopWorld = dop.x * b.u + dop.y * b.v + dop.z * b.n;
    // Step back along DOP from the view plane to the PRP's plane: dop.z = −PRP.n, so one DOP.
    ray.origin = target - dopWorld;
    ray.direction = glm::normalize(dopWorld);
  }
  // Depth along −n grows by cosTheta per unit of t.
  const double cosTheta = -glm::dot(ray.direction, b.n);
  ray.tNear = spec.nearDistance / cosTheta;
  ray.tFar = spec.farDistance / cosTheta;
  return ray;
}

Ray lensRay(const Camera& camera, glm::dvec2 lensOffset, glm::dvec2 pixel, ImageSize size, double inverseFocusShift) {
  const ViewSpec view = viewThroughLens(camera, lensOffset, {0.0, 0.0}, inverseFocusShift);
  return primaryRay(view, windowFromPixel(view.window, pixel, size.widthPx, size.heightPx));
}

}  // namespace lenslab
