#pragma once
// OpenCV's projectPoints for a camera looking down its +z axis (x right, y down), and its fisheye
// model's, written from OpenCV's documentation (calib3d, "Detailed Description": the rational and
// thin-prism models too; the fisheye module) rather than taken from the code under test. Pixel
// coordinates are OpenCV's: pixel centres on integers (lenslab's are at i + 0.5).
#include <glm/glm.hpp>

#include <cmath>

namespace lenslab::test {

struct OpenCvCamera {
  double fx, fy, cx, cy;
  double k1 = 0, k2 = 0, p1 = 0, p2 = 0, k3 = 0;
  double k4 = 0, k5 = 0, k6 = 0;          // the rational model
  double s1 = 0, s2 = 0, s3 = 0, s4 = 0;  // the thin prism

  bool beyondFive() const { return k4 != 0 || k5 != 0 || k6 != 0 || s1 != 0 || s2 != 0 || s3 != 0 || s4 != 0; }

  glm::dvec2 project(glm::dvec3 cameraPoint) const {
    const double x = cameraPoint.x / cameraPoint.z, y = cameraPoint.y / cameraPoint.z;
    const double r2 = x * x + y * y, r4 = r2 * r2, r6 = r4 * r2;
    const double radial = (1 + k1 * r2 + k2 * r4 + k3 * r6) / (1 + k4 * r2 + k5 * r4 + k6 * r6);
    const double xd = x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x) + s1 * r2 + s2 * r4;
    const double yd = y * radial + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y + s3 * r2 + s4 * r4;
    return {fx * xd + cx, fy * yd + cy};
  }
};

// OpenCV's fisheye model (cv::fisheye::projectPoints, from its documentation): the angle from the
// axis θ, θ_d = θ(1 + k1 θ² + k2 θ⁴ + k3 θ⁶ + k4 θ⁸), the point at θ_d along its direction. θ
// from the direction itself (atan2), so that the formula holds to 90° and past it.
struct OpenCvFisheye {
  double fx, fy, cx, cy;
  double k1 = 0, k2 = 0, k3 = 0, k4 = 0;

  double thetaD(double theta) const {
    const double t2 = theta * theta;
    return theta * (1 + k1 * t2 + k2 * t2 * t2 + k3 * t2 * t2 * t2 + k4 * t2 * t2 * t2 * t2);
  }
  glm::dvec2 project(glm::dvec3 cameraPoint) const {
    const double rho = std::hypot(cameraPoint.x, cameraPoint.y);
    const double theta = std::atan2(rho, cameraPoint.z);
    const double scale = rho > 0 ? thetaD(theta) / rho : 0.0;
    return {fx * cameraPoint.x * scale + cx, fy * cameraPoint.y * scale + cy};
  }
};

}  // namespace lenslab::test
