// The oracle's own checks (tests/common/pixel_integral.h): clipping, the Gauss rules, the camera
// it builds from the lecture's formula, and its images against closed forms and against
// themselves at twice the quadrature (the grazing floor's: tests/render/oracle_test.cpp). No GL; they live beside the oracle tests they support.
#include "../common/pixel_integral.h"
#include "camera/Projection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lenslab::test {
namespace {

constexpr ImageSize kSize{96, 64};

Camera cameraAt(double focusM, double halfWidth, double apertureRadius) {
  return axisCamera(focusM, halfWidth, apertureRadius, kSize);
}

double maxDifference(const Image& a, const Image& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i)
    worst = std::max(worst, static_cast<double>(std::abs(a.rgba[i] - b.rgba[i])));
  return worst;
}

TEST(OracleIntegrator, ClipsConvexPolygons) {
  const Polygon square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_DOUBLE_EQ(std::abs(signedArea(clipToHalfPlane(square, {1, 1}, 1.0))), 0.5);
  EXPECT_DOUBLE_EQ(std::abs(signedArea(clipToBox(square, {0.25, -1.0}, {2.0, 0.5}))), 0.375);
  // A diamond of half-diagonal 1 about (1, 1) against the square: one quarter of its area 2.
  const Polygon diamond{{1, 0}, {2, 1}, {1, 2}, {0, 1}};
  EXPECT_NEAR(std::abs(signedArea(clipToConvex(square, diamond))), 0.5, 1e-15);
  // Either orientation of the clipper.
  const Polygon reversed(diamond.rbegin(), diamond.rend());
  EXPECT_NEAR(std::abs(signedArea(clipToConvex(square, reversed))), 0.5, 1e-15);
  EXPECT_TRUE(clipToBox(square, {2, 2}, {3, 3}).empty());
}

// ∫ x^a y^b over the triangle (0,0), (1,0), (0,1) is a! b! / (a + b + 2)!.
TEST(OracleIntegrator, TriangleRuleIsExactForPolynomialsUpToItsDegree) {
  const int n = 8;
  const QuadratureRule rule = gaussLegendre01(n);
  const Polygon triangle{{0, 0}, {1, 0}, {0, 1}};
  for (int a = 0; a <= 2 * n - 2; ++a)
    for (int b = 0; a + b <= 2 * n - 2; ++b) {
      const double got =
          integrateConvex(
              triangle, [&](glm::dvec2 p) { return glm::dvec3(std::pow(p.x, a) * std::pow(p.y, b)); }, rule)
              .x;
      const double expected = std::tgamma(a + 1.0) * std::tgamma(b + 1.0) / std::tgamma(a + b + 3.0);
      EXPECT_NEAR(got, expected, 1e-15) << "x^" << a << " y^" << b;
    }
}

// The oracle builds its own projection from the lecture's formula; it must agree with lenslab's
// camera (projectToWindow, pixelFromWindow, viewThroughLens), including through the lens.
TEST(OracleIntegrator, ProjectionAgreesWithTheCameraModel) {
  Camera camera = cameraAt(4.0, 2.0, 0.25);
  camera.view.vpn = glm::normalize(glm::dvec3(0.2, 0.3, 1.0));  // not along an axis
  camera.view.vrp = {0.5, -0.2, -3.0};
  for (const glm::dvec2 lens : {glm::dvec2(0.0, 0.0), glm::dvec2(0.2, -0.1)}) {
    const PinholeProjection projection(camera, kSize, lens);
    const ViewSpec view = viewThroughLens(camera, lens, {0.0, 0.0});
    for (const glm::dvec3 p : {glm::dvec3(0.3, -0.4, -5.0), glm::dvec3(-1.0, 0.7, -2.5), glm::dvec3(2.0, 1.0, -9.0)}) {
      const glm::dvec2 expected = pixelFromWindow(view.window, projectToWindow(view, p), kSize.widthPx, kSize.heightPx);
      const glm::dvec2 got = projection.pixel(p);
      EXPECT_NEAR(got.x, expected.x, 1e-9);
      EXPECT_NEAR(got.y, expected.y, 1e-9);
    }
  }
}

// Fronto-parallel, the plane's texture coordinates are affine in the pixel's, and the pixel
// integral separates: ∫∫ T(s, t) over the pixel = Σ T_ij · (∫ weight_i ds)(∫ weight_j dt), with
// box weights (nearest) or hat weights centred on the texel centres (bilinear).
double boxIntegral(double t0, double t1, int i) {
  return std::max(0.0, std::min(t1, i + 1.0) - std::max(t0, static_cast<double>(i)));
}
double hatIntegral(double t0, double t1, int i) {
  // Antiderivative of max(0, 1 − |t − c|), c = i + 0.5.
  const auto h = [&](double t) {
    const double d = t - (i + 0.5);
    return d < -1.0 ? 0.0 : d < 0.0 ? 0.5 * (d + 1.0) * (d + 1.0) : d < 1.0 ? 1.0 - 0.5 * (1.0 - d) * (1.0 - d) : 1.0;
  };
  return h(t1) - h(t0);
}

TEST(OracleIntegrator, FrontoParallelPlaneMatchesTheSeparableClosedForm) {
  const TextureImage image = randomTexture(16, 16, 9);
  const Camera camera = cameraAt(1.5, 1.0, 0.0);
  const PinholeProjection projection(camera, kSize);
  TexturedPlane plane;  // 5 m × 4 m at 3 m: covers the whole image, 1.87 px per texel
  plane.origin = {-2.53, 2.07, -3.0};
  plane.perU = {1.25, 0.0, 0.0};
  plane.perV = {0.0, -1.25, 0.0};
  plane.uvMax = {4.0, 3.2};
  plane.image = &image;
  const glm::dvec2 origin = projection.pixel(plane.world({0, 0}));
  const glm::dvec2 texelsPerPixel(image.width / (projection.pixel(plane.world({1, 0})).x - origin.x),
                                  image.height / (projection.pixel(plane.world({0, 1})).y - origin.y));
  for (const bool nearest : {true, false}) {
    plane.nearest = nearest;
    const Image oracle = planeImage(plane, projection, kSize, glm::dvec3(0.0));
    double worst = 0.0;
    for (int y = 0; y < kSize.heightPx; y += 3)
      for (int x = 0; x < kSize.widthPx; x += 3) {
        const double s0 = (x - origin.x) * texelsPerPixel.x, s1 = s0 + texelsPerPixel.x;
        const double t0 = (y - origin.y) * texelsPerPixel.y, t1 = t0 + texelsPerPixel.y;
        glm::dvec3 sum(0.0);
        for (int j = static_cast<int>(std::floor(t0)) - 1; j <= static_cast<int>(std::ceil(t1)); ++j)
          for (int i = static_cast<int>(std::floor(s0)) - 1; i <= static_cast<int>(std::ceil(s1)); ++i) {
            const double w = nearest ? boxIntegral(s0, s1, i) * boxIntegral(t0, t1, j)
                                     : hatIntegral(s0, s1, i) * hatIntegral(t0, t1, j);
            const std::uint8_t* p =
                &image.rgba8[static_cast<std::size_t>(((j % 16 + 16) % 16) * 16 + (i % 16 + 16) % 16) * 4];
            sum += w * glm::dvec3(decodeSrgb8(p[0]), decodeSrgb8(p[1]), decodeSrgb8(p[2]));
          }
        sum /= (s1 - s0) * (t1 - t0);
        const glm::vec4 got = oracle.at(x, y);
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(got[c] - sum[c]));
      }
    EXPECT_LT(worst, 1e-6) << (nearest ? "nearest" : "bilinear");  // float images
  }
}

// The thin-lens integral against brute force: a 600 × 600 grid over the aperture's square, each
// point's exact areas, for a few pixels; and against itself with twice the Gauss points.
TEST(OracleIntegrator, ThinLensIntegralMatchesBruteForceAndHasConverged) {
  const MovingRect front{{40.3, 20.7}, {52.9, 31.2}, {-9.1, 8.3}, {0.9, 0.8, 0.2}};
  std::vector<MovingRect> back;
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 8; ++i)
      back.push_back({{30.2 + 4.7 * i, 14.9 + 3.1 * j},
                      {30.2 + 4.7 * (i + 1), 14.9 + 3.1 * (j + 1)},
                      {6.0, -5.5},
                      {0.1 * (i % 5), 0.15 * (j % 4), 0.3 + 0.05 * ((i + j) % 3)}});
  const glm::dvec3 background{0.05, 0.06, 0.08};
  const double radius = 0.25;
  const ImageSize size{96, 64};
  const Image used = thinLensRectsImage(front, back, size, background, radius, 12);
  const Image fine = thinLensRectsImage(front, back, size, background, radius, 24);
  EXPECT_LT(maxDifference(used, fine), 1e-7);

  const auto area = [](const MovingRect& r, const MovingRect* also, glm::dvec2 lens, int x, int y) {
    glm::dvec2 lo = glm::max(r.lo + r.pxPerLens * lens, glm::dvec2(x, y)),
               hi = glm::min(r.hi + r.pxPerLens * lens, glm::dvec2(x + 1, y + 1));
    if (also)
      lo = glm::max(lo, also->lo + also->pxPerLens * lens), hi = glm::min(hi, also->hi + also->pxPerLens * lens);
    return std::max(0.0, hi.x - lo.x) * std::max(0.0, hi.y - lo.y);
  };
  for (const glm::ivec2 pixel : {glm::ivec2(41, 21), glm::ivec2(52, 30), glm::ivec2(35, 18), glm::ivec2(60, 33)}) {
    glm::dvec3 sum(0.0);
    int inside = 0;
    const int n = 600;
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a) {
        const glm::dvec2 lens = radius * (glm::dvec2(a + 0.5, b + 0.5) * (2.0 / n) - 1.0);
        if (glm::dot(lens, lens) > radius * radius) continue;
        ++inside;
        double covered = area(front, nullptr, lens, pixel.x, pixel.y);
        glm::dvec3 colour = covered * front.colour;
        for (const MovingRect& r : back) {
          const double visible = area(r, nullptr, lens, pixel.x, pixel.y) - area(r, &front, lens, pixel.x, pixel.y);
          colour += visible * r.colour;
          covered += visible;
        }
        sum += colour + (1.0 - covered) * background;
      }
    const glm::dvec3 expected = sum / static_cast<double>(inside);
    const glm::vec4 got = used.at(pixel.x, pixel.y);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 2e-4) << "pixel " << pixel.x << ", " << pixel.y;
  }
}

}  // namespace
}  // namespace lenslab::test
