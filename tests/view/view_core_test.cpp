// The interactive view's pure parts (no window, no GL): navigation is a rigid motion that keeps
// the camera valid and its pivot or PRP fixed, and the lecture diagram's geometry is the camera's.
#include "view_fixtures.h"
#include "camera/PhysicalCamera.h"
#include "camera/Projection.h"
#include "lens/AperturePattern.h"
#include "view/LectureDiagram.h"
#include "view/Navigation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lenslab::view {
namespace {

using test::rowsDof;

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
  EXPECT_NEAR(glm::length(a - b), 0.0, tolerance)
      << "(" << a.x << " " << a.y << " " << a.z << ") vs (" << b.x << " " << b.y << " " << b.z << ")";
}

TEST(ViewNavigation, OrbitKeepsThePivotAndTheShape) {
  const EditableCamera start = fromPhysical(rowsDof(), "test");
  const EditableCamera c = orbited(start, 0.7, -0.3);
  EXPECT_NO_THROW(validate(c.camera.view, "orbited"));
  expectNear(focusPivotWorld(c.camera), focusPivotWorld(start.camera), 1e-12);
  EXPECT_NEAR(glm::length(prpWorld(c.camera.view) - focusPivotWorld(c.camera)),
              glm::length(prpWorld(start.camera.view) - focusPivotWorld(start.camera)), 1e-12);
  EXPECT_EQ(c.camera.view.prp, start.camera.view.prp) << "PRP and window ride along in VRC";
  EXPECT_DOUBLE_EQ(c.camera.lens.apertureRadius, start.camera.lens.apertureRadius);
  // The physical description moved the same way: rebuilding from it gives the same camera.
  ASSERT_TRUE(c.physical);
  const Camera rebuilt = toCamera(*c.physical, "rebuilt");
  expectNear(prpWorld(rebuilt.view), prpWorld(c.camera.view), 1e-9);
  expectNear(viewBasis(rebuilt.view).n, viewBasis(c.camera.view).n, 1e-9);
}

TEST(ViewNavigation, LookingAroundKeepsThePrpAndFlyingMovesAlongTheAxes) {
  const EditableCamera start = fromPhysical(rowsDof(), "test");
  const EditableCamera looked = lookedAround(start, -0.4, 0.2);
  expectNear(prpWorld(looked.camera.view), prpWorld(start.camera.view), 1e-12);
  const ViewBasis b = viewBasis(start.camera.view);
  const EditableCamera flew = flown(start, {0.5, -0.25, 2.0});
  expectNear(prpWorld(flew.camera.view), prpWorld(start.camera.view) + 0.5 * b.u - 0.25 * b.v - 2.0 * b.n, 1e-12);
  expectNear(flew.physical->eye, start.physical->eye + 0.5 * b.u - 0.25 * b.v - 2.0 * b.n, 1e-12);
}

TEST(LectureDiagram, WindowCornersRaysAndSamplesAreTheCameras) {
  const Camera camera = toCamera(rowsDof(), "test");
  const std::vector<LensSample> samples = makeApertureSamples(AperturePattern::Concentric, 16, 1);
  DiagramStyle style;
  const std::vector<DiagramLine> lines = lectureDiagram(camera, samples, 5, style);
  const ViewSpec& s = camera.view;
  const ViewBasis b = viewBasis(s);
  const glm::dvec3 prp = prpWorld(s);
  int windowEdges = 0, rays = 0, doneMarks = 0;
  for (const DiagramLine& l : lines) {
    if (l.color == style.colors.window && glm::length(l.to - l.from) > 0.5) {
      // A window edge: both ends on the view plane, at the window's corners.
      ++windowEdges;
      for (const glm::dvec3& p : {l.from, l.to}) {
        EXPECT_NEAR(glm::dot(p - s.vrp, b.n), 0.0, 1e-12);
        const glm::dvec2 uv = projectToWindow(s, p);
        EXPECT_NEAR(std::abs(uv.x), s.window.umax, 1e-9);
        EXPECT_NEAR(std::abs(uv.y), s.window.vmax, 1e-9);
      }
    }
    if (l.color == style.colors.ray) {
      // A ray from an aperture point (in the PRP's plane, inside the disk) through the window centre.
      ++rays;
      EXPECT_NEAR(glm::dot(l.from - prp, b.n), 0.0, 1e-12);
      EXPECT_LE(glm::length(l.from - prp), camera.lens.apertureRadius * (1.0 + 1e-12));
      const glm::dvec3 centre = s.vrp + s.window.center().x * b.u + s.window.center().y * b.v;
      const glm::dvec3 d = glm::normalize(l.to - l.from);
      EXPECT_NEAR(glm::length(glm::cross(centre - l.from, d)), 0.0, 1e-9) << "the ray misses the window centre";
    }
    if (l.color == style.colors.sampleDone) ++doneMarks;
  }
  EXPECT_EQ(windowEdges, 4);
  EXPECT_EQ(rays, style.rayCount);
  EXPECT_EQ(doneMarks, 2 * 5) << "a cross per accumulated sample";

  // Enlarged for reading: the disk's radius scales, the PRP and window do not move.
  style.apertureScale = readableApertureScale(camera);
  EXPECT_GT(style.apertureScale, 1.0);
  for (const DiagramLine& l : lectureDiagram(camera, samples, 5, style)) {
    if (l.color == style.colors.aperture) {
      EXPECT_NEAR(glm::length(l.from - prp), camera.lens.apertureRadius * style.apertureScale, 1e-9);
    }
  }
}

TEST(LectureDiagram, PinholeHasNoAperture) {
  PhysicalCamera p = rowsDof();
  p.fNumber = std::numeric_limits<double>::infinity();
  const std::vector<DiagramLine> lines = lectureDiagram(toCamera(p, "pinhole"), {}, 0);
  EXPECT_EQ(lines.size(), 3u + 4u + 2u + 4u) << "PRP cross, window, its centre, the view volume";
  for (const DiagramLine& l : lines) {
    EXPECT_NE(l.color, DiagramColors{}.aperture);
    EXPECT_NE(l.color, DiagramColors{}.ray);
  }
}

}  // namespace
}  // namespace lenslab::view
