#pragma once
// Automatic framing: a camera that shows a whole subject — its bounding sphere — as large as the
// frame allows, from the front and a little above, upright (world +Y up in the image), focused on
// the sphere's centre.
//
// The sphere must fit the smaller half field of view of the lens *focused at that distance*:
// tan(half angle) = s / (2·z_i), s the sensor's smaller side and z_i = f·D / (D − f) the image
// distance, so close subjects need more room than the infinity field of view atan(s / 2f) says.
// With the margin m, D solves  m·r / √(D² − (m·r)²) = s·(D − f) / (2·f·D)  (one root beyond
// max(m·r, f); see framingDistance).
//
// A thin lens focuses no closer than its focal length, and real lenses reach life size (1:1, a
// subject at D = 2f) at most. A subject smaller than the sensor would need more — a 1 mm part on a
// 24 mm high sensor, whatever the lens — and gets a pinhole with the lens's field of view at
// infinity focus instead (no focus, no blur); the camera's source says so and what to change.
#include "camera/Camera.h"
#include "camera/PhysicalCamera.h"

#include <glm/glm.hpp>

namespace lenslab {

// The sphere's radius is enlarged by this before fitting: its silhouette ends 2 % of the frame's
// half height (or half width) inside the nearer edges.
constexpr double kFramingMargin = 1.02;

// The distance from the lens centre at which a sphere of radius `radius` just fills the half field
// of view across `sensorSide` of a thin lens of focal length `focalLength` focused at that
// distance (all in world units). Always beyond both the radius and the focal length.
double framingDistance(double radius, double focalLength, double sensorSide);

// Frames the sphere (centre, radius) with a `focalLengthMm` lens on a `sensorMm` sensor, the
// camera on the side `towardCamera` points to (default: in front, 0.35 up for each 1 back). The
// physical description when the lens can focus on the sphere's centre at life size or less;
// otherwise a pinhole (no physical description) — the source says which. Its near and far only
// have to be valid: the caller marks them to be fitted to the scene (Camera::nearFromScene and
// farFromScene), as composeCamera does for every automatically framed camera.
SelectedCamera frameSphere(const glm::dvec3& center, double radius, double focalLengthMm, glm::dvec2 sensorMm,
                           const glm::dvec3& towardCamera = glm::dvec3(0.0, 0.35, 1.0));

}  // namespace lenslab
