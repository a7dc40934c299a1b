// A shaped aperture, seen where it shows: a small bright marker far behind the plane of focus is
// blurred into the aperture's shape (lens/ApertureShape.h), in the rasterizer and the ray caster
// alike. Each image is compared with the shape predicted in closed form: the marker's square, moved
// by every aperture point, averaged over the aperture — per pixel, the area of the shape that
// falls in the square about the pixel, over the shape's area (polygon clipping, exact).
#include "camera/Camera.h"
#include "camera/Projection.h"
#include "../common/gl_test_context.h"
#include "lens/ApertureShape.h"
#include "lens/LensBarrel.h"
#include "plan/FramePlan.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "scene/ProceduralScenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace lenslab {
namespace {

constexpr int kSizePx = 96;
constexpr double kFocus = 2.0, kMarkerDepth = 8.0;
constexpr double kMarkerHalfPx = 3.0;  // half the marker's side on the image
constexpr double kCocRadiusPx = 20.0;  // the round aperture's blur radius at the marker's depth

// Camera at the origin looking down −z, the plane of focus at kFocus, window 2 wide; the aperture
// radius that blurs the marker's depth into kCocRadiusPx.
Camera bokehCamera(const ApertureShape& shape) {
  ViewSpec v;
  v.vrp = {0.0, 0.0, -kFocus};
  v.vpn = {0.0, 0.0, 1.0};
  v.prp = {0.0, 0.0, kFocus};
  v.window = {-1.0, -1.0, 1.0, 1.0};
  v.nearDistance = 0.01;
  const double pxPerUnit = kSizePx / 2.0;
  // CoC diameter on the window 2R·(z − z_f)/z.
  const double radius = kCocRadiusPx / pxPerUnit / ((kMarkerDepth - kFocus) / kMarkerDepth);
  Camera c = cameraFocusedOnViewPlane(v, radius, "bokeh test");
  c.lens.aperture = shape;
  return c;
}

Scene markerScene() {
  Scene scene;
  scene.source = "bokeh marker";
  scene.lighting.background = glm::vec3(0.0f);
  // On the window the marker's half side is h·z_f/z; in pixels kMarkerHalfPx.
  const double half = kMarkerHalfPx / (kSizePx / 2.0) * kMarkerDepth / kFocus;
  addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -kMarkerDepth)), half, half,
               glm::vec3(1.0f));
  return scene;
}

double polygonArea(const std::vector<glm::dvec2>& p) {
  double a = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const glm::dvec2 u = p[i], w = p[(i + 1) % p.size()];
    a += u.x * w.y - w.x * u.y;
  }
  return 0.5 * std::abs(a);
}

// The part of a convex polygon on the side x·n ≤ d of a line (Sutherland–Hodgman, one edge).
std::vector<glm::dvec2> clipped(const std::vector<glm::dvec2>& p, glm::dvec2 n, double d) {
  std::vector<glm::dvec2> out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const glm::dvec2 a = p[i], b = p[(i + 1) % p.size()];
    const double da = glm::dot(a, n) - d, db = glm::dot(b, n) - d;
    if (da <= 0.0) out.push_back(a);
    if ((da < 0.0) != (db < 0.0) && da != db) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

// The predicted image: the shape (vertices in units of the aperture radius, v up) as image offsets
// of the marker's copies (× the blur radius, y down: behind the plane of focus a copy moves with
// its aperture point), each pixel the mean over 4 × 4 points of it of the shape's area in the
// marker's square about the point, over the shape's area.
std::vector<double> predicted(const std::vector<glm::dvec2>& shape) {
  std::vector<glm::dvec2> offsets;
  for (const glm::dvec2& v : shape) offsets.push_back(kCocRadiusPx * glm::dvec2(v.x, -v.y));
  const double area = polygonArea(offsets);
  const glm::dvec2 centre(kSizePx / 2.0);
  std::vector<double> image(static_cast<std::size_t>(kSizePx * kSizePx));
  for (int y = 0; y < kSizePx; ++y)
    for (int x = 0; x < kSizePx; ++x) {
      double sum = 0.0;
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
          const glm::dvec2 q = glm::dvec2(x + (i + 0.5) / 4.0, y + (j + 0.5) / 4.0) - centre;
          std::vector<glm::dvec2> p = offsets;
          p = clipped(p, {1.0, 0.0}, q.x + kMarkerHalfPx);
          p = clipped(p, {-1.0, 0.0}, -(q.x - kMarkerHalfPx));
          p = clipped(p, {0.0, 1.0}, q.y + kMarkerHalfPx);
          p = clipped(p, {0.0, -1.0}, -(q.y - kMarkerHalfPx));
          if (p.size() >= 3) sum += polygonArea(p) / area;
        }
      image[static_cast<std::size_t>(y * kSizePx + x)] = sum / 16.0;
    }
  return image;
}

double rmseAgainst(const Image& image, const std::vector<double>& expected) {
  double sum = 0.0;
  for (int y = 0; y < kSizePx; ++y)
    for (int x = 0; x < kSizePx; ++x) {
      const double d = image.at(x, y).g - expected[static_cast<std::size_t>(y * kSizePx + x)];
      sum += d * d;
    }
  return std::sqrt(sum / (kSizePx * kSizePx));
}

struct SpotMeasure {
  double energy = 0.0;    // the image's sum
  glm::dvec2 centroid{};  // energy-weighted, pixels
  double areaPx = 0.0;    // energy ÷ the plateau: the aperture's area as seen in the blur
};

// The plateau is the mean where the marker's square lies inside the shape wherever it is placed:
// pixels that the prediction puts at the full value.
SpotMeasure measure(const Image& image, const std::vector<double>& expected) {
  SpotMeasure m;
  double plateau = 0.0, plateauPixels = 0.0, full = 0.0;
  for (const double v : expected) full = std::max(full, v);
  for (int y = 0; y < kSizePx; ++y)
    for (int x = 0; x < kSizePx; ++x) {
      const double v = image.at(x, y).g;
      m.energy += v;
      m.centroid += v * glm::dvec2(x + 0.5, y + 0.5);
      if (expected[static_cast<std::size_t>(y * kSizePx + x)] >= full * (1.0 - 1e-9)) {
        plateau += v;
        plateauPixels += 1.0;
      }
    }
  m.centroid /= m.energy;
  plateau /= plateauPixels;
  // Every copy of the marker adds its area: the energy is the marker's area, the plateau the
  // marker's area over the shape's, so their ratio is the shape's area.
  m.areaPx = m.energy / plateau;
  return m;
}

ApertureShape hexagon(double rotationDeg) { return ApertureShape{6, rotationDeg, 0.0, 1.0}; }

// How a shape's image is checked: its energy, centre and area, and that the predicted shape fits
// it better than the same shape with one blade more or fewer, or turned by 10 degrees either way.
void expectTheShape(const char* renderer, const Image& image, const Image& focused, const ApertureShape& shape) {
  const std::vector<double> expected = predicted(apertureVertices(shape));
  const SpotMeasure m = measure(image, expected);
  double focusedEnergy = 0.0;
  for (int y = 0; y < kSizePx; ++y)
    for (int x = 0; x < kSizePx; ++x) focusedEnergy += focused.at(x, y).g;
  const double areaExpected = M_PI * kCocRadiusPx * kCocRadiusPx;  // the shape keeps the round aperture's area
  const double fit = rmseAgainst(image, expected);
  std::printf(
      "  %s: energy %.3f (focused %.3f), centroid (%.3f, %.3f), area %.1f px^2 (expected %.1f), RMSE against the shape "
      "%.5f\n",
      renderer, m.energy, focusedEnergy, m.centroid.x, m.centroid.y, m.areaPx, areaExpected, fit);
  EXPECT_NEAR(m.energy / focusedEnergy, 1.0, 0.01) << renderer << ": the blur keeps the marker's light";
  EXPECT_NEAR(m.centroid.x, kSizePx / 2.0, 0.25) << renderer;
  EXPECT_NEAR(m.centroid.y, kSizePx / 2.0, 0.25) << renderer;
  EXPECT_NEAR(m.areaPx / areaExpected, 1.0, 0.01) << renderer << ": the shape's area is the round aperture's";
  for (const ApertureShape& other : {ApertureShape{shape.blades - 1, shape.rotationDeg, 0.0, 1.0},
                                     ApertureShape{shape.blades + 1, shape.rotationDeg, 0.0, 1.0},
                                     ApertureShape{shape.blades, shape.rotationDeg - 10.0, 0.0, 1.0},
                                     ApertureShape{shape.blades, shape.rotationDeg + 10.0, 0.0, 1.0}}) {
    const double otherFit = rmseAgainst(image, predicted(apertureVertices(other)));
    std::printf("    against %s: RMSE %.5f\n", describeAperture(other).c_str(), otherFit);
    EXPECT_LT(fit * 1.3, otherFit) << renderer << ": " << describeAperture(shape) << " fits no better than "
                                   << describeAperture(other);
  }
}

TEST(Bokeh, AMarkerBehindTheFocusBlursIntoTheBladesPolygonInTheRasterizer) {
  LENSLAB_REQUIRE_GL();
  const Scene scene = markerScene();
  const ApertureShape shape = hexagon(15.0);
  const Camera camera = bokehCamera(shape);
  const ImageSize size{kSizePx, kSizePx};
  Renderer renderer(scene);
  const Image image = renderer.render(
      camera, makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Sobol, 4096, 4096, 3}), size);
  Camera pinhole = camera;
  pinhole.lens.apertureRadius = 0.0;
  const Image focused = renderer.render(
      pinhole, makeFramePlan(scene, pinhole, size, PlanOptions{AperturePattern::Sobol, 64, 64, 3}), size);
  expectTheShape("raster", image, focused, shape);
}

TEST(Bokeh, AMarkerBehindTheFocusBlursIntoTheBladesPolygonInTheRayCaster) {
  const Scene scene = markerScene();
  const ApertureShape shape = hexagon(15.0);
  const Camera camera = bokehCamera(shape);
  const ImageSize size{kSizePx, kSizePx};
  const RayCaster caster(scene);
  const Image image = caster.render(camera, size, RaycastOptions{1024, 9});
  Camera pinhole = camera;
  pinhole.lens.apertureRadius = 0.0;
  const Image focused = caster.render(pinhole, size, RaycastOptions{64, 9});
  expectTheShape("ray cast", image, focused, shape);
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

TEST(Bokeh, AnAnamorphicApertureBlursIntoAnOvalWithItsAxesInTheSqueezeRatio) {
  LENSLAB_REQUIRE_GL();
  const Scene scene = markerScene();
  ApertureShape shape;
  shape.anamorphicSqueeze = 2.0;
  const Camera camera = bokehCamera(shape);
  const ImageSize size{kSizePx, kSizePx};
  Renderer renderer(scene);
  const Image image = renderer.render(
      camera, makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Sobol, 4096, 4096, 3}), size);
  // The axes from the second moments: a uniform ellipse's variance along an axis is a²/4; the
  // marker's square and the pixel each add their own (side²/12), along both axes alike.
  double energy = 0.0;
  glm::dvec2 mean(0.0), second(0.0);
  for (int y = 0; y < kSizePx; ++y)
    for (int x = 0; x < kSizePx; ++x) {
      const double v = image.at(x, y).g;
      const glm::dvec2 p(x + 0.5, y + 0.5);
      energy += v;
      mean += v * p;
      second += v * p * p;
    }
  mean /= energy;
  const glm::dvec2 variance =
      second / energy - mean * mean - glm::dvec2((4.0 * kMarkerHalfPx * kMarkerHalfPx + 1.0) / 12.0);
  const double ratio = std::sqrt(variance.y / variance.x);
  const double semiAxisX = 2.0 * std::sqrt(variance.x), semiAxisY = 2.0 * std::sqrt(variance.y);
  std::printf("  semi-axes %.2f x %.2f px (expected %.2f x %.2f), ratio %.4f\n", semiAxisX, semiAxisY,
              kCocRadiusPx / std::sqrt(2.0), kCocRadiusPx * std::sqrt(2.0), ratio);
  EXPECT_NEAR(ratio, 2.0, 0.02) << "taller than wide by the squeeze";
  EXPECT_NEAR(semiAxisX * semiAxisY, kCocRadiusPx * kCocRadiusPx, 0.01 * kCocRadiusPx * kCocRadiusPx)
      << "the round aperture's area";
  // And the outline: the predicted oval fits better than a rounder or a flatter one.
  const double fit = rmseAgainst(image, predicted(apertureOutline(shape, 256)));
  for (const double other : {1.7, 2.3}) {
    ApertureShape o = shape;
    o.anamorphicSqueeze = other;
    const double otherFit = rmseAgainst(image, predicted(apertureOutline(o, 256)));
    std::printf("  RMSE against squeeze 2: %.5f, against %.1f: %.5f\n", fit, other, otherFit);
    EXPECT_LT(fit * 1.3, otherFit);
  }
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

// An unlit white wall on the plane of focus, filling the view: every aperture point sees the same
// white at every pixel, so a pixel's value is the share of the aperture the barrel lets through
// from its direction — the two circles' overlap (lens/LensBarrel.h), known in closed form.
Scene whiteWall() {
  Scene scene;
  scene.source = "white wall";
  scene.lighting.background = glm::vec3(0.0f);
  addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -kFocus)), 4.0, 4.0, glm::vec3(1.0f));
  return scene;
}

// That overlap at continuous pixel position `pixel` of `camera`'s image.
double shareThroughBarrel(const Camera& camera, ImageSize size, glm::dvec2 pixel) {
  const glm::dvec2 w = windowFromPixel(camera.view.window, pixel, size.widthPx, size.heightPx);
  const glm::dvec2 n = (w - glm::dvec2(camera.view.prp)) / camera.view.prp.z;
  return roundApertureThroughBarrel(camera.lens.barrel, camera.lens.apertureRadius, n, camera.inverseFocusDistance());
}

TEST(CatsEye, APixelSeesTheShareOfTheApertureThatTheBarrelLetsThrough) {
  LENSLAB_REQUIRE_GL();
  const Scene scene = whiteWall();
  Camera camera = bokehCamera(ApertureShape{});
  camera.lens.apertureRadius = 0.1;
  // Seen in the opening's plane the aperture has radius 0.1·(1 − 0.2/2) = 0.09, centred at 0.2·n:
  // whole at the centre, clipped toward the edges, most at the corners (|n| = 0.71).
  camera.lens.barrel = LensBarrel{0.2, 0.13};
  const ImageSize size{48, 48};
  Renderer renderer(scene);
  const FramePlan plan = makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Sobol, 1024, 1024, 3});
  const Image raster = renderer.render(camera, plan, size);
  const Image raycast = RayCaster(scene).render(camera, size, RaycastOptions{1024, 4});
  double worstRaster = 0.0, worstRaycast = 0.0, least = 1.0;
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      const double share = shareThroughBarrel(camera, size, {x + 0.5, y + 0.5});
      least = std::min(least, share);
      worstRaster = std::max(worstRaster, std::abs(raster.at(x, y).g - share));
      worstRaycast = std::max(worstRaycast, std::abs(raycast.at(x, y).g - share));
    }
  std::printf(
      "  share of the aperture through the barrel: least %.3f (a corner); worst |image - overlap| raster %.4f, ray "
      "cast %.4f\n",
      least, worstRaster, worstRaycast);
  EXPECT_LT(least, 0.5) << "the test's barrel should clip the corners";
  EXPECT_LT(worstRaster, 0.02);
  EXPECT_LT(worstRaycast, 0.02);
  EXPECT_NEAR(raster.at(24, 24).g, 1.0, 1e-4) << "the centre sees the whole aperture";
}

// A barrel whose opening passes light only within a few pixels of the centre (a small aperture
// far behind a narrow opening): the share changes within a pixel, so a pixel's value is the
// overlap averaged over its area, not taken at its centre. The raster tests each view's barrel at
// that view's jittered sample, as the ray caster tests each ray at its film point.
TEST(CatsEye, WhereTheShareChangesWithinAPixelThePixelAveragesItOverItsArea) {
  LENSLAB_REQUIRE_GL();
  const Scene scene = whiteWall();
  Camera camera = bokehCamera(ApertureShape{});
  camera.lens.apertureRadius = 0.001;
  // The aperture, radius 0.0009 in the opening's plane, wholly inside the 0.0089 opening for
  // |n| < 0.04 and wholly outside for |n| > 0.049: a disk of some 2 px radius whose rim is sharper
  // than a pixel (n changes by 0.021 a pixel).
  camera.lens.barrel = LensBarrel{0.2, 0.0089};
  const ImageSize size{48, 48};
  Renderer renderer(scene);
  const FramePlan plan = makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Sobol, 1024, 1024, 3});
  const Image raster = renderer.render(camera, plan, size);
  const Image raycast = RayCaster(scene).render(camera, size, RaycastOptions{4096, 4});
  const auto shareAt = [&](glm::dvec2 pixel) { return shareThroughBarrel(camera, size, pixel); };
  double worstRaster = 0.0, worstRaycast = 0.0, centreVersusArea = 0.0;
  for (int y = 16; y < 32; ++y)
    for (int x = 16; x < 32; ++x) {
      constexpr int kSub = 16;
      double area = 0.0;
      for (int j = 0; j < kSub; ++j)
        for (int i = 0; i < kSub; ++i) area += shareAt({x + (i + 0.5) / kSub, y + (j + 0.5) / kSub});
      area /= kSub * kSub;
      centreVersusArea = std::max(centreVersusArea, std::abs(shareAt({x + 0.5, y + 0.5}) - area));
      worstRaster = std::max(worstRaster, std::abs(raster.at(x, y).g - area));
      worstRaycast = std::max(worstRaycast, std::abs(raycast.at(x, y).g - area));
    }
  std::printf(
      "  narrow barrel: the overlap at a pixel's centre is up to %.3f off its area's mean; worst |image - area "
      "mean| raster %.4f, ray cast %.4f\n",
      centreVersusArea, worstRaster, worstRaycast);
  EXPECT_GT(centreVersusArea, 0.05) << "the test's share should change within a pixel";
  EXPECT_LT(worstRaster, 0.02);
  EXPECT_LT(worstRaycast, 0.02);
}

TEST(CatsEye, ABarrelThatClipsNothingChangesNothing) {
  LENSLAB_REQUIRE_GL();
  const Scene scene = markerScene();
  Camera camera = bokehCamera(ApertureShape{});
  const ImageSize size{kSizePx, kSizePx};
  Renderer renderer(scene);
  const FramePlan plan = makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Sobol, 64, 64, 3});
  const Image without = renderer.render(camera, plan, size);
  camera.lens.barrel = LensBarrel{0.01, 10.0};  // wide open
  const FramePlan withPlan = makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Sobol, 0, 256, 3});
  const FramePlan withoutPlan =
      makeFramePlan(scene, bokehCamera(ApertureShape{}), size, PlanOptions{AperturePattern::Sobol, 0, 256, 3});
  EXPECT_EQ(withPlan.apertureSamples, withoutPlan.apertureSamples) << "no more views for a barrel that hides nothing";
  const Image with = renderer.render(camera, plan, size);
  double worst = 0.0;
  for (std::size_t i = 0; i < with.rgba.size(); ++i)
    worst = std::max(worst, static_cast<double>(std::abs(with.rgba[i] - without.rgba[i])));
  EXPECT_LT(worst, 1e-5);
}

}  // namespace
}  // namespace lenslab
