#include "camera/GltfCamera.h"
#include "camera/PhysicalCamera.h"
#include "camera/Projection.h"
#include "core/Error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lenslab {
namespace {

PhysicalCamera fiftyMillimetre() {
  PhysicalCamera c;
  c.eye = {1.0, 1.5, 6.0};
  c.target = {0.0, 0.5, 0.0};
  c.focalLengthMm = 50.0;
  c.sensorMm = {36.0, 24.0};
  c.fNumber = 2.0;
  c.focusDistance = 4.0;
  return c;
}

TEST(PhysicalCamera, ThinLensRelationsByHand) {
  const PhysicalCamera c = fiftyMillimetre();
  // z_i = f·z_f/(z_f − f) = 0.05·4/3.95
  const double zi = 0.05 * 4.0 / 3.95;
  EXPECT_NEAR(imageDistance(0.05, 4.0), zi, 1e-15);
  const ViewSpec s = toViewSpec(c);
  // The window on the plane of focus is the sensor scaled by z_f/z_i.
  EXPECT_NEAR(s.window.width(), 0.036 * 4.0 / zi, 1e-12);
  EXPECT_NEAR(s.window.height(), 0.024 * 4.0 / zi, 1e-12);
  EXPECT_NEAR(s.prp.z, 4.0, 1e-15);
  EXPECT_NEAR(glm::length(prpWorld(s) - c.eye), 0.0, 1e-12);
  EXPECT_NEAR(apertureRadius(c), 0.05 / 4.0, 1e-15);
  EXPECT_NEAR(verticalFovRadians(c), 2.0 * std::atan(0.024 / (2.0 * zi)), 1e-15);
  // The window subtends the same angle from the PRP as the sensor from the lens.
  EXPECT_NEAR(2.0 * std::atan(0.5 * s.window.height() / s.prp.z), verticalFovRadians(c), 1e-12);
}

TEST(PhysicalCamera, FocusAtInfinityGivesTheLecturesFieldOfView) {
  PhysicalCamera c = fiftyMillimetre();
  c.focusDistance = 1e9;
  // The lecture: FOV = atan(d / 2f) is the half angle when z_i = f.
  EXPECT_NEAR(0.5 * verticalFovRadians(c), std::atan(0.024 / (2.0 * 0.05)), 1e-9);
}

TEST(PhysicalCamera, RoundTripsThroughTheLectureForm) {
  const PhysicalCamera c = fiftyMillimetre();
  const ViewSpec s = toViewSpec(c);
  const PhysicalCamera back = toPhysical(toCamera(c, "test"), c.sensorMm);
  EXPECT_NEAR(back.focalLengthMm, c.focalLengthMm, 1e-9);
  EXPECT_NEAR(back.focusDistance, c.focusDistance, 1e-12);
  EXPECT_NEAR(glm::length(back.eye - c.eye), 0.0, 1e-12);
  const glm::dvec3 dir = glm::normalize(c.target - c.eye);
  EXPECT_NEAR(glm::dot(glm::normalize(back.target - back.eye), dir), 1.0, 1e-12);
  const ViewSpec again = toViewSpec(back);
  EXPECT_NEAR(again.window.umin, s.window.umin, 1e-12);
  EXPECT_NEAR(again.window.vmax, s.window.vmax, 1e-12);
  EXPECT_NEAR(glm::length(again.vrp - s.vrp), 0.0, 1e-12);
}

TEST(PhysicalCamera, TargetProjectsToTheImageCentre) {
  const PhysicalCamera c = fiftyMillimetre();
  const glm::dvec2 uv = projectToWindow(toViewSpec(c), c.target);
  EXPECT_NEAR(uv.x, 0.0, 1e-12);
  EXPECT_NEAR(uv.y, 0.0, 1e-12);
}

TEST(PhysicalCamera, RefusesFocusInsideTheFocalLength) {
  PhysicalCamera c = fiftyMillimetre();
  c.focusDistance = 0.04;
  EXPECT_THROW(validate(c, "cam.json"), InputError);
  c = fiftyMillimetre();
  c.target = c.eye;
  EXPECT_THROW(validate(c, "cam.json"), InputError);
  c = fiftyMillimetre();
  c.fNumber = -1.0;
  EXPECT_THROW(validate(c, "cam.json"), InputError);
  c = fiftyMillimetre();
  c.up = c.target - c.eye;
  EXPECT_THROW(validate(c, "cam.json"), InputError);
  EXPECT_NO_THROW(validate(fiftyMillimetre(), "cam.json"));
}

TEST(GltfCamera, PerspectiveWindowMatchesTheFieldOfView) {
  glm::dmat4 worldFromCamera(1.0);
  worldFromCamera[3] = glm::dvec4(0.0, 2.0, 10.0, 1.0);
  const double yfov = 0.8;
  const ViewSpec s = viewSpecFromGltfPerspective(worldFromCamera, yfov, 1.5, 0.1, 100.0, 7.0);
  validate(s, "test");
  EXPECT_NEAR(s.window.height(), 2.0 * 7.0 * std::tan(0.4), 1e-12);
  EXPECT_NEAR(s.window.width(), 1.5 * s.window.height(), 1e-12);
  // glTF cameras look along −Z: a point straight ahead lands on the centre.
  const glm::dvec2 uv = projectToWindow(s, {0.0, 2.0, -20.0});
  EXPECT_NEAR(uv.x, 0.0, 1e-12);
  EXPECT_NEAR(uv.y, 0.0, 1e-12);
  // A point at the top edge of the field of view lands on vmax.
  const double z = 30.0;
  const glm::dvec2 top = projectToWindow(s, {0.0, 2.0 + z * std::tan(0.4), 10.0 - z});
  EXPECT_NEAR(top.y, s.window.vmax, 1e-12);
}

TEST(GltfCamera, OrthographicIsAParallelProjectionOfTheMagnification) {
  const ViewSpec s = viewSpecFromGltfOrthographic(glm::dmat4(1.0), 3.0, 2.0, 0.1, 50.0, 5.0);
  validate(s, "test");
  EXPECT_EQ(s.projection, Projection::Parallel);
  const glm::dvec2 uv = projectToWindow(s, {1.0, -0.5, -30.0});
  EXPECT_NEAR(uv.x, 1.0, 1e-12);
  EXPECT_NEAR(uv.y, -0.5, 1e-12);
}

}  // namespace
}  // namespace lenslab
