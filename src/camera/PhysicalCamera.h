#pragma once
// A camera described as a photographer would: where it stands, where it looks, its lens and sensor.
// World units are metres (glTF's); lens and sensor sizes are millimetres, as printed on lenses.
//
// Conversion to the lecture's viewing description puts the window on the plane of focus
// (../shared/ARCHITECTURE.md), by the thin-lens relations:
//   image distance   z_i = f·z_f / (z_f − f)
//   window           = sensor × z_f / z_i        (the sensor, projected back through the lens centre)
//   field of view    = 2·atan(d / (2·z_i))      (the lecture's atan(d/2f) is the half angle at
//                                                infinity focus, where z_i = f)
//   aperture radius  = f / (2N)
#include "camera/Camera.h"
#include "camera/ViewSpec.h"

#include <glm/glm.hpp>

#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace lenslab {

struct PhysicalCamera {
  glm::dvec3 eye{0.0, 0.0, 5.0};                             // lens centre, world
  glm::dvec3 target{0.0};                                    // a point the camera looks at, world
  glm::dvec3 up{0.0, 1.0, 0.0};                              // world up
  double focalLengthMm = 35.0;                               // f
  glm::dvec2 sensorMm{36.0, 24.0};                           // sensor width, height
  double fNumber = std::numeric_limits<double>::infinity();  // N; infinity = pinhole
  double focusDistance = 5.0;  // z_f: distance from the lens to the plane of focus, world;
                               // +infinity allowed
  double nearDistance = 0.05;  // world
  double farDistance = std::numeric_limits<double>::infinity();
  // The exposure as a photographer sets it beside the f-number (camera/Exposure.h); none: the
  // image is not exposed physically.
  std::optional<double> shutterSeconds;  // t, seconds
  std::optional<double> iso;             // S, ISO arithmetic speed
};

constexpr double kMetresPerMillimetre = 1e-3;

// Throws InputError naming `where` for non-finite or non-positive values, eye == target, up
// parallel to the view direction, or focus at or inside the focal length (no real image).
void validate(const PhysicalCamera& camera, std::string_view where);

// Image distance z_i for focus distance z_f and focal length f (same units).
double imageDistance(double focalLength, double focusDistance);

// Where toViewSpec puts the view plane: on the plane of focus, unless focus lies further than
// kMaxViewPlaneMove × |target − eye| (or at infinity), which no well-conditioned view plane can
// hold: then at |target − eye|, with the focus carried as 1/z_f (see toCamera).
double viewPlaneDistance(const PhysicalCamera& camera);

// The viewing description: view plane at viewPlaneDistance, window = the sensor seen back through
// the lens centre on it (sensor × d / z_i).
ViewSpec toViewSpec(const PhysicalCamera& camera);

// The whole camera: view, aperture radius f/2N and focus.
Camera toCamera(const PhysicalCamera& camera, std::string source);
// The same with `lens`'s aperture shape, barrel and effects; the radius stays the description's
// f/2N. How a lens kept beside a physical description (a path's key, a camera being replaced)
// joins it.
Camera toCamera(const PhysicalCamera& camera, const Lens& lens, std::string source);

// A camera and, when it was given in the physical form, that description: what refocusing and the
// viewer's lens panel change.
struct SelectedCamera {
  Camera camera;
  std::optional<PhysicalCamera> physical;
};

// The physical description converted (toCamera) and kept beside its camera, which also keeps what
// `like` had beyond the description: lens effects, calibrated image size, and near/far left to be
// fitted to the scene. How a description that replaces a camera's stays that camera otherwise.
SelectedCamera toSelectedCamera(const PhysicalCamera& camera, const Camera& like, std::string source);

// Refocuses at `distance` (+infinity allowed) along the one validation path a camera file's
// focus_distance takes: a physical camera gets the new focus_distance, is validated (focus beyond
// the focal length) and converted again, so its field of view follows z_i as a real lens's does;
// other cameras go through refocused(Camera). Effects, calibrated size and source carry over.
// Throws InputError naming `where`.
SelectedCamera refocused(const SelectedCamera& camera, double distance, const std::string& where);

// Aperture radius f / (2N) in world units (0 for a pinhole).
double apertureRadius(const PhysicalCamera& camera);

// Vertical field of view, 2·atan(sensor_h / (2·z_i)).
double verticalFovRadians(const PhysicalCamera& camera);

// The inverse of toCamera for a perspective camera whose PRP is over the window centre, given
// the sensor size (which the viewing description does not hold). Near/far carry over; the
// target is the view plane's centre.
PhysicalCamera toPhysical(const Camera& camera, glm::dvec2 sensorMm);

}  // namespace lenslab
