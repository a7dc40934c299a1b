// Depth precision chosen from the scene: open near/far fitted to the scene's bounds in view.
#include "camera/DepthRange.h"
#include "camera/Projection.h"
#include "core/Error.h"
#include "core/Text.h"
#include "io/CameraJson.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lenslab {
namespace {

Bounds box(glm::dvec3 lo, glm::dvec3 hi) {
  Bounds b;
  b.extend(lo);
  b.extend(hi);
  return b;
}

TEST(DepthRange, ATelephotoGetsNearAndFarAroundItsSubject) {
  // A PRP 1e9 from the view plane (a very long lens); near defaults to PRP.n/1000 = 1e6 and far to
  // infinity: reverse-Z depth then resolves only ~60 units at the subject, 1e9 away.
  const Camera open =
      parseCameraJson(R"({"vrp": [0, 0, 0], "vpn": [0, 0, 1], "prp": [0, 0, 1e9], "window": [-3, -2, 3, 2]})",
                      "tele.json")
          .camera;
  ASSERT_TRUE(open.nearFromScene && open.farFromScene);
  const Bounds scene = box({-5, -1, -30}, {5, 3, 2});
  const Camera fitted = withDepthRangeFitted(open, scene);
  const DepthInterval d = depthIntervalOf(fitted.view, scene);
  EXPECT_LT(fitted.view.nearDistance, d.nearest);
  EXPECT_GT(fitted.view.farDistance, d.farthest);
  EXPECT_GT(fitted.view.nearDistance, 1e9 - 2000.0);  // the margin: 1e-6 of the distance
  EXPECT_LT(fitted.view.farDistance, 1e9 + 2000.0);
  // Reverse-Z depth now separates surfaces 1 unit apart at the subject by far more than float's
  // step (the depth buffer's 2^-24 near 1); with far at infinity they were 1e-12 apart.
  const double z1 = 1e9 - 1.0, z2 = 1e9;
  const glm::dvec4 a = clipFromEye(fitted.view) * glm::dvec4(0, 0, -z1, 1),
                   b = clipFromEye(fitted.view) * glm::dvec4(0, 0, -z2, 1);
  EXPECT_GT(std::abs(a.z / a.w - b.z / b.w), 1e-4);
}

TEST(DepthRange, GivenValuesAreKeptAndAnOpenNearInsideTheSceneIsItsDefaultOrAThousandthOfIt) {
  const Bounds scene = box({-1, -1, -10}, {1, 1, 5.5});  // reaches behind the camera at z = 5
  const Camera given =
      parseCameraJson(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "near": 0.01, "far": 100})", "given.json").camera;
  EXPECT_FALSE(given.nearFromScene || given.farFromScene);
  const Camera kept = withDepthRangeFitted(given, scene);
  EXPECT_EQ(kept.view.nearDistance, 0.01);
  EXPECT_EQ(kept.view.farDistance, 100.0);
  const Camera open = parseCameraJson(R"({"eye": [0, 0, 5], "target": [0, 0, 0]})", "open.json").camera;
  const Camera fitted = withDepthRangeFitted(open, scene);
  // The scene reaches behind the camera: near is the default (0.05) or 1e-3 of the scene's size
  // (15.76), the smaller.
  EXPECT_NEAR(fitted.view.nearDistance, 1e-3 * glm::length(glm::dvec3(2, 2, 15.5)), 1e-12);
  EXPECT_NEAR(fitted.view.farDistance, 15.0 + 0.01 * 15.5, 1e-9);
  const Bounds large = box({-100, -100, -100}, {100, 100, 100});
  EXPECT_EQ(withDepthRangeFitted(open, large).view.nearDistance, 0.05);
}

// A 1 cm scene seen from 3 cm lies nearer than the default near (0.05): fitted, not clipped away.
TEST(DepthRange, ASceneNearerThanTheDefaultNearIsFittedNotClipped) {
  const Bounds scene = box({-0.005, -0.005, -0.005}, {0.005, 0.005, 0.005});
  const Camera open =
      parseCameraJson(R"({"eye": [0, 0, 0.03], "target": [0, 0, 0], "focus_distance": "infinity"})", "open.json")
          .camera;
  const Camera fitted = withDepthRangeFitted(open, scene);
  EXPECT_GT(fitted.view.nearDistance, 0.02);
  EXPECT_LT(fitted.view.nearDistance, 0.025);
  EXPECT_GT(fitted.view.farDistance, 0.035);
}

TEST(DepthRange, ParallelAndEmptyScenesAreLeftAlone) {
  const Camera parallel =
      parseCameraJson(
          R"({"projection": "parallel", "vrp": [0, 0, 0], "vpn": [0, 0, 1], "prp": [0, 0, 5], "window": [-1, -1, 1, 1], "far": 50})",
          "par.json")
          .camera;
  const Camera fitted = withDepthRangeFitted(parallel, box({-1, -1, -1}, {1, 1, 1}));
  EXPECT_EQ(fitted.view.nearDistance, parallel.view.nearDistance);
  EXPECT_EQ(fitted.view.farDistance, parallel.view.farDistance);
  const Camera open = parseCameraJson(R"({"eye": [0, 0, 5], "target": [0, 0, 0]})", "open.json").camera;
  EXPECT_TRUE(std::isinf(withDepthRangeFitted(open, Bounds{}).view.farDistance));
}

// A given near so small that near / depth has no normal float (reverse-Z) drew nothing at all: it
// is refused in one line with the smallest near that works for this scene.
TEST(DepthRange, AGivenNearBelowWhatDepthCanHoldIsRefused) {
  const Bounds scene = box({-1, -1, -10}, {1, 1, 0});
  for (const char* near : {"1e-100", "1e-320"}) {
    const Camera c =
        parseCameraJson(cat(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "near": )", near, "}"), "n.json").camera;
    try {
      withDepthRangeFitted(c, scene);
      ADD_FAILURE() << near << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("n.json: near is"), std::string::npos) << e.what();
    }
  }
  const Camera fine = parseCameraJson(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "near": 1e-20})", "n.json").camera;
  EXPECT_EQ(withDepthRangeFitted(fine, scene).view.nearDistance, 1e-20);
}

}  // namespace
}  // namespace lenslab
