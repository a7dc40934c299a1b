#pragma once
// A physical camera looking from `eye` at `target` (f/2, focused at infinity), its frame, and the
// world direction through a pixel centre: what tests that compare against closed forms (a plane's
// depth, normal or instance seen through a given pixel) compute by hand.
#include "camera/ImageSize.h"
#include "camera/PhysicalCamera.h"

#include <glm/glm.hpp>

#include <limits>

namespace lenslab::test {

struct Frame {
  glm::dvec3 forward, right, up;
};

inline Frame frameOf(const PhysicalCamera& c) {
  Frame f;
  f.forward = glm::normalize(c.target - c.eye);
  f.right = glm::normalize(glm::cross(f.forward, c.up));
  f.up = glm::cross(f.right, f.forward);
  return f;
}

// A thin lens at f/2: what these tests read (depth, normal, albedo, instance) is taken along the
// lens centre's ray, so the aperture must not matter to them.
inline PhysicalCamera lookingAt(const glm::dvec3& eye, const glm::dvec3& target) {
  PhysicalCamera c;
  c.eye = eye;
  c.target = target;
  c.fNumber = 2.0;
  c.focusDistance = std::numeric_limits<double>::infinity();
  return c;
}

// Pixel centre (x, y) of a width × height image in normalised image coordinates (x right, y down,
// OpenCV's) before any distortion, for a camera focused at infinity (the window is the sensor seen
// at the focal length).
inline glm::dvec2 normalisedCentre(const PhysicalCamera& c, int x, int y, int width, int height) {
  const double fx = c.focalLengthMm / c.sensorMm.x * width;
  const double fy = c.focalLengthMm / c.sensorMm.y * height;
  return {(x + 0.5 - 0.5 * width) / fx, (y + 0.5 - 0.5 * height) / fy};
}

// The world direction (not unit) through pixel centre (x, y).
inline glm::dvec3 pixelDirection(const PhysicalCamera& c, int x, int y, ImageSize size) {
  const Frame f = frameOf(c);
  const glm::dvec2 n = normalisedCentre(c, x, y, size.widthPx, size.heightPx);
  return f.forward + n.x * f.right - n.y * f.up;
}

}  // namespace lenslab::test
