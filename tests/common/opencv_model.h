#pragma once
// OpenCV's projectPoints for a camera looking down its +z axis (x right, y down), written from
// OpenCV's documentation rather than taken from the code under test. Pixel coordinates are
// OpenCV's: pixel centres on integers (lenslab's are at i + 0.5).
#include <glm/glm.hpp>

namespace lenslab::test {

struct OpenCvCamera {
  double fx, fy, cx, cy;
  double k1 = 0, k2 = 0, p1 = 0, p2 = 0, k3 = 0;

  glm::dvec2 project(glm::dvec3 cameraPoint) const {
    const double x = cameraPoint.x / cameraPoint.z, y = cameraPoint.y / cameraPoint.z;
    const double r2 = x * x + y * y;
    const double radial = 1 + k1 * r2 + k2 * r2 * r2 + k3 * r2 * r2 * r2;
    const double xd = x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x);
    const double yd = y * radial + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y;
    return {fx * xd + cx, fy * yd + cy};
  }
};

}  // namespace lenslab::test
