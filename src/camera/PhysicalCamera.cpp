#include "camera/PhysicalCamera.h"

#include "core/Error.h"
#include "core/Text.h"
#include "lens/ThinLens.h"

#include <cmath>
#include <utility>

namespace lenslab {
namespace {

bool finite(const glm::dvec3& a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }

[[noreturn]] void fail(std::string_view where, const std::string& message) {
  throw InputError(cat(where, ": ", message));
}

}  // namespace

void validate(const PhysicalCamera& c, std::string_view where) {
  if (!finite(c.eye)) fail(where, "eye must be three finite numbers");
  if (!finite(c.target)) fail(where, "target must be three finite numbers");
  if (!finite(c.up)) fail(where, "up must be three finite numbers");
  if (!(std::isfinite(c.focalLengthMm) && c.focalLengthMm > 0.0))
    fail(where, cat("focal_length_mm is ", c.focalLengthMm, "; give a positive number of millimetres"));
  if (!(std::isfinite(c.sensorMm.x) && std::isfinite(c.sensorMm.y) && c.sensorMm.x > 0.0 && c.sensorMm.y > 0.0))
    fail(where, "sensor_mm must be two positive numbers [width, height] in millimetres");
  // A thin lens in air cannot be faster than f/0.5 (a numerical aperture of 1: the aperture's
  // radius reaches the focal length); below that the "lens" is an aperture of any size, and at
  // f/1e-320 a radius past every float.
  if (!(c.fNumber >= 0.5))
    fail(where, cat("f_number is ", c.fNumber,
                    "; no lens in air is faster than f/0.5: give 0.5 or more (e.g. 2.8), "
                    "or leave it out for a pinhole"));
  const glm::dvec3 forward = c.target - c.eye;
  const double distance = glm::length(forward);
  if (!(distance > 0.0)) fail(where, "eye and target are the same point; the view direction is undefined");
  if (!(glm::length(c.up) > 0.0)) fail(where, "up is the zero vector");
  if (glm::length(glm::cross(glm::normalize(c.up), forward / distance)) < 1e-9)
    fail(where, "up is parallel to the view direction (target - eye); give an up direction across it");
  const double f = c.focalLengthMm * kMetresPerMillimetre;
  if (std::isnan(c.focusDistance) || !(c.focusDistance > f))
    fail(where, cat("focus_distance is ", c.focusDistance, "; it must be beyond the focal length (", f,
                    " world units), or the lens forms no real image; \"infinity\" is allowed"));
  if (!(std::isfinite(c.nearDistance) && c.nearDistance > 0.0))
    fail(where, cat("near is ", c.nearDistance, "; give a positive distance"));
  if (std::isnan(c.farDistance) || !(c.farDistance > c.nearDistance))
    fail(where, cat("near (", c.nearDistance, ") must be less than far (", c.farDistance, ")"));
}

double imageDistance(double focalLength, double focusDistance) {
  // 1/∞ = 0: focus at infinity needs no special case there.
  return imageDistanceFromInverse(focalLength, 1.0 / focusDistance);
}

double viewPlaneDistance(const PhysicalCamera& c) {
  const double toTarget = glm::length(c.target - c.eye);
  return viewPlaneDistanceFor(c.focusDistance, toTarget);
}

ViewSpec toViewSpec(const PhysicalCamera& c) {
  const double f = c.focalLengthMm * kMetresPerMillimetre;
  const double d = viewPlaneDistance(c);
  // z_i from 1/z_f (0 at infinity): a focus of 1e300 gives z_i = f, as infinity does.
  const double zi = imageDistanceFromInverse(f, 1.0 / c.focusDistance);
  // The sensor seen back through the lens centre, on the view plane.
  const glm::dvec2 windowSize = c.sensorMm * kMetresPerMillimetre * (d / zi);
  const glm::dvec3 forward = glm::normalize(c.target - c.eye);

  ViewSpec spec;
  spec.projection = Projection::Perspective;
  spec.vrp = c.eye + d * forward;
  spec.vpn = -forward;
  spec.vup = c.up;
  spec.prp = {0.0, 0.0, d};
  spec.window = {-0.5 * windowSize.x, -0.5 * windowSize.y, 0.5 * windowSize.x, 0.5 * windowSize.y};
  spec.nearDistance = c.nearDistance;
  spec.farDistance = c.farDistance;
  return spec;
}

Camera toCamera(const PhysicalCamera& c, std::string source) {
  Camera camera = cameraFocusedOnViewPlane(toViewSpec(c), apertureRadius(c), std::move(source));
  if (camera.view.prp.z != c.focusDistance) camera.inverseFocusOffPlane = 1.0 / c.focusDistance;
  return camera;
}

Camera toCamera(const PhysicalCamera& c, const Lens& lens, std::string source) {
  Camera camera = toCamera(c, std::move(source));
  const double radius = camera.lens.apertureRadius;
  camera.lens = lens;
  camera.lens.apertureRadius = radius;
  return camera;
}

SelectedCamera toSelectedCamera(const PhysicalCamera& camera, const Camera& like, std::string source) {
  SelectedCamera out{toCamera(camera, like.lens, std::move(source)), camera};
  out.camera.calibratedSize = like.calibratedSize;
  out.camera.nearFromScene = like.nearFromScene;
  out.camera.farFromScene = like.farFromScene;
  return out;
}

SelectedCamera refocused(const SelectedCamera& camera, double distance, const std::string& where) {
  if (!camera.physical) return {refocused(camera.camera, distance, where), std::nullopt};
  PhysicalCamera p = *camera.physical;
  p.focusDistance = distance;
  validate(p, where);
  return toSelectedCamera(p, camera.camera, camera.camera.source);
}

double apertureRadius(const PhysicalCamera& c) {
  if (std::isinf(c.fNumber)) return 0.0;
  return c.focalLengthMm * kMetresPerMillimetre / (2.0 * c.fNumber);
}

double verticalFovRadians(const PhysicalCamera& c) {
  const double f = c.focalLengthMm * kMetresPerMillimetre;
  const double zi = imageDistance(f, c.focusDistance);
  return 2.0 * std::atan(c.sensorMm.y * kMetresPerMillimetre / (2.0 * zi));
}

PhysicalCamera toPhysical(const Camera& camera, glm::dvec2 sensorMm) {
  const ViewSpec& spec = camera.view;
  const ViewBasis b = viewBasis(spec);
  PhysicalCamera c;
  c.eye = prpWorld(spec);
  c.focusDistance = camera.focusDistance();
  c.target = c.eye - spec.prp.z * b.n;
  c.up = b.v;
  c.sensorMm = sensorMm;
  // window = sensor · d / z_i  ⇒  z_i = sensor · d / window;  1/f = 1/z_i + 1/z_f.
  const double zi = sensorMm.x * kMetresPerMillimetre * spec.prp.z / spec.window.width();
  const double f = 1.0 / (1.0 / zi + camera.inverseFocusDistance());
  c.focalLengthMm = f / kMetresPerMillimetre;
  c.nearDistance = spec.nearDistance;
  c.farDistance = spec.farDistance;
  return c;
}

}  // namespace lenslab
