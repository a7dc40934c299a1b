// Camera paths whose keys are calibrated cameras (camera/ViewPath.h): K held to the last digit
// where the keys share it, each quantity interpolated as the header says (checked against its
// own formula: slerp of the rotation, K, eye and distortion linearly), and the keys' mistakes
// refused in one line naming the key.
#include "../common/refusal.h"
#include "camera/Intrinsics.h"
#include "camera/ViewPath.h"
#include "core/Text.h"
#include "io/CameraPathJson.h"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdio>
#include <string>

namespace lenslab {
namespace {

constexpr ImageSize kSize{1920, 1080};

// An OpenCV key: K at 1920 × 1080, the camera at `eye` turned by `yawDeg` about the world's y.
std::string key(double time, double fx, double cx, double cy, glm::dvec3 eye, double yawDeg, double k1 = -0.1) {
  const double a = glm::radians(yawDeg);
  // R's rows: x right, y down, z forward; forward = (sin a, 0, −cos a) turned about y.
  const glm::dvec3 forward(std::sin(a), 0.0, -std::cos(a)), down(0.0, -1.0, 0.0);
  const glm::dvec3 right = glm::cross(down, forward);
  const glm::dvec3 t = -glm::dvec3(glm::dot(right, eye), glm::dot(down, eye), glm::dot(forward, eye));
  char text[1024];
  std::snprintf(text, sizeof text,
                R"({"time": %.17g, "K": [[%.17g, 0, %.17g], [0, %.17g, %.17g], [0, 0, 1]], "width": 1920,
                  "height": 1080, "R": [[%.17g, %.17g, %.17g], [%.17g, %.17g, %.17g], [%.17g, %.17g, %.17g]],
                  "t": [%.17g, %.17g, %.17g], "dist": [%.17g, 0.01, 0.001, -0.0005], "focus_distance": 4})",
                time, fx, cx, fx, cy, right.x, right.y, right.z, down.x, down.y, down.z, forward.x, forward.y,
                forward.z, t.x, t.y, t.z, k1);
  return text;
}

CameraPath twoKeys(const std::string& interpolation, double fxB = 1500.0, double k1B = -0.1) {
  return parseCameraPath(cat(R"({"fps": 10, "interpolation": ")", interpolation, R"(", "keys": [)",
                             key(0.0, 1500.0, 962.3, 541.7, {0, 1, 5}, 0.0), ", ",
                             key(1.0, fxB, 962.3, 541.7, {2, 1, 5}, 90.0, k1B), "]}"),
                         "path.json");
}

TEST(ViewPath, SharedIntrinsicsAreHeldOnEveryFrame) {
  for (const char* mode : {"smooth", "linear"}) {
    const CameraPath path = twoKeys(mode);
    ASSERT_TRUE(path.holdsViews());
    for (int frame = 0; frame < path.frameCount(); ++frame) {
      const Camera c = viewCameraAt(path, path.frameTimeSeconds(frame), "frame");
      const OpenCvIntrinsics k = intrinsicsOf(c.view, kSize);
      EXPECT_NEAR(k.fx, 1500.0, 1e-9 * 1500.0) << mode << " frame " << frame;
      EXPECT_NEAR(k.fy, 1500.0, 1e-9 * 1500.0);
      EXPECT_NEAR(k.cx, 962.3, 1e-9 * 1500.0);
      EXPECT_NEAR(k.cy, 541.7, 1e-9 * 1500.0);
      EXPECT_EQ(c.lens.effects.distortion.distCoeffs()[0], -0.1);
      ASSERT_TRUE(c.calibratedSize);
      EXPECT_EQ(c.calibratedSize->widthPx, 1920);
    }
  }
}

TEST(ViewPath, KeysAreHitAndTheWayBetweenFollowsTheStatedRules) {
  const CameraPath path = twoKeys("linear", 1800.0, -0.3);
  for (const double t : {0.0, 0.25, 0.5, 1.0}) {
    const Camera c = viewCameraAt(path, t, "frame");
    const OpenCvIntrinsics k = intrinsicsOf(c.view, kSize);
    EXPECT_NEAR(k.fx, 1500.0 + 300.0 * t, 1e-9 * 1800.0) << t;  // K linearly
    EXPECT_NEAR(c.lens.effects.distortion.distCoeffs()[0], -0.1 - 0.2 * t, 1e-12);
    const OpenCvPose pose = poseOf(c.view);
    const glm::dvec3 eye = placementOf(pose).eye;
    EXPECT_NEAR(eye.x, 2.0 * t, 1e-9) << t;  // eye linearly in "linear"
    // The rotation turns at a constant rate about y: slerp from 0° to 90°.
    const double yaw = std::atan2(pose.rows[2].x, -pose.rows[2].z);
    EXPECT_NEAR(glm::degrees(yaw), 90.0 * t, 1e-9) << t;
    EXPECT_NEAR(c.focusDistance(), 4.0, 1e-9);
  }
  // Outside the keys' times the first or last key holds.
  EXPECT_NEAR(intrinsicsOf(viewCameraAt(path, 3.0, "frame").view, kSize).fx, 1800.0, 1e-9 * 1800.0);
}

TEST(ViewPath, KeysNoPinholePathCanHoldAreRefusedByName) {
  const std::string a = key(0.0, 1500.0, 962.3, 541.7, {0, 1, 5}, 0.0);
  const std::string physical = R"({"time": 1, "eye": [0, 1, 5], "target": [0, 0, 0]})";
  EXPECT_EQ(test::refusalOf([&] { parseCameraPath(cat(R"({"fps": 10, "keys": [)", a, ", ", physical, "]}"), "p"); }),
            "p: keys[1]: is in the physical form where keys[0] is not; give every key in the physical form (a "
            "photographer's focal length and sensor), or every key in the lecture or OpenCV form (a calibrated K)");
  std::string otherSize = key(1.0, 1500.0, 962.3, 541.7, {0, 1, 5}, 10.0);
  otherSize.replace(otherSize.find("1080"), 4, "1000");
  EXPECT_NE(test::refusalOf([&] {
              parseCameraPath(cat(R"({"fps": 10, "keys": [)", a, ", ", otherSize, "]}"), "p");
            }).find("p: keys[1]: its image size differs from the first key's"),
            std::string::npos);
  const std::string parallel =
      R"({"time": 1, "projection": "parallel", "vrp": [0, 0, 0], "vpn": [0, 0, 1], "prp": [0, 0, 5],
          "window": [-1, -1, 1, 1], "far": 10})";
  EXPECT_NE(test::refusalOf([&] {
              parseCameraPath(cat(R"({"fps": 10, "keys": [)", parallel, "]}"), "p");
            }).find("p: keys[0]: a parallel projection has no pinhole"),
            std::string::npos);
}

TEST(ViewPath, LectureKeysKeepAnOffCentrePrincipalPoint) {
  // An oblique view (PRP off the window's centre) is an off-centre principal point; a path of two
  // such keys at the same window keeps it.
  const std::string lecture = R"("vpn": [0, 0, 1], "prp": [0.2, 0.1, 2], "window": [-1, -0.75, 1, 0.75]})";
  const CameraPath path = parseCameraPath(cat(R"({"fps": 4, "keys": [{"time": 0, "vrp": [0, 1, 0], )", lecture,
                                              R"(, {"time": 1, "vrp": [1, 1, 0], )", lecture, "]}"),
                                          "lecture.json");
  const OpenCvIntrinsics first = intrinsicsOf(path.viewKeys.front().camera.view, kNominalViewKeySize);
  const OpenCvIntrinsics mid = intrinsicsOf(viewCameraAt(path, 0.5, "mid").view, kNominalViewKeySize);
  EXPECT_NEAR(mid.cx, first.cx, 1e-9 * first.fx);
  EXPECT_NEAR(mid.cy, first.cy, 1e-9 * first.fx);
  EXPECT_NEAR(mid.fx, first.fx, 1e-9 * first.fx);
  EXPECT_GT(std::abs(first.cx - 499.5), 10.0);  // the key is off centre indeed
}

}  // namespace
}  // namespace lenslab
