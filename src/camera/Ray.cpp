#include "camera/Ray.h"

#include "camera/Projection.h"

namespace lenslab {

glm::dvec3 viewPlanePoint(const ViewSpec& spec, glm::dvec2 uv) {
  const ViewBasis b = viewBasis(spec);
  return spec.vrp + uv.x * b.u + uv.y * b.v;
}

Ray primaryRay(const ViewSpec& spec, glm::dvec2 uv) {
  const ViewBasis b = viewBasis(spec);
  const glm::dvec3 target = viewPlanePoint(spec, uv);
  Ray ray;
  if (spec.projection == Projection::Perspective) {
    ray.origin = prpWorld(spec);
    ray.direction = glm::normalize(target - ray.origin);
  } else {
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
