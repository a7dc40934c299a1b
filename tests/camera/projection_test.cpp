#include "camera/Projection.h"
#include "camera/Ray.h"

#include <gtest/gtest.h>

#include <random>

namespace lenslab {
namespace {

ViewSpec obliqueSpec() {
  ViewSpec s;
  s.vrp = {3.0, -1.0, 2.0};
  s.vpn = {0.2, 0.1, 1.0};
  s.vup = {0.1, 1.0, 0.0};
  s.prp = {0.4, -0.3, 2.5};  // not over the window centre: an oblique frustum
  s.window = {-1.2, -0.7, 0.8, 0.9};
  s.nearDistance = 0.1;
  s.farDistance = 100.0;
  return s;
}

glm::dvec3 transformPoint(const glm::dmat4& m, const glm::dvec3& p) {
  const glm::dvec4 h = m * glm::dvec4(p, 1.0);
  return glm::dvec3(h) / h.w;
}

TEST(LecturePerspective, IsTheLectureMatrix) {
  const double f = 2.5;
  const glm::dmat4 m = lecturePerspective(f);
  // m[column][row]
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) {
      double expected = (row == col && row < 3) ? 1.0 : 0.0;
      if (row == 3 && col == 2) expected = 1.0 / f;
      EXPECT_DOUBLE_EQ(m[col][row], expected) << "row " << row << " column " << col;
    }
}

TEST(LecturePerspective, GivesUEqualsFXOverZForRandomPoints) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> xy(-50.0, 50.0);
  std::uniform_real_distribution<double> z(0.01, 1000.0);
  std::uniform_real_distribution<double> fs(0.01, 10.0);
  for (int i = 0; i < 10000; ++i) {
    const double f = fs(rng);
    const glm::dvec3 p(xy(rng), xy(rng), z(rng));
    const glm::dvec3 projected = transformPoint(lecturePerspective(f), p);
    EXPECT_NEAR(projected.x, f * p.x / p.z, 1e-9 * (1.0 + std::abs(f * p.x / p.z)));
    EXPECT_NEAR(projected.y, f * p.y / p.z, 1e-9 * (1.0 + std::abs(f * p.y / p.z)));
    EXPECT_NEAR(projected.z, f, 1e-12 * f) << "every point lands on the view plane z = f";
  }
}

// The clip matrix and the lecture's formula agree on where random points land.
TEST(ClipFromWorld, MatchesTheLectureFormulaForObliquePerspective) {
  const ViewSpec s = obliqueSpec();
  validate(s, "test");
  const glm::dmat4 clip = clipFromWorld(s);
  const ViewBasis b = viewBasis(s);
  const glm::dvec3 prp = prpWorld(s);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> lateral(-3.0, 3.0);
  std::uniform_real_distribution<double> depth(0.2, 90.0);
  for (int i = 0; i < 5000; ++i) {
    const double z = depth(rng);
    const glm::dvec3 world = prp - z * b.n + lateral(rng) * z * 0.3 * b.u + lateral(rng) * z * 0.3 * b.v;
    // The lecture: X, Y relative to the PRP, Z the depth; u = f·X/Z, offset by the PRP's (u, v).
    const glm::dvec3 rel = world - prp;
    const double bigX = glm::dot(rel, b.u), bigY = glm::dot(rel, b.v), bigZ = -glm::dot(rel, b.n);
    const double f = s.prp.z;
    const glm::dvec2 expectedUv(s.prp.x + f * bigX / bigZ, s.prp.y + f * bigY / bigZ);
    const glm::dvec3 ndc = transformPoint(clip, world);
    const glm::dvec2 uv = windowFromNdc(s.window, glm::dvec2(ndc));
    EXPECT_NEAR(uv.x, expectedUv.x, 1e-9 * (1.0 + std::abs(expectedUv.x)));
    EXPECT_NEAR(uv.y, expectedUv.y, 1e-9 * (1.0 + std::abs(expectedUv.y)));
    const glm::dvec2 direct = projectToWindow(s, world);
    EXPECT_NEAR(direct.x, expectedUv.x, 1e-9 * (1.0 + std::abs(expectedUv.x)));
    // Reverse-Z: depth falls from 1 at near to 0 at far.
    const double expectedDepth = s.nearDistance * (s.farDistance - bigZ) / (bigZ * (s.farDistance - s.nearDistance));
    EXPECT_NEAR(ndc.z, expectedDepth, 1e-9);
  }
}

TEST(ClipFromWorld, NearMapsToOneAndFarToZero) {
  ViewSpec s = obliqueSpec();
  const ViewBasis b = viewBasis(s);
  const glm::dvec3 prp = prpWorld(s);
  const glm::dmat4 clip = clipFromWorld(s);
  EXPECT_NEAR(transformPoint(clip, prp - s.nearDistance * b.n).z, 1.0, 1e-12);
  EXPECT_NEAR(transformPoint(clip, prp - s.farDistance * b.n).z, 0.0, 1e-12);
  s.farDistance = std::numeric_limits<double>::infinity();
  const glm::dmat4 infinite = clipFromWorld(s);
  EXPECT_NEAR(transformPoint(infinite, prp - s.nearDistance * b.n).z, 1.0, 1e-12);
  EXPECT_NEAR(transformPoint(infinite, prp - 1e12 * b.n).z, s.nearDistance / 1e12, 1e-20);
  EXPECT_GT(transformPoint(infinite, prp - 1e12 * b.n).z, 0.0);
}

// "Ray R from PRP toward VRP + u·udir + v·vdir": every point on it maps back to (u, v).
TEST(PrimaryRay, EveryPointOnTheRayMapsToItsWindowPoint) {
  for (Projection projection : {Projection::Perspective, Projection::Parallel}) {
    ViewSpec s = obliqueSpec();
    s.projection = projection;
    validate(s, "test");
    const glm::dmat4 clip = clipFromWorld(s);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> ru(s.window.umin, s.window.umax);
    std::uniform_real_distribution<double> rv(s.window.vmin, s.window.vmax);
    std::uniform_real_distribution<double> rt(0.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
      const glm::dvec2 uv(ru(rng), rv(rng));
      const Ray ray = primaryRay(s, uv);
      const double t = ray.tNear + rt(rng) * (std::min(ray.tFar, 1e3) - ray.tNear);
      const glm::dvec3 p = ray.origin + t * ray.direction;
      const glm::dvec2 back = windowFromNdc(s.window, glm::dvec2(transformPoint(clip, p)));
      EXPECT_NEAR(back.x, uv.x, 1e-9) << (projection == Projection::Parallel ? "parallel" : "perspective");
      EXPECT_NEAR(back.y, uv.y, 1e-9);
      const glm::dvec2 direct = projectToWindow(s, p);
      EXPECT_NEAR(direct.x, uv.x, 1e-9);
      EXPECT_NEAR(direct.y, uv.y, 1e-9);
    }
  }
}

TEST(PrimaryRay, PerspectiveRaysStartAtThePrpAndPassThroughTheViewPlanePoint) {
  const ViewSpec s = obliqueSpec();
  const glm::dvec2 uv(0.3, -0.2);
  const Ray ray = primaryRay(s, uv);
  const glm::dvec3 prp = prpWorld(s);
  EXPECT_NEAR(glm::length(ray.origin - prp), 0.0, 1e-12);
  const glm::dvec3 target = viewPlanePoint(s, uv);
  const glm::dvec3 toTarget = glm::normalize(target - prp);
  EXPECT_NEAR(glm::dot(toTarget, ray.direction), 1.0, 1e-12);
  // The near distance is measured along −n from the PRP.
  const ViewBasis b = viewBasis(s);
  EXPECT_NEAR(-glm::dot(ray.tNear * ray.direction, b.n), s.nearDistance, 1e-12);
}

// The same view with the view plane (and the window with it) brought to 1e-15 … 1e-300 of the
// PRP, the PRP kept where it is in the world: every ray keeps its direction, however close the
// view plane is to the PRP and however far the scene is from the origin.
TEST(PrimaryRay, DirectionsDoNotDependOnTheViewPlanesDistance) {
  const ViewSpec s = obliqueSpec();
  const ViewBasis b = viewBasis(s);
  for (const double scale : {1e-15, 1e-30, 1e-300}) {
    ViewSpec near = s;
    near.prp = s.prp * scale;
    near.window = {s.window.umin * scale, s.window.vmin * scale, s.window.umax * scale, s.window.vmax * scale};
    near.vrp = prpWorld(s) - near.prp.x * b.u - near.prp.y * b.v - near.prp.z * b.n;
    near.nearDistance = s.nearDistance * scale;
    validate(near, "test");
    for (const glm::dvec2 uv : {glm::dvec2(0.3, -0.2), glm::dvec2(-1.1, 0.85), glm::dvec2(0.75, -0.6)}) {
      const Ray far = primaryRay(s, uv), close = primaryRay(near, uv * scale);
      EXPECT_NEAR(glm::length(close.direction - far.direction), 0.0, 1e-12)
          << "view plane at " << scale << " of the original";
    }
  }
}

TEST(ParallelProjection, ProjectsAlongDopOntoTheViewPlane) {
  ViewSpec s = obliqueSpec();
  s.projection = Projection::Parallel;
  const ViewBasis b = viewBasis(s);
  const glm::dvec3 dop = directionOfProjection(s);
  const glm::dvec3 dopWorld = dop.x * b.u + dop.y * b.v + dop.z * b.n;
  // Two points on one line along DOP land on the same window point; the window centre is hit by
  // the line through the PRP.
  const glm::dvec3 a = s.vrp + 0.3 * b.u - 0.2 * b.v - 4.0 * b.n;
  const glm::dvec3 c = a + 7.5 * dopWorld;
  const glm::dvec2 pa = projectToWindow(s, a), pc = projectToWindow(s, c);
  EXPECT_NEAR(pa.x, pc.x, 1e-12);
  EXPECT_NEAR(pa.y, pc.y, 1e-12);
  const glm::dvec2 fromPrp = projectToWindow(s, prpWorld(s));
  EXPECT_NEAR(fromPrp.x, s.window.center().x, 1e-12);
  EXPECT_NEAR(fromPrp.y, s.window.center().y, 1e-12);
  // A point on the view plane projects to itself, wherever the PRP is.
  const glm::dvec2 onPlane = projectToWindow(s, s.vrp + 0.25 * b.u + 0.5 * b.v);
  EXPECT_NEAR(onPlane.x, 0.25, 1e-12);
  EXPECT_NEAR(onPlane.y, 0.5, 1e-12);
  // Linear reverse depth.
  const glm::dmat4 clip = clipFromWorld(s);
  const glm::dvec3 prp = prpWorld(s);
  EXPECT_NEAR(transformPoint(clip, prp - s.nearDistance * b.n).z, 1.0, 1e-12);
  EXPECT_NEAR(transformPoint(clip, prp - s.farDistance * b.n).z, 0.0, 1e-12);
}

TEST(PixelMapping, CentresAndCornersRoundTrip) {
  const Window w{-3.0, -1.0, 3.0, 3.0};
  const glm::dvec2 topLeft = pixelFromWindow(w, {w.umin, w.vmax}, 600, 400);
  EXPECT_DOUBLE_EQ(topLeft.x, 0.0);
  EXPECT_DOUBLE_EQ(topLeft.y, 0.0);
  const glm::dvec2 bottomRight = pixelFromWindow(w, {w.umax, w.vmin}, 600, 400);
  EXPECT_DOUBLE_EQ(bottomRight.x, 600.0);
  EXPECT_DOUBLE_EQ(bottomRight.y, 400.0);
  const glm::dvec2 uv = windowFromPixel(w, {10.5, 20.5}, 600, 400);
  const glm::dvec2 back = pixelFromWindow(w, uv, 600, 400);
  EXPECT_NEAR(back.x, 10.5, 1e-12);
  EXPECT_NEAR(back.y, 20.5, 1e-12);
}

}  // namespace
}  // namespace lenslab
