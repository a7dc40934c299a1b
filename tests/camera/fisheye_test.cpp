// OpenCV's fisheye model (lens/effects/Distortion.h) without a GL context: where lenslab puts world
// points against cv::fisheye's formula written out in tests/common/opencv_model.h, its inverse and
// Jacobian, the ray caster's rays and the flow's projection through it, and the refusals: an image
// that reaches 90° from the axis, a fold, terms the model does not have, and a raster render that
// would have to stretch without bound.
#include "camera/ImageMap.h"
#include "camera/LensMap.h"
#include "core/Text.h"
#include "io/CameraJson.h"
#include "plan/FramePlan.h"
#include "scene/ProceduralScenes.h"

#include "../common/lenslab_pixel.h"
#include "../common/opencv_model.h"
#include "../common/refusal.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

namespace lenslab {
namespace {

using test::OpenCvFisheye;

constexpr int kWidth = 1280, kHeight = 960;
// A calibrated fisheye: the farthest corner (800 px from the centre) at about 80° from the axis.
const OpenCvFisheye kFisheye{560.0, 561.5, 641.3, 478.2, 0.021, -0.0043, 0.0011, -0.00018};

std::string fisheyeJson(const OpenCvFisheye& c, const std::string& distortion = "") {
  const std::string terms = distortion.empty() ? cat(R"("model": "fisheye", "k1": )", c.k1, R"(, "k2": )", c.k2,
                                                     R"(, "k3": )", c.k3, R"(, "k4": )", c.k4)
                                               : distortion;
  return cat(R"({"K": [[)", c.fx, ", 0, ", c.cx, "], [0, ", c.fy, ", ", c.cy, R"(], [0, 0, 1]], "width": )", kWidth,
             R"(, "height": )", kHeight, R"(, "R": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "t": [0, 0, 0],
             "near": 0.01, "distortion": {)",
             terms, "}}");
}

Camera fisheyeCamera(const OpenCvFisheye& c = kFisheye) {
  return parseCameraJson(fisheyeJson(c), "fisheye.json").camera;
}

// A direction at angle θ from the axis (OpenCV's camera frame, R = I: the world's), at distance `range`.
glm::dvec3 pointAt(double theta, double azimuth, double range) {
  return range * glm::dvec3(std::sin(theta) * std::cos(azimuth), std::sin(theta) * std::sin(azimuth), std::cos(theta));
}

TEST(Fisheye, PutsPointsWhereOpenCvsFisheyeDoesOutTo85Degrees) {
  const Camera camera = fisheyeCamera();
  const ImageSize size = resolveImageSize(camera, std::nullopt, std::nullopt);
  ASSERT_EQ(size.widthPx, kWidth);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> theta(0.0, 85.0 * M_PI / 180.0), azimuth(0.0, 2 * M_PI), range(0.1, 50.0);
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const glm::dvec3 world = pointAt(theta(rng), azimuth(rng), range(rng));
    const glm::dvec2 expected = kFisheye.project(world) + glm::dvec2(0.5);  // lenslab's pixel centres
    worst = std::max(worst, glm::length(test::lenslabPixel(camera, world, size) - expected));
  }
  std::printf("worst distance from cv::fisheye's pixel %.3g px\n", worst);
  EXPECT_LE(worst, 1e-6);
}

TEST(Fisheye, NearTheCentreItIsThePinholeWithTheModelsCurvature) {
  Distortion d;
  d.fisheye = true;  // k1 … k4 = 0: the equidistant fisheye, θ_d = θ
  EXPECT_FALSE(d.isZero());
  EXPECT_EQ(d.distort({0.0, 0.0}), glm::dvec2(0.0));
  const glm::dvec2 p(3e-9, -4e-9);
  EXPECT_NEAR(glm::length(d.distort(p)), 5e-9, 1e-22);
  const glm::dvec2 far(1.0, 0.0);  // 45°
  EXPECT_NEAR(d.distort(far).x, M_PI / 4.0, 1e-15);
}

TEST(Fisheye, InverseRoundTripsOverTheWholeImage) {
  const Camera camera = fisheyeCamera();
  const Distortion& d = camera.lens.effects.distortion;
  const NormalisedRect rect = normalisedWindow(camera.view);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(rect.min.x, rect.max.x), v(rect.min.y, rect.max.y);
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const glm::dvec2 distorted(u(rng), v(rng));
    const auto truth = d.undistort(distorted);
    ASSERT_TRUE(truth.has_value()) << distorted.x << ", " << distorted.y;
    worst = std::max(worst, glm::length(d.distort(*truth) - distorted) * kFisheye.fx);
  }
  EXPECT_LT(worst, 1e-6);  // pixels
}

TEST(Fisheye, JacobianMatchesFiniteDifferencesFromTheCentreTo85Degrees) {
  const Distortion d = fisheyeCamera().lens.effects.distortion;
  for (const glm::dvec2 p : {glm::dvec2(3e-5, -2e-5), glm::dvec2(0.3, -0.2), glm::dvec2(-1.5, 0.4),
                             glm::dvec2(0.01, 3.0), glm::dvec2(8.0, -8.0)}) {
    const glm::dmat2 j = d.jacobian(p);
    const double h = 1e-6 * std::max(1.0, glm::length(p));
    const glm::dvec2 dx = (d.distort(p + glm::dvec2(h, 0)) - d.distort(p - glm::dvec2(h, 0))) / (2 * h);
    const glm::dvec2 dy = (d.distort(p + glm::dvec2(0, h)) - d.distort(p - glm::dvec2(0, h))) / (2 * h);
    EXPECT_NEAR(j[0].x, dx.x, 1e-7) << p.x << ", " << p.y;
    EXPECT_NEAR(j[0].y, dx.y, 1e-7) << p.x << ", " << p.y;
    EXPECT_NEAR(j[1].x, dy.x, 1e-7) << p.x << ", " << p.y;
    EXPECT_NEAR(j[1].y, dy.y, 1e-7) << p.x << ", " << p.y;
  }
}

// The ray caster's ray of each pixel, projected by cv::fisheye's formula, lands on that pixel; and
// the flow's projection (pixelOfPoint) puts a point where the formula does.
TEST(Fisheye, TheRayCastersRaysLeaveEachPixelAlongTheModelsDirection) {
  const Camera camera = fisheyeCamera();
  const ImageSize size = resolveImageSize(camera, std::nullopt, std::nullopt);
  const ThinLensMap map(camera, size);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> x(0.0, kWidth), y(0.0, kHeight), range(0.5, 20.0);
  double worstRay = 0.0, worstPoint = 0.0;
  for (int i = 0; i < 5000; ++i) {
    const glm::dvec2 pixel(x(rng), y(rng));
    const auto ray = map.centreRay(pixel);
    ASSERT_TRUE(ray);
    const glm::dvec3 world = ray->ray.origin + range(rng) * ray->ray.direction;
    worstRay = std::max(worstRay, glm::length(kFisheye.project(world) + glm::dvec2(0.5) - pixel));
    const auto projected = map.pixelOfPoint(world);
    ASSERT_TRUE(projected);
    worstPoint = std::max(worstPoint, glm::length(*projected - pixel));
  }
  std::printf("worst ray %.3g px, worst projection %.3g px\n", worstRay, worstPoint);
  EXPECT_LE(worstRay, 1e-6);
  EXPECT_LE(worstPoint, 1e-6);
  // The models end at 90°: COLMAP's fisheyes project no point at w ≤ 0, OpenCV's divides by z.
  EXPECT_FALSE(map.pixelOfPoint(pointAt(100.0 * M_PI / 180.0, 0.3, 2.0)));
  EXPECT_FALSE(map.pixelOfPoint(pointAt(90.5 * M_PI / 180.0, 0.3, 2.0)));
}

TEST(Fisheye, AnImageThatReaches90DegreesIsRefusedByName) {
  OpenCvFisheye wide = kFisheye;
  wide.fx = wide.fy = 480.0;  // the corner at 800 / 480 = 1.67 > θ_d(90°) ≈ 1.62
  const std::string message = test::refusalOf([&] { fisheyeCamera(wide); });
  EXPECT_NE(message.find("fisheye.json: the fisheye's image reaches 90°"), std::string::npos) << message;
  EXPECT_NE(message.find("longer focal length"), std::string::npos) << message;
  // A fold before 90°: θ_d = θ(1 − 0.3 θ²) stops growing at θ = 1/√0.9 (60.5°).
  OpenCvFisheye folding = kFisheye;
  folding.k1 = -0.3, folding.k2 = folding.k3 = folding.k4 = 0.0;
  const std::string fold = test::refusalOf([&] { fisheyeCamera(folding); });
  EXPECT_NE(fold.find("folds over"), std::string::npos) << fold;
  EXPECT_NE(fold.find("fisheye k1 = -0.3"), std::string::npos) << fold;
  const Distortion d = [] {
    Distortion f;
    f.fisheye = true, f.k1 = -0.3;
    return f;
  }();
  const auto reach = d.fisheyeReach();
  ASSERT_TRUE(reach);
  EXPECT_TRUE(reach->folds);
  EXPECT_NEAR(reach->theta, 1.0 / std::sqrt(0.9), 1e-9);
}

TEST(Fisheye, TermsTheModelDoesNotHaveAndUnknownModelsAreRefused) {
  const auto refused = [](const std::string& terms) {
    return test::refusalOf([&] { parseCameraJson(fisheyeJson(kFisheye, terms), "f.json"); });
  };
  const std::string p1 = refused(R"("model": "fisheye", "k1": 0.01, "p1": 0.001)");
  EXPECT_NE(p1.find("\"distortion.p1\""), std::string::npos) << p1;
  EXPECT_NE(p1.find("k1, k2, k3 and k4"), std::string::npos) << p1;
  const std::string model = refused(R"("model": "kannala")");
  EXPECT_NE(model.find("\"distortion.model\""), std::string::npos) << model;
  EXPECT_NE(model.find("\"fisheye\""), std::string::npos) << model;
  EXPECT_EQ(refused(R"("model": "opencv", "k1": -0.01)"), "accepted");
}

TEST(Fisheye, TheCameraFileWritesTheModelAndReadsBack) {
  const Camera camera = fisheyeCamera();
  const ImageSize size = resolveImageSize(camera, std::nullopt, std::nullopt);
  const std::string written = toOpenCvCameraJson(camera, size, false, false);
  EXPECT_NE(written.find("\"fisheye\""), std::string::npos) << written;
  const Distortion back = parseCameraJson(written, "written.json").camera.lens.effects.distortion;
  EXPECT_TRUE(back.fisheye);
  EXPECT_EQ(back.k1, kFisheye.k1);
  EXPECT_EQ(back.k4, kFisheye.k4);
}

// The raster draws the image from one undistorted render; toward 90° its size runs off as tan θ.
TEST(Fisheye, TheRasterRefusesARenderThatStretchesWithoutBoundAndNamesTheRayCaster) {
  Scene scene;
  addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, 2.0)), 1.0, 1.0, glm::vec3(1.0f));
  scene.bounds = computeBounds(scene);
  const Camera camera = fisheyeCamera();  // the corner at about 80°: tan θ / θ about 4
  const ImageSize size = resolveImageSize(camera, std::nullopt, std::nullopt);
  EXPECT_NO_THROW(makeFramePlan(scene, camera, size));
  OpenCvFisheye wide{530.0, 530.0, 639.5, 479.5};  // the equidistant fisheye, its corner at 86.5°
  const Camera wideCamera = fisheyeCamera(wide);
  const std::string message = test::refusalOf([&] { makeFramePlan(scene, wideCamera, size); });
  EXPECT_NE(message.find("lenslab raycast"), std::string::npos) << message;
  EXPECT_NE(message.find("at most 8"), std::string::npos) << message;
  // The ray caster takes it: its rays still land where the model puts them.
  const ThinLensMap map(wideCamera, size);
  const auto corner = map.centreRay({0.5, 0.5});
  ASSERT_TRUE(corner);
  EXPECT_LE(
      glm::length(wide.project(corner->ray.origin + corner->ray.direction) + glm::dvec2(0.5) - glm::dvec2(0.5, 0.5)),
      1e-6);
}

}  // namespace
}  // namespace lenslab
