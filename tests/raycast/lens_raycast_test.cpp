// `raycast --lens`: the ray caster through a real lens prescription (lens/LensCamera,
// RayCaster::render(LensCamera)). A uniformly bright world shows the lens's relative illumination,
// pixel by pixel, with no rings; a small marker off the axis lands where the lens's chief ray for
// its field angle lands, the right way up.
#include "camera/PhysicalCamera.h"
#include "core/TextFile.h"
#include "lens/ExitPupil.h"
#include "lens/LensAnalysis.h"
#include "lens/LensCamera.h"
#include "lens/ParaxialLens.h"
#include "raycast/RayCaster.h"
#include "scene/ProceduralScenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

namespace lenslab {
namespace {

std::shared_ptr<const LensPrescription> bundled(const std::string& name) {
  const std::string path = std::string(LENSLAB_TEST_ASSET_DIR) + "/lenses/" + name;
  return std::make_shared<LensPrescription>(parseLensPrescription(readTextFile(path, "lens file"), path));
}

// A camera at the origin looking down −z, 36 × 24 mm, focused at `focus` metres.
PhysicalCamera looking(double focus) {
  PhysicalCamera c;
  c.eye = {0.0, 0.0, 0.0};
  c.target = {0.0, 0.0, -1.0};
  c.focusDistance = focus;
  c.fNumber = 2.0;
  return c;
}

LensCameraPose poseOf(const PhysicalCamera& c) {
  LensCameraPose pose;
  pose.eye = c.eye;
  pose.forward = glm::normalize(c.target - c.eye);
  pose.right = glm::normalize(glm::cross(pose.forward, c.up));
  pose.up = glm::cross(pose.right, pose.forward);
  return pose;
}

TEST(LensRaycast, AUniformWorldShowsTheRelativeIlluminationWithoutRings) {
  const auto lens = bundled("double-gauss-50mm.lens");
  Scene scene;  // nothing but the background, radiance 1 every way
  scene.source = "uniform";
  scene.lighting.background = glm::vec3(1.0f);
  addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, 1e4)), 1.0, 1.0,
               glm::vec3(1.0f));  // behind the camera
  scene.bounds = computeBounds(scene);
  const PhysicalCamera physical = looking(INFINITY);
  const Camera camera = toCamera(physical, "test");
  const LensCamera lensCamera(lens, {}, poseOf(physical));
  const ImageSize size{36, 24};
  const Image image = RayCaster(scene).render(lensCamera, camera, size, RaycastOptions{256, 1});
  const double filmZ = lens->lengthMm() + lensCamera.filmDistanceMm();
  LensTrace trace;
  trace.stopDiameterMm = lensCamera.stopDiameterMm();
  const double axial = filmIrradianceBySearch(*lens, filmZ, 0.0, trace, 192);
  double worst = 0.0;
  for (int y = 0; y < size.heightPx; y += 3)
    for (int x = 0; x < size.widthPx; x += 2) {
      const double r = std::hypot(x + 0.5 - 18.0, y + 0.5 - 12.0);  // 1 mm per pixel
      const double expected = filmIrradianceBySearch(*lens, filmZ, r, trace, 192) / axial;
      const double got = image.at(x, y).r;
      worst = std::max(worst, std::abs(got - expected));
      EXPECT_NEAR(got, expected, 0.03) << "pixel " << x << "," << y << " at " << r << " mm";
    }
  std::printf("uniform world through the double Gauss: worst |pixel - relative illumination| %.4f\n", worst);
  EXPECT_NEAR(image.at(18, 12).r, 1.0, 0.03);
}

// A marker up and to the right in the scene, at the focus distance, shows up and to the right, at
// the film height whose chief ray leaves at the marker's angle (the lens's distortion included).
TEST(LensRaycast, AMarkerLandsWhereItsChiefRayDoesTheRightWayUp) {
  const auto lens = bundled("wide-angle-28mm.lens");
  const double distance = 5.0, angle = 0.5;  // radians off the axis, toward up-right
  const glm::dvec3 along =
      glm::normalize(glm::dvec3(std::sin(angle) * std::cos(0.6), std::sin(angle) * std::sin(0.6), -std::cos(angle)));
  Scene scene = markerScene({{distance * along, 0.01, glm::vec3(1.0f)}});
  const PhysicalCamera physical = looking(distance);
  const Camera camera = toCamera(physical, "test");
  LensCameraSettings settings;
  settings.focusDistance = distance;
  settings.fNumber = 8.0;
  const LensCamera lensCamera(lens, settings, poseOf(physical));
  const ImageSize size{360, 240};  // 0.1 mm per pixel
  const Image image = RayCaster(scene).render(lensCamera, camera, size, RaycastOptions{16, 3});
  glm::dvec2 centroid(0.0);
  double total = 0.0;
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      const double v = image.at(x, y).g;
      centroid += v * glm::dvec2(x + 0.5, y + 0.5);
      total += v;
    }
  ASSERT_GT(total, 0.0) << "the marker is in the picture";
  centroid /= total;
  // Image millimetres from the centre, right and up.
  const glm::dvec2 imageMm((centroid.x - 180.0) * 0.1, (120.0 - centroid.y) * 0.1);
  EXPECT_NEAR(std::atan2(imageMm.y, imageMm.x), 0.6, 0.01) << "up and to the right, at the marker's azimuth";
  // The film height of the chief ray at this angle, from the analysis's field table.
  LensAnalysisOptions o;
  // The same focus as the camera's, measured from the film as the analysis takes it.
  o.focusDistanceMm =
      1000.0 * distance - firstOrder(*lens).entrancePupilMm + lens->lengthMm() + lensCamera.filmDistanceMm();
  o.fNumber = 8.0;
  o.fieldSamples = 41;
  o.pupilSamples = 8;
  const LensReport report = analyseLens(*lens, o);
  double expected = 0.0;
  for (std::size_t i = 1; i < report.field.size(); ++i) {
    const FieldSample &a = report.field[i - 1], &b = report.field[i];
    const double degrees = angle * 180.0 / 3.14159265358979323846;
    if (a.fieldAngleDegrees <= degrees && degrees <= b.fieldAngleDegrees)
      expected = a.imageHeightMm + (degrees - a.fieldAngleDegrees) / (b.fieldAngleDegrees - a.fieldAngleDegrees) *
                                       (b.imageHeightMm - a.imageHeightMm);
  }
  ASSERT_GT(expected, 0.0);
  EXPECT_NEAR(glm::length(imageMm), expected, 0.05) << "mm from the centre";
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

// Focusing: a point on the axis at the focus distance images as the lens's own spot (the
// analysis's RMS radius at that focus), not as a defocused disc.
TEST(LensRaycast, APointAtTheFocusDistanceImagesAsTheLensesSpot) {
  for (const char* file : {"double-gauss-50mm.lens", "telephoto-250mm.lens"}) {
    const auto lens = bundled(file);
    const double distance = 5.0;
    Scene scene = markerScene({{glm::dvec3(0.0, 0.0, -distance), 2e-4, glm::vec3(1.0f)}});
    const PhysicalCamera physical = looking(distance);
    const Camera camera = toCamera(physical, "test");
    LensCameraSettings settings;
    settings.focusDistance = distance;
    settings.fNumber = 5.6;
    settings.sensorMm = {1.2, 1.2};  // 0.01 mm per pixel
    const LensCamera lensCamera(lens, settings, poseOf(physical));
    const ImageSize size{120, 120};
    const Image image = RayCaster(scene).render(lensCamera, camera, size, RaycastOptions{64, 5});
    glm::dvec2 mean(0.0);
    double total = 0.0, second = 0.0;
    for (int y = 0; y < size.heightPx; ++y)
      for (int x = 0; x < size.widthPx; ++x) {
        const double v = image.at(x, y).g;
        mean += v * glm::dvec2(x + 0.5, y + 0.5);
        total += v;
      }
    ASSERT_GT(total, 0.0) << file;
    mean /= total;
    for (int y = 0; y < size.heightPx; ++y)
      for (int x = 0; x < size.widthPx; ++x) {
        const glm::dvec2 d = glm::dvec2(x + 0.5, y + 0.5) - mean;
        second += image.at(x, y).g * glm::dot(d, d);
      }
    const double rmsMm = 0.01 * std::sqrt(second / total);
    LensAnalysisOptions o;
    o.sensorMm = {1.2, 1.2};
    o.fNumber = 5.6;
    o.fieldSamples = 2;
    o.pupilSamples = 64;
    o.focusDistanceMm =
        1000.0 * distance - firstOrder(*lens).entrancePupilMm + lens->lengthMm() + lensCamera.filmDistanceMm();
    const double spot = analyseLens(*lens, o).rmsSpotMm.x;
    std::printf("%s at %.1f m: image RMS radius %.4f mm, analysis's spot %.4f mm\n", file, distance, rmsMm, spot);
    EXPECT_NEAR(rmsMm, spot, 0.25 * spot + 0.01) << file;
  }
}

}  // namespace
}  // namespace lenslab
