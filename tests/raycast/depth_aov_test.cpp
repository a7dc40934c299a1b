// The depth AOV (`capture --aov depth`) against planes whose depth is known in closed form: the
// distance along the optical axis from the lens centre to where each pixel's centre ray meets the
// plane. The expected rays are built here from the physical camera alone (sensor, focal length,
// pixel grid; OpenCV's projection for distortion), not from lenslab's camera code.
#include "../common/looking_at.h"
#include "camera/PhysicalCamera.h"
#include "raycast/RayCaster.h"
#include "scene/ProceduralScenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace lenslab {
namespace {
using test::Frame;
using test::frameOf;
using test::lookingAt;
using test::normalisedCentre;

struct Plane {
  glm::dvec3 point;
  glm::dvec3 normal;  // unit, towards the camera
};

// An unlit quad of 2·half × 2·half in `plane`.
Scene planeScene(const Plane& plane, double half, const glm::dvec3& sideways = glm::dvec3(0.0)) {
  Scene scene;
  scene.source = "plane";
  const glm::dvec3 z = plane.normal;
  const glm::dvec3 x = glm::normalize(glm::cross(glm::dvec3(0.0, 1.0, 0.0), z));
  const glm::dvec3 y = glm::cross(z, x);
  glm::dmat4 worldFromModel(glm::dvec4(x, 0.0), glm::dvec4(y, 0.0), glm::dvec4(z, 0.0),
                            glm::dvec4(plane.point + sideways, 1.0));
  addUnlitQuad(scene, worldFromModel, half, half, {0.5f, 0.5f, 0.5f});
  scene.bounds = computeBounds(scene);
  return scene;
}

double analyticDepth(const PhysicalCamera& c, const Plane& plane, glm::dvec2 normalised) {
  const Frame f = frameOf(c);
  const glm::dvec3 direction = f.forward + normalised.x * f.right - normalised.y * f.up;
  const double t = glm::dot(plane.point - c.eye, plane.normal) / glm::dot(direction, plane.normal);
  return glm::dot(t * direction, f.forward);
}

constexpr int kWidth = 96;

TEST(DepthAov, FrontalPlaneIsItsDistanceEverywhere) {
  const PhysicalCamera c = lookingAt({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0});
  const Plane plane{{0.0, 0.0, -3.7}, {0.0, 0.0, 1.0}};
  const Scene scene = planeScene(plane, 100.0);
  const Camera camera = toCamera(c, "test");
  const ImageSize size = resolveImageSize(camera, kWidth, std::nullopt);
  const std::vector<float> depth = RayCaster(scene).depthImage(camera, size);
  ASSERT_EQ(depth.size(), static_cast<std::size_t>(size.pixelCount()));
  for (const float z : depth) ASSERT_NEAR(z, 3.7, 3.7e-4 * 0.1);  // well inside 1e-4 relative
}

TEST(DepthAov, TiltedPlaneFromAnOffAxisCameraMatchesTheAnalyticDistance) {
  const PhysicalCamera c = lookingAt({0.4, -0.2, 1.0}, {0.1, 0.3, -5.0});
  const Plane plane{{0.0, 0.0, -5.0}, glm::normalize(glm::dvec3(0.3, 0.2, 1.0))};
  const Scene scene = planeScene(plane, 100.0);
  const Camera camera = toCamera(c, "test");
  const ImageSize size = resolveImageSize(camera, kWidth, std::nullopt);
  const std::vector<float> depth = RayCaster(scene).depthImage(camera, size);
  double worst = 0.0;
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      const double expected = analyticDepth(c, plane, normalisedCentre(c, x, y, size.widthPx, size.heightPx));
      worst = std::max(worst, std::abs(depth[static_cast<std::size_t>(y) * size.widthPx + x] - expected) / expected);
    }
  std::printf("worst relative error %.3g\n", worst);
  EXPECT_LE(worst, 1e-4);
}

TEST(DepthAov, NothingHitIsPlusInfinityAndTheEdgeIsWhereThePlaneEnds) {
  const PhysicalCamera c = lookingAt({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0});
  const Plane plane{{0.0, 0.0, -2.0}, {0.0, 0.0, 1.0}};
  // A quad 1 wide whose centre is 0.5 to the right: it covers x from 0 to 1 at depth 2.
  const Scene scene = planeScene(plane, 0.5, {0.5, 0.0, 0.0});
  const Camera camera = toCamera(c, "test");
  const ImageSize size = resolveImageSize(camera, kWidth, std::nullopt);
  const std::vector<float> depth = RayCaster(scene).depthImage(camera, size);
  int hits = 0, misses = 0;
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      const glm::dvec2 n = normalisedCentre(c, x, y, size.widthPx, size.heightPx);
      const glm::dvec2 onPlane = 2.0 * glm::dvec2(n.x, -n.y);  // world x, y where the ray meets z = −2
      const float z = depth[static_cast<std::size_t>(y) * size.widthPx + x];
      const double margin = 1e-6;
      if (onPlane.x > margin && onPlane.x < 1.0 - margin && std::abs(onPlane.y) < 0.5 - margin) {
        EXPECT_NEAR(z, 2.0, 2e-4) << x << "," << y;
        ++hits;
      } else if (onPlane.x < -margin || onPlane.x > 1.0 + margin || std::abs(onPlane.y) > 0.5 + margin) {
        EXPECT_TRUE(std::isinf(z) && z > 0.0) << x << "," << y << ": " << z;
        ++misses;
      }
    }
  EXPECT_GT(hits, 100);
  EXPECT_GT(misses, 100);
}

TEST(DepthAov, UnderDistortionEachPixelGetsTheDepthOfItsTruePerspectiveDirection) {
  const PhysicalCamera c = lookingAt({0.4, -0.2, 1.0}, {0.1, 0.3, -5.0});
  const Plane plane{{0.0, 0.0, -5.0}, glm::normalize(glm::dvec3(0.3, 0.2, 1.0))};
  const Scene scene = planeScene(plane, 100.0);
  Camera camera = toCamera(c, "test");
  const double k1 = -0.2, k2 = 0.05;
  camera.lens.effects.distortion.k1 = k1;
  camera.lens.effects.distortion.k2 = k2;
  const ImageSize size = resolveImageSize(camera, kWidth, std::nullopt);
  const std::vector<float> depth = RayCaster(scene).depthImage(camera, size);
  double worst = 0.0, moved = 0.0;
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      // OpenCV's model maps the true position u to the distorted d = u·(1 + k1 r² + k2 r⁴); the pixel
      // shows d, so its direction is the u that maps there (fixed point: u = d / radial(u)).
      const glm::dvec2 distorted = normalisedCentre(c, x, y, size.widthPx, size.heightPx);
      glm::dvec2 u = distorted;
      for (int i = 0; i < 200; ++i) {
        const double r2 = glm::dot(u, u);
        u = distorted / (1.0 + k1 * r2 + k2 * r2 * r2);
      }
      const double expected = analyticDepth(c, plane, u);
      moved = std::max(moved, std::abs(analyticDepth(c, plane, distorted) - expected) / expected);
      worst = std::max(worst, std::abs(depth[static_cast<std::size_t>(y) * size.widthPx + x] - expected) / expected);
    }
  std::printf("worst relative error %.3g (ignoring the distortion: %.3g)\n", worst, moved);
  EXPECT_LE(worst, 1e-4);
  EXPECT_GT(moved, 1e-2);  // the distortion matters here: ignoring it would fail the bound above
}

}  // namespace
}  // namespace lenslab
