// A small marker at a known world position lands on the pixel the lecture's formula predicts.
#include "camera/Camera.h"
#include "camera/Projection.h"
#include "../common/gl_test_context.h"
#include "plan/FramePlan.h"
#include "render/Renderer.h"
#include "scene/ProceduralScenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace lenslab {
namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;
constexpr int kSupersample = 4;  // the centroid is measured on a 4× finer grid
constexpr double kTolerancePx = 0.15;

ViewSpec obliquePerspective() {
  ViewSpec s;
  s.vrp = {0.5, 1.0, -2.0};
  s.vpn = {0.25, 0.1, 1.0};
  s.vup = {0.0, 1.0, 0.1};
  s.prp = {0.3, -0.2, 4.0};  // off the window centre: an oblique frustum
  s.window = {-1.6, -1.1, 1.4, 1.15};
  s.nearDistance = 0.05;
  s.farDistance = std::numeric_limits<double>::infinity();
  return s;
}

// The lecture's formula, written out here rather than taken from the code under test:
// X, Y relative to the PRP on the u, v axes, Z the depth along −n; u = PRP.u + f·X/Z.
// Parallel: move along DOP = CW − PRP to the view plane.
glm::dvec2 lecturePixel(const ViewSpec& s, const glm::dvec3& world) {
  const glm::dvec3 n = glm::normalize(s.vpn);
  const glm::dvec3 u = glm::normalize(glm::cross(s.vup, n));
  const glm::dvec3 v = glm::cross(n, u);
  const glm::dvec3 rel = world - s.vrp;  // in VRC: (x, y, z)
  const double x = glm::dot(rel, u), y = glm::dot(rel, v), z = glm::dot(rel, n);
  double pu, pv;
  if (s.projection == Projection::Perspective) {
    const double f = s.prp.z;
    const double bigX = x - s.prp.x, bigY = y - s.prp.y, bigZ = s.prp.z - z;
    pu = s.prp.x + f * bigX / bigZ;
    pv = s.prp.y + f * bigY / bigZ;
  } else {
    const double cu = 0.5 * (s.window.umin + s.window.umax), cv = 0.5 * (s.window.vmin + s.window.vmax);
    const glm::dvec3 dop(cu - s.prp.x, cv - s.prp.y, -s.prp.z);
    const double t = -z / dop.z;
    pu = x + t * dop.x;
    pv = y + t * dop.y;
  }
  return {(pu - s.window.umin) / s.window.width() * kWidth, (s.window.vmax - pv) / s.window.height() * kHeight};
}

// A flat square parallel to the view plane: its image is an exact (scaled, shifted) square under
// both projections, so the centroid of its pixels is the image of its centre.
Scene squareMarker(const ViewSpec& s, const glm::dvec3& center, double halfSize) {
  const ViewBasis b = viewBasis(s);
  glm::dmat4 worldFromModel(glm::dvec4(b.u, 0.0), glm::dvec4(b.v, 0.0), glm::dvec4(b.n, 0.0), glm::dvec4(center, 1.0));
  Scene scene;
  scene.source = "square marker";
  scene.lighting.background = glm::vec3(0.0f);
  addUnlitQuad(scene, worldFromModel, halfSize, halfSize, glm::vec3(1.0f));
  return scene;
}

glm::dvec2 measuredCentroid(const Image& fine) {
  double sum = 0.0;
  glm::dvec2 weighted(0.0);
  for (int y = 0; y < fine.height; ++y)
    for (int x = 0; x < fine.width; ++x) {
      const double w = fine.at(x, y).g;
      sum += w;
      weighted += w * glm::dvec2(x + 0.5, y + 0.5);
    }
  EXPECT_GT(sum, 0.0) << "the marker is not in the image";
  return weighted / sum / static_cast<double>(kSupersample);
}

void expectMarkersLandOnTheLecturePixel(const ViewSpec& spec) {
  validate(spec, "test camera");
  const ViewBasis b = viewBasis(spec);
  const glm::dvec3 prp = prpWorld(spec);
  // Points spread over the view at several depths: in front of, on and behind the view plane.
  const double depths[] = {1.5, 4.0, 9.0};
  const glm::dvec2 spots[] = {{0.0, 0.0}, {-0.6, 0.5}, {0.7, -0.6}, {0.8, 0.7}};
  for (double depth : depths)
    for (const glm::dvec2& spot : spots) {
      // Follow the line from the PRP through the window centre, then step sideways by a window
      // position scaled to the depth, so the marker stays inside the view.
      const bool perspective = spec.projection == Projection::Perspective;
      const double alongCentre = depth / spec.prp.z;
      const double scale = perspective ? alongCentre : 1.0;
      const glm::dvec3 center = prp - depth * b.n + alongCentre * (spec.window.center().x - spec.prp.x) * b.u +
                                alongCentre * (spec.window.center().y - spec.prp.y) * b.v + spot.x * scale * 1.2 * b.u +
                                spot.y * scale * 0.9 * b.v;
      const double halfSize = 0.02 * scale;
      const Scene scene = squareMarker(spec, center, halfSize);
      Camera camera;
      camera.view = spec;
      Renderer renderer(scene);
      const ImageSize fineSize{kWidth * kSupersample, kHeight * kSupersample};
      const Image fine = renderer.render(camera, makeFramePlan(scene, camera, fineSize), fineSize);
      const glm::dvec2 measured = measuredCentroid(fine);
      const glm::dvec2 expected = lecturePixel(spec, center);
      SCOPED_TRACE(testing::Message() << "depth " << depth << " spot (" << spot.x << ", " << spot.y << ")");
      ASSERT_GT(expected.x, 2.0);
      ASSERT_LT(expected.x, kWidth - 2.0);
      ASSERT_GT(expected.y, 2.0);
      ASSERT_LT(expected.y, kHeight - 2.0);
      // The brief asks for ±0.5 px; a half-pixel convention slip would sit exactly at 0.5, so
      // hold it to 0.15 px. The 4× grid quantises each edge to 1/8 px; measured worst: 0.05 px.
      EXPECT_NEAR(measured.x, expected.x, kTolerancePx);
      EXPECT_NEAR(measured.y, expected.y, kTolerancePx);
    }
}

TEST(Placement, PerspectiveObliqueMarkersLandWhereTheLectureSays) {
  LENSLAB_REQUIRE_GL();
  expectMarkersLandOnTheLecturePixel(obliquePerspective());
}

TEST(Placement, PerspectiveCentredMarkersLandWhereTheLectureSays) {
  LENSLAB_REQUIRE_GL();
  ViewSpec s = obliquePerspective();
  s.prp = {s.window.center().x, s.window.center().y, 3.0};
  expectMarkersLandOnTheLecturePixel(s);
}

TEST(Placement, ParallelObliqueMarkersLandWhereTheLectureSays) {
  LENSLAB_REQUIRE_GL();
  ViewSpec s = obliquePerspective();
  s.projection = Projection::Parallel;
  s.nearDistance = 0.0;
  s.farDistance = 50.0;
  s.prp = {0.6, -0.4, 5.0};  // DOP = CW − PRP is tilted: an oblique parallel projection
  expectMarkersLandOnTheLecturePixel(s);
}

}  // namespace
}  // namespace lenslab
