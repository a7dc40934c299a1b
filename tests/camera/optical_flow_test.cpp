// The flow AOV's geometry (camera/OpticalFlow.h) against closed forms: a node moved sideways at a
// known depth moves by f·Δx / z pixels, a node that does not move and a camera that does not move
// give zero, the projection through a distorting lens inverts the pixel's own centre ray, and a
// frame without a next one is NaN.
#include "camera/Intrinsics.h"
#include "camera/OpticalFlow.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace lenslab {
namespace {

constexpr ImageSize kSize{64, 48};

// A pinhole at the origin looking down −z (OpenCV's R = diag(1, −1, −1)), K off centre, and the
// distortion `k1`.
Camera camera(double k1 = 0.0, glm::dvec3 eye = glm::dvec3(0.0)) {
  OpenCvIntrinsics k;
  k.fx = 80.0, k.fy = 82.0, k.cx = 33.2, k.cy = 22.9, k.widthPx = kSize.widthPx, k.heightPx = kSize.heightPx;
  OpenCvPose pose;
  pose.rows = {glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, -1)};
  pose.translation = -(glm::dvec3(eye.x, -eye.y, -eye.z));
  Distortion d;
  d.k1 = k1;
  return pinholeFromOpenCv(k, d, pose, "test camera");
}

// Every pixel sees node `node` at depth `depth` along the axis.
AovImages surfaces(double depth, int node) {
  AovImages a;
  a.widthPx = kSize.widthPx, a.heightPx = kSize.heightPx;
  a.depth.assign(static_cast<std::size_t>(kSize.pixelCount()), static_cast<float>(depth));
  a.instance.assign(a.depth.size(), static_cast<float>(node));
  return a;
}

TEST(OpticalFlow, ANodeMovedSidewaysMovesByFocalLengthTimesShiftOverDepth) {
  const ThinLensMap now(camera(), kSize), next(camera(), kSize);
  const NodeMotion motion{{3, glm::translate(glm::dmat4(1.0), glm::dvec3(0.1, 0.05, 0.0))}};
  const std::vector<float> flow = opticalFlow(now, surfaces(5.0, 3), &next, motion);
  for (std::size_t i = 0; i < flow.size() / 2; ++i) {
    EXPECT_NEAR(flow[2 * i], 80.0 * 0.1 / 5.0, 1e-4) << i;        // x right
    EXPECT_NEAR(flow[2 * i + 1], -82.0 * 0.05 / 5.0, 1e-4) << i;  // world up is image up: y down negative
  }
  // Another node does not move; nor does anything when the camera stays.
  for (const float f : opticalFlow(now, surfaces(5.0, 2), &next, motion)) EXPECT_NEAR(f, 0.0, 1e-4);
}

TEST(OpticalFlow, TheCameraMovingIsTheSceneMovingTheOtherWayThroughADistortingLens) {
  // Through k1 = −0.2 the pixel's centre ray and the projection invert each other: a camera moved
  // by +Δ matches the scene moved by −Δ, pixel for pixel.
  const ThinLensMap now(camera(-0.2), kSize);
  const ThinLensMap moved(camera(-0.2, {0.1, 0.0, 0.0}), kSize);
  const std::vector<float> byCamera = opticalFlow(now, surfaces(4.0, 1), &moved, {});
  const NodeMotion back{{1, glm::translate(glm::dmat4(1.0), glm::dvec3(-0.1, 0.0, 0.0))}};
  const std::vector<float> byScene = opticalFlow(now, surfaces(4.0, 1), &now, back);
  ASSERT_EQ(byCamera.size(), byScene.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < byCamera.size(); ++i) {
    EXPECT_NEAR(byCamera[i], byScene[i], 1e-4) << i;
    largest = std::max(largest, std::abs(static_cast<double>(byCamera[i])));
  }
  EXPECT_GT(largest, 1.0);  // the motion is there to see
  // A pixel's own surface projects back onto the pixel's centre through the distortion.
  const std::optional<CameraRay> r = now.centreRay({5.5, 7.5});
  ASSERT_TRUE(r);
  const std::optional<glm::dvec2> p = now.pixelOfPoint(r->ray.origin + 3.0 * r->ray.direction);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->x, 5.5, 1e-6);
  EXPECT_NEAR(p->y, 7.5, 1e-6);
}

TEST(OpticalFlow, UnknownWhereNothingIsHitOrThereIsNoNextFrame) {
  const ThinLensMap now(camera(), kSize);
  for (const float f : opticalFlow(now, surfaces(5.0, 1), nullptr, {})) EXPECT_TRUE(std::isnan(f));
  for (const float f : opticalFlow(now, surfaces(INFINITY, -1), &now, {})) EXPECT_TRUE(std::isnan(f));
  // A point that the next camera has behind it.
  const ThinLensMap turned(camera(0.0, {0.0, 0.0, -10.0}), kSize);
  for (const float f : opticalFlow(now, surfaces(5.0, 1), &turned, {})) EXPECT_TRUE(std::isnan(f));
}

}  // namespace
}  // namespace lenslab
