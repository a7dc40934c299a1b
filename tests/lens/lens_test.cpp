// The thin lens: hand-derived values, aperture patterns, the moved-PRP construction, and the
// frame plan's sample count.
#include "camera/Camera.h"
#include "camera/PhysicalCamera.h"
#include "camera/Projection.h"
#include "camera/Ray.h"
#include "core/Error.h"
#include "lens/AperturePattern.h"
#include "lens/ThinLens.h"
#include "plan/FramePlan.h"
#include "scene/ProceduralScenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace lenslab {
namespace {

// f = 50 mm, focus 2 m, N = 2, sensor CoC limit 0.03 mm.
constexpr double f = 0.05, zf = 2.0, N = 2.0, cocLimit = 0.03e-3;

TEST(ThinLens, ImageDistanceAndMagnificationByHand) {
  // 1/z_i = 1/f − 1/z_f = 20 − 0.5 = 19.5  ⇒  z_i = 0.0512820…
  EXPECT_NEAR(imageDistanceFromInverse(f, 1.0 / zf), 1.0 / 19.5, 1e-15);
  EXPECT_DOUBLE_EQ(imageDistanceFromInverse(f, 0.0), f) << "focus at infinity: the image is at f";
  EXPECT_NEAR(magnification(f, 1.0 / zf), (1.0 / 19.5) / 2.0, 1e-15);
}

TEST(ThinLens, CircleOfConfusionByHand) {
  const double r = f / (2.0 * N);  // 12.5 mm
  // A point at 4 m: on the plane of focus 2R·|z − z_f|/z = 0.025·2/4 = 12.5 mm.
  EXPECT_NEAR(cocDiameterOnFocusPlane(r, 1.0 / zf, 4.0), 0.0125, 1e-15);
  // On the sensor it is smaller by the magnification z_i / z_f.
  EXPECT_NEAR(cocDiameterOnSensor(r, f, 1.0 / zf, 4.0), 0.0125 * (1.0 / 19.5) / 2.0, 1e-15);
  // Focus at infinity: a point at 10 m blurs to 2R·f/z on the sensor, no division by infinity.
  EXPECT_NEAR(cocDiameterOnSensor(r, f, 0.0, 10.0), 0.025 * 0.05 / 10.0, 1e-15);
  EXPECT_EQ(cocDiameterOnSensor(r, f, 1.0 / zf, zf), 0.0);
}

TEST(ThinLens, HyperfocalAndDepthOfFieldByHand) {
  // H = f²/(N c) + f = 0.0025/(6e-5) + 0.05 = 41.7167 m
  const double h = hyperfocalDistance(f, N, cocLimit);
  EXPECT_NEAR(h, 0.0025 / 6e-5 + 0.05, 1e-9);
  const DepthOfField dof = depthOfField(f, zf, h);
  EXPECT_NEAR(dof.nearDistance, zf * (h - f) / (h + zf - 2 * f), 1e-12);
  EXPECT_NEAR(dof.farDistance, zf * (h - f) / (h - zf), 1e-12);
  EXPECT_LT(dof.nearDistance, zf);
  EXPECT_GT(dof.farDistance, zf);
  // The limits are where the sensor CoC equals c.
  EXPECT_NEAR(cocDiameterOnSensor(f / (2 * N), f, 1.0 / zf, dof.nearDistance), cocLimit, 1e-3 * cocLimit);
  EXPECT_NEAR(cocDiameterOnSensor(f / (2 * N), f, 1.0 / zf, dof.farDistance), cocLimit, 1e-3 * cocLimit);
  // Focused at the hyperfocal distance, everything from H/2 to infinity is sharp.
  const DepthOfField atH = depthOfField(f, h, h);
  EXPECT_TRUE(std::isinf(atH.farDistance));
  EXPECT_NEAR(atH.nearDistance, h * (h - f) / (2 * h - 2 * f), 1e-9);
}

TEST(AperturePattern, Lecture17IsCentrePlusTwoRadiiEvery45Degrees) {
  const auto s = makeApertureSamples(AperturePattern::Lecture17, 5, 3);
  ASSERT_EQ(s.size(), 17u);
  EXPECT_EQ(s[0].lens, glm::dvec2(0.0));
  for (int k = 0; k < 8; ++k) {
    const double a = k * std::numbers::pi / 4;
    EXPECT_NEAR(glm::length(s[1 + k].lens - 0.5 * glm::dvec2(std::cos(a), std::sin(a))), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(s[9 + k].lens - glm::dvec2(std::cos(a), std::sin(a))), 0.0, 1e-12);
  }
}

TEST(AperturePattern, EveryPatternStaysInTheDiskAndIsReproducible) {
  for (AperturePattern p : {AperturePattern::Concentric, AperturePattern::R2, AperturePattern::Random,
                            AperturePattern::Lecture17, AperturePattern::Sobol}) {
    SCOPED_TRACE(patternName(p));
    const auto a = makeApertureSamples(p, 100, 7), b = makeApertureSamples(p, 100, 7),
               other = makeApertureSamples(p, 100, 8);
    ASSERT_EQ(a.size(), p == AperturePattern::Lecture17 ? 17u : 100u);
    bool differs = false;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_LE(glm::length(a[i].lens), 1.0 + 1e-12);
      EXPECT_GE(a[i].pixel.x, -0.5);
      EXPECT_LT(a[i].pixel.x, 0.5);
      EXPECT_GE(a[i].pixel.y, -0.5);
      EXPECT_LT(a[i].pixel.y, 0.5);
      EXPECT_EQ(a[i].lens, b[i].lens);
      EXPECT_EQ(a[i].pixel, b[i].pixel);
      differs |= a[i].pixel != other[i].pixel;
    }
    EXPECT_TRUE(differs) << "another seed gives other samples";
  }
}

TEST(AperturePattern, StratifiedPatternsCoverTheDiskEvenly) {
  // Mean of a uniform disk is 0 and E[r²] = 1/2; stratified and low-discrepancy points get close.
  for (AperturePattern p : {AperturePattern::Concentric, AperturePattern::R2, AperturePattern::Sobol}) {
    const auto s = makeApertureSamples(p, 256, 1);
    glm::dvec2 mean(0.0);
    double r2 = 0.0;
    for (const LensSample& x : s) {
      mean += x.lens;
      r2 += glm::dot(x.lens, x.lens);
    }
    mean /= 256.0;
    r2 /= 256.0;
    EXPECT_LT(glm::length(mean), 0.02) << patternName(p);
    EXPECT_NEAR(r2, 0.5, 0.01) << patternName(p);
  }
}

TEST(AperturePattern, ConcentricMapIsAreaPreservingAtTheCorners) {
  EXPECT_NEAR(glm::length(concentricDisk({1.0, 0.5})), 1.0, 1e-12);
  EXPECT_NEAR(glm::length(concentricDisk({0.5, 0.0})), 1.0, 1e-12);
  EXPECT_EQ(concentricDisk({0.5, 0.5}), glm::dvec2(0.0));
}

Camera lensCamera(Projection projection) {
  ViewSpec v;
  v.projection = projection;
  v.vrp = {0.2, 0.1, -3.0};
  v.vpn = {0.1, 0.0, 1.0};
  v.prp = {0.1, -0.05, 3.0};
  v.window = {-1.0, -0.6, 1.2, 0.8};
  v.nearDistance = 0.1;
  v.farDistance = 100.0;
  return cameraFocusedOnViewPlane(v, 0.2, "test");
}

// The heart of the design: with the PRP moved across the aperture and the window kept, points on
// the view plane land on the same window point from every aperture point (zero parallax), and a
// point at depth z spreads by exactly the circle of confusion.
TEST(ViewThroughLens, ViewPlaneIsSharpAndOtherDepthsSpreadByTheCircleOfConfusion) {
  for (Projection projection : {Projection::Perspective, Projection::Parallel}) {
    SCOPED_TRACE(projection == Projection::Parallel ? "parallel" : "perspective");
    const Camera cam = lensCamera(projection);
    const ViewBasis b = viewBasis(cam.view);
    const glm::dvec3 onPlane = viewPlanePoint(cam.view, {0.3, 0.2});
    const glm::dvec3 prp = prpWorld(cam.view);
    const double depth = 7.0;
    const glm::dvec3 behind =
        prp +
        depth * glm::normalize(viewPlanePoint(cam.view, {0.3, 0.2}) - prp) *
            (projection == Projection::Perspective ? 1.0 : 0.0) +
        (projection == Projection::Parallel ? onPlane - (depth - cam.view.prp.z) * b.n : glm::dvec3(0.0));
    double spreadMax = 0.0;
    const glm::dvec2 centre = projectToWindow(cam.view, behind);
    for (const LensSample& s : makeApertureSamples(AperturePattern::Lecture17, 17, 1)) {
      const ViewSpec v = viewThroughLens(cam, s.lens * cam.lens.apertureRadius, {0.0, 0.0});
      const glm::dvec2 p = projectToWindow(v, onPlane);
      EXPECT_NEAR(p.x, 0.3, 1e-12);
      EXPECT_NEAR(p.y, 0.2, 1e-12);
      spreadMax = std::max(spreadMax, glm::length(projectToWindow(v, behind) - centre));
    }
    const double depthOfBehind = glm::dot(behind - prp, -b.n);
    EXPECT_NEAR(2.0 * spreadMax, cocDiameterOnWindow(cam, depthOfBehind), 1e-9);
  }
}

TEST(ViewThroughLens, FocusAtInfinityMovesTheWindowWithThePrp) {
  PhysicalCamera p;
  p.eye = {0, 0, 0};
  p.target = {0, 0, -10};
  p.fNumber = 2.0;
  p.focusDistance = std::numeric_limits<double>::infinity();
  const Camera cam = toCamera(p, "test");
  ASSERT_TRUE(cam.focusAtInfinity());
  // A star (a very distant point) lands on the same window point from every aperture point.
  const glm::dvec3 star(1e9, 2e9, -1e10);
  // Compared in NDC (where the point lands in the image), since the window itself moves.
  const glm::dvec2 centre = ndcFromWindow(cam.view.window, projectToWindow(cam.view, star));
  for (const LensSample& s : makeApertureSamples(AperturePattern::Concentric, 16, 1)) {
    const ViewSpec v = viewThroughLens(cam, s.lens * cam.lens.apertureRadius, {0, 0});
    const glm::dvec2 q = ndcFromWindow(v.window, projectToWindow(v, star));
    EXPECT_NEAR(glm::length(q - centre), 0.0, 1e-6);
    EXPECT_GT(glm::length(v.window.center() - cam.view.window.center()), 0.0);
  }
}

TEST(Refocus, KeepsTheFieldOfViewAndMovesThePlaneOfFocus) {
  const Camera cam = lensCamera(Projection::Perspective);
  const Camera moved = refocused(cam, 9.0, "test");
  EXPECT_DOUBLE_EQ(moved.view.prp.z, 9.0);
  EXPECT_NEAR(glm::length(prpWorld(moved.view) - prpWorld(cam.view)), 0.0, 1e-12);
  // The pinhole image is unchanged: any point projects to the same place in NDC.
  const glm::dvec3 p(0.5, 0.3, -6.0);
  const glm::dvec4 a = clipFromWorld(cam.view) * glm::dvec4(p, 1.0), c = clipFromWorld(moved.view) * glm::dvec4(p, 1.0);
  EXPECT_NEAR(a.x / a.w, c.x / c.w, 1e-12);
  EXPECT_NEAR(a.y / a.w, c.y / c.w, 1e-12);
  EXPECT_THROW(refocused(cam, -1.0, "test"), InputError);
  Camera par = lensCamera(Projection::Parallel);
  const Camera parMoved = refocused(par, 5.0, "test");
  const glm::dvec4 pa = clipFromWorld(par.view) * glm::dvec4(p, 1.0),
                   pc = clipFromWorld(parMoved.view) * glm::dvec4(p, 1.0);
  EXPECT_NEAR(pa.x, pc.x, 1e-12);
  EXPECT_NEAR(pa.y, pc.y, 1e-12);
}

TEST(FramePlan, AutoSamplesFollowTheCircleOfConfusion) {
  EXPECT_EQ(autoApertureSamples(0.0, 256), 1);
  EXPECT_EQ(autoApertureSamples(1.0, 256), 1);
  EXPECT_EQ(autoApertureSamples(4.0, 256), 13);     // ceil(pi/4 · 16)
  EXPECT_EQ(autoApertureSamples(8.0, 256), 51);     // ceil(pi/4 · 64): four times the CoC² of 4 px
  EXPECT_EQ(autoApertureSamples(100.0, 256), 256);  // capped
  EXPECT_EQ(autoApertureSamples(100.0, 64), 64);
}

Scene planeAt(double depth) {
  Scene scene;
  addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -depth)), 1.0, 1.0, glm::vec3(1.0f));
  return scene;
}

// Looking down −z from the origin, the view plane (= plane of focus) 5 away, a window 2 wide.
ViewSpec viewFiveAway() {
  ViewSpec v;
  v.vrp = {0, 0, -5};
  v.prp = {0, 0, 5};
  v.window = {-1, -1, 1, 1};
  return v;
}

// A sharp frame, pinhole or wholly in focus, is anti-aliased by auto (kAntialiasSamples jittered
// views) and one plain pass when one view is asked for.
TEST(FramePlan, PinholeAndInFocusScenesAreAntialiasedOrOnePlainPass) {
  const ViewSpec v = viewFiveAway();
  const PlanOptions oneView{AperturePattern::Sobol, 1, 256, 1};
  const Camera pinhole = cameraFocusedOnViewPlane(v, 0.0, "test");
  FramePlan plan = makeFramePlan(planeAt(5.0), pinhole, {100, 100});
  EXPECT_EQ(plan.apertureSamples, kAntialiasSamples) << plan.samplesWhy;
  EXPECT_NE(plan.samplesWhy.find("anti-aliasing"), std::string::npos) << plan.samplesWhy;
  plan = makeFramePlan(planeAt(5.0), pinhole, {100, 100}, oneView);
  EXPECT_EQ(plan.apertureSamples, 1);
  ASSERT_EQ(plan.passes.size(), 1u);
  EXPECT_EQ(plan.passes[0].name, "scene");
  // Auto never asks for more than --max-samples.
  EXPECT_EQ(
      makeFramePlan(planeAt(5.0), pinhole, {100, 100}, PlanOptions{AperturePattern::Sobol, 0, 4, 1}).apertureSamples,
      4);

  // A wide aperture, but the whole scene is a plane on the plane of focus.
  const Camera lens = cameraFocusedOnViewPlane(v, 0.5, "test");
  plan = makeFramePlan(planeAt(5.0), lens, {100, 100});
  EXPECT_EQ(plan.apertureSamples, kAntialiasSamples) << plan.samplesWhy;
  EXPECT_NEAR(plan.cocMaxPx, 0.0, 1e-9);
  plan = makeFramePlan(planeAt(5.0), lens, {100, 100}, oneView);
  EXPECT_EQ(plan.apertureSamples, 1) << plan.samplesWhy;
  EXPECT_EQ(plan.passes.size(), 1u);

  // Off the plane of focus: CoC on the window 2R·|z − z_f|/z = 1·5/10 = 0.5 → 25 px; N = ceil(π/4·625).
  plan = makeFramePlan(planeAt(10.0), lens, {100, 100});
  EXPECT_NEAR(plan.cocMaxPx, 25.0, 1e-9);
  EXPECT_EQ(plan.apertureSamples, 256) << "capped";
  plan = makeFramePlan(planeAt(10.0), lens, {100, 100}, PlanOptions{AperturePattern::Concentric, 0, 1000, 1});
  EXPECT_EQ(plan.apertureSamples, static_cast<int>(std::ceil(std::numbers::pi / 4 * 625)));
  ASSERT_EQ(plan.passes.size(), 3u);
  EXPECT_EQ(plan.passes[1].name, "accumulate");
  // Twice the aperture, four times the samples (CoC²).
  const Camera wider = cameraFocusedOnViewPlane(v, 0.25, "test");
  const int quarter =
      makeFramePlan(planeAt(10.0), wider, {100, 100}, PlanOptions{AperturePattern::Concentric, 0, 1000, 1})
          .apertureSamples;
  EXPECT_NEAR(static_cast<double>(plan.apertureSamples) / quarter, 4.0, 0.05);
  // lecture17 is always 17.
  EXPECT_EQ(makeFramePlan(planeAt(10.0), lens, {100, 100}, PlanOptions{AperturePattern::Lecture17, 0, 256, 1})
                .apertureSamples,
            17);
}

// The barrel clips at the undistorted field: a barrel distortion pushes the corners' rays farther
// off-axis than the window's corners. Seen in the opening's plane the aperture has radius
// 0.1·(1 − 0.2/5) = 0.096 about 0.2·n; the window's corner (|n| = 0.283) reaches 0.153, inside the
// opening's 0.155, while the undistorted corner with k1 = −0.8 (|n| ≈ 0.306) reaches 0.157.
TEST(FramePlan, TheBarrelClipsAtTheUndistortedCorners) {
  Camera lens = cameraFocusedOnViewPlane(viewFiveAway(), 0.1, "test");
  lens.lens.barrel = LensBarrel{0.2, 0.155};
  const FramePlan straight = makeFramePlan(planeAt(5.0), lens, {100, 100});
  EXPECT_EQ(straight.apertureSamples, kAntialiasSamples)
      << "the window's corners see the whole aperture: " << straight.samplesWhy;
  EXPECT_EQ(straight.samplesWhy.find("barrel"), std::string::npos) << straight.samplesWhy;
  lens.lens.effects.distortion.k1 = -0.8;
  const FramePlan distorted = makeFramePlan(planeAt(5.0), lens, {100, 100});
  EXPECT_EQ(distorted.apertureSamples, 64) << distorted.samplesWhy;
  EXPECT_NE(distorted.samplesWhy.find("barrel"), std::string::npos) << distorted.samplesWhy;
}

// An explicit count with a pinhole is honoured: N sub-pixel-jittered views of the same PRP (the
// box-filtered pixel integral, i.e. anti-aliasing); auto gives kAntialiasSamples, 1 one view.
TEST(FramePlan, AnExplicitCountWithAPinholeGivesJitteredViews) {
  const ViewSpec v = viewFiveAway();
  const Camera pinhole = cameraFocusedOnViewPlane(v, 0.0, "test");
  const FramePlan asked =
      makeFramePlan(planeAt(8.0), pinhole, {100, 100}, PlanOptions{AperturePattern::Concentric, 16, 256, 1});
  EXPECT_EQ(asked.apertureSamples, 16) << asked.samplesWhy;
  EXPECT_EQ(asked.viewsPerSample, 1);
  ASSERT_EQ(asked.passes.size(), 3u);
  EXPECT_EQ(asked.passes[1].name, "accumulate");
  EXPECT_NE(asked.samplesWhy.find("anti-aliasing"), std::string::npos);
  EXPECT_EQ(makeFramePlan(planeAt(8.0), pinhole, {100, 100}).apertureSamples, kAntialiasSamples);
  EXPECT_EQ(makeFramePlan(planeAt(8.0), pinhole, {100, 100}, PlanOptions{AperturePattern::Concentric, 1, 256, 1})
                .passes.size(),
            1u);
  EXPECT_EQ(makeFramePlan(planeAt(8.0), pinhole, {100, 100}, PlanOptions{AperturePattern::Lecture17, 0, 256, 1})
                .apertureSamples,
            17);
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

// The lecture's construction of the in-focus point ("RC + TL (II)"): from an image point, one ray
// parallel to the optic axis (deflected through the front focal point) and one through the back
// focal point (deflected parallel to the axis) meet at the point in focus. Every lens ray the ray
// caster fires for that pixel must pass through it.
TEST(LensRay, RaysOfOnePixelMeetAtTheLecturesTwoRayFocusPoint) {
  PhysicalCamera p;
  p.eye = {0.3, 1.2, 4.0};
  p.target = {-0.5, 0.8, -3.0};
  p.focalLengthMm = 50.0;
  p.fNumber = 1.8;
  p.focusDistance = 2.5;
  const Camera camera = toCamera(p, "test");
  const ViewBasis b = viewBasis(camera.view);
  const glm::dvec3 d = -b.n;  // the optic axis, toward the scene
  const double focal = 0.05, focus = p.focusDistance, zi = imageDistance(focal, focus);

  const double a = 0.004, c = -0.003;  // an image point on the sensor, behind the lens
  const glm::dvec3 sensorPoint = p.eye - zi * d + a * b.u + c * b.v;
  // Ray A: parallel to the axis to the lens, then through the front focal point.
  const glm::dvec3 lensA = p.eye + a * b.u + c * b.v;
  const glm::dvec3 dirA = glm::normalize((p.eye + focal * d) - lensA);
  // Ray B: through the back focal point to the lens, then parallel to the axis.
  const glm::dvec3 backFocal = p.eye - focal * d;
  const double t = zi / (zi - focal);
  const glm::dvec3 lensB = sensorPoint + t * (backFocal - sensorPoint);
  const glm::dvec3 dirB = d;
  // Closest points of the two lines: they intersect.
  const glm::dvec3 w0 = lensA - lensB;
  const double aa = glm::dot(dirA, dirA), bb = glm::dot(dirA, dirB), cc = glm::dot(dirB, dirB);
  const double dd = glm::dot(dirA, w0), ee = glm::dot(dirB, w0);
  const double sA = (bb * ee - cc * dd) / (aa * cc - bb * bb), sB = (aa * ee - bb * dd) / (aa * cc - bb * bb);
  const glm::dvec3 qA = lensA + sA * dirA, qB = lensB + sB * dirB;
  ASSERT_NEAR(glm::length(qA - qB), 0.0, 1e-9) << "the lecture's two rays meet";
  const glm::dvec3 focusPoint = 0.5 * (qA + qB);
  EXPECT_NEAR(glm::dot(focusPoint - p.eye, d), focus, 1e-9) << "on the plane of focus";

  // The pixel that images it: through the lens centre the image is inverted and scaled by z_f/z_i.
  const ImageSize size{600, 400};
  const glm::dvec2 uv(-a * focus / zi, -c * focus / zi);
  const glm::dvec2 pixel = pixelFromWindow(camera.view.window, uv, size.widthPx, size.heightPx);
  for (const LensSample& s : makeApertureSamples(AperturePattern::Lecture17, 17, 1)) {
    const Ray ray = lensRay(camera, s.lens * camera.lens.apertureRadius, pixel, size);
    const glm::dvec3 toPoint = focusPoint - ray.origin;
    const double miss = glm::length(toPoint - glm::dot(toPoint, ray.direction) * ray.direction);
    EXPECT_NEAR(miss, 0.0, 1e-9) << "a lens ray misses the in-focus point";
  }
}

}  // namespace
}  // namespace lenslab
