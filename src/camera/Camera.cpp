#include "camera/Camera.h"

#include "camera/Projection.h"
#include "core/Error.h"
#include "core/Text.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lenslab {

Camera cameraFocusedOnViewPlane(const ViewSpec& view, double apertureRadius, std::string source) {
  Camera c;
  c.view = view;
  c.lens.apertureRadius = apertureRadius;
  c.source = std::move(source);
  return c;
}

ImageSize resolveImageSize(const Camera& camera, std::optional<int> widthPx, std::optional<int> heightPx,
                           int defaultWidthPx) {
  if (!camera.calibratedSize || (widthPx && heightPx))
    return resolveImageSize(camera.view.window, widthPx, heightPx, defaultWidthPx);
  // A calibrated camera's pixels need not be square (fx ≠ fy): scale its own size.
  const ImageSize own = *camera.calibratedSize;
  if (!widthPx && !heightPx) return resolveImageSize(camera.view.window, own.widthPx, own.heightPx);
  const double aspect = static_cast<double>(own.widthPx) / own.heightPx;
  return resolveImageSize(aspect, "the calibrated image's", widthPx, heightPx);
}

std::string pixelShapeWarning(const Camera& camera, std::optional<int> widthPx, std::optional<int> heightPx,
                              ImageSize size) {
  const bool widthGiven = widthPx.has_value(), heightGiven = heightPx.has_value();
  if (!camera.calibratedSize)
    return pixelShapeWarning(camera.view.window.width() / camera.view.window.height(), size, widthGiven, heightGiven);
  // Calibrated pixels need not be square (fx ≠ fy): the shape to keep is the calibration's.
  const ImageSize own = *camera.calibratedSize;
  const double aspect = camera.view.window.width() / camera.view.window.height();
  const double ownStretch = pixelStretch(aspect, own);
  // The pixel shape of `size` against that of the calibrated image: the same window, so the
  // stretch between them is the ratio of the two image aspects.
  return pixelShapeWarning(static_cast<double>(own.widthPx) / own.heightPx, size, widthGiven, heightGiven,
                           std::abs(ownStretch) <= kSquarePixelTolerance
                               ? std::string()
                               : cat("the calibrated ", own.widthPx, "x", own.heightPx, " image"));
}

double viewPlaneDistanceFor(double focusDistance, double nearDistance) {
  return focusDistance <= kMaxViewPlaneMove * nearDistance ? focusDistance : nearDistance;
}

double Camera::focusDistance() const {
  const double inverse = inverseFocusDistance();
  return inverse > 0.0 ? 1.0 / inverse : std::numeric_limits<double>::infinity();
}

ViewSpec viewThroughLens(const Camera& camera, glm::dvec2 lensOffset, glm::dvec2 pixelOffset,
                         double inverseFocusShift) {
  ViewSpec v = camera.view;
  v.prp.x += lensOffset.x;
  v.prp.y += lensOffset.y;
  // Perspective and parallel alike: a point at depth z_f lands on the same window point from every
  // aperture point when the window moves by 1 − d/z_f of the lens offset (0 on the view plane).
  // Parallel cameras have no lens effects, so no shift.
  const double focusShift = v.projection == Projection::Perspective ? inverseFocusShift : 0.0;
  const double windowTravel = !camera.inverseFocusOffPlane && focusShift == 0.0
                                  ? 0.0  // exactly, not 1 − d·(1/d)
                                  : 1.0 - v.prp.z * (camera.inverseFocusDistance() + focusShift);
  const glm::dvec2 shift = windowTravel * lensOffset + pixelOffset;
  // Sub-pixel jitter moves a parallel projection as a whole: with the PRP left behind, the DOP
  // would tilt and points off the view plane would smear across pixels (a lens nobody asked for).
  if (v.projection == Projection::Parallel) {
    v.prp.x += pixelOffset.x;
    v.prp.y += pixelOffset.y;
  }
  v.window.umin += shift.x;
  v.window.umax += shift.x;
  v.window.vmin += shift.y;
  v.window.vmax += shift.y;
  return v;
}

double cocDiameterOnWindow(const Camera& camera, double depth, double inverseFocusShift) {
  const double r =
      camera.lens.apertureRadius * (camera.lens.aperture.isRound() ? 1.0 : apertureReach(camera.lens.aperture));
  const double d = camera.view.prp.z;
  // Parallel: the ray from lens offset s meets depth z at s·(1 − z/z_f) from where the pinhole's does.
  if (camera.view.projection == Projection::Parallel)
    return 2.0 * r * std::abs(1.0 - depth * camera.inverseFocusDistance());
  return 2.0 * r * d * std::abs(camera.inverseFocusDistance() + inverseFocusShift - 1.0 / depth);
}

Camera refocused(const Camera& camera, double distance, const std::string& where) {
  if (std::isnan(distance) || !(distance > 0.0))
    throw InputError(cat(where, ": focus distance ", distance, " must be a positive distance or infinity"));
  Camera c = camera;
  if (c.view.projection == Projection::Parallel) {
    if (std::isinf(distance)) throw InputError(cat(where, ": a parallel projection cannot focus at infinity"));
  }
  if (viewPlaneDistanceFor(distance, c.view.prp.z) != distance) {
    // Computed as 1/z_f: 1/1e300 is a tiny number, not a view plane at 1e300.
    c.inverseFocusOffPlane = 1.0 / distance;
    return c;
  }
  // Move the view plane to the new plane of focus, keeping the PRP where it is in the world and,
  // for perspective, the field of view: the window scales about the principal point.
  const ViewBasis b = viewBasis(c.view);
  const glm::dvec3 prp = prpWorld(c.view);
  const double scale = c.view.projection == Projection::Perspective ? distance / c.view.prp.z : 1.0;
  const glm::dvec2 principal(c.view.prp.x, c.view.prp.y);
  Window& w = c.view.window;
  w = {principal.x + (w.umin - principal.x) * scale, principal.y + (w.vmin - principal.y) * scale,
       principal.x + (w.umax - principal.x) * scale, principal.y + (w.vmax - principal.y) * scale};
  if (c.view.projection == Projection::Parallel) {
    // DOP = CW − PRP keeps its direction: the PRP's (u, v) offset from the window centre scales too.
    const double ratio = distance / c.view.prp.z;
    const glm::dvec2 cw = w.center();
    c.view.prp.x = cw.x + (c.view.prp.x - cw.x) * ratio;
    c.view.prp.y = cw.y + (c.view.prp.y - cw.y) * ratio;
  }
  // New VRP: the PRP's foot on the new plane, minus the PRP's (u, v) so that coordinates carry over.
  c.view.vrp = prp - distance * b.n - c.view.prp.x * b.u - c.view.prp.y * b.v;
  c.view.prp.z = distance;
  c.inverseFocusOffPlane.reset();
  return c;
}

}  // namespace lenslab
