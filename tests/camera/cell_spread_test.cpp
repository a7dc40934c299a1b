// camera/CellSpread: how far a thin-lens view's point moves in the image per unit of aperture. It
// vanishes on the plane of focus, is affine in 1/Z, and predicts exactly where a point lands when
// the view's aperture point moves (checked against the views' own clipFromWorld).
#include "camera/CellSpread.h"
#include "camera/Camera.h"
#include "camera/Projection.h"

#include <gtest/gtest.h>

#include <random>

namespace lenslab {
namespace {

constexpr ImageSize kSize{200, 130};

Camera thinLensCamera(ApertureShape shape) {
  Camera c;
  c.view.vrp = {0.3, -0.2, 1.0};
  c.view.vpn = glm::normalize(glm::dvec3(0.2, 0.1, 1.0));
  c.view.prp = {0.05, -0.03, 2.0};
  c.view.window = {-0.7, -0.45, 0.75, 0.55};
  c.lens.apertureRadius = 0.06;
  c.lens.aperture = shape;
  c.source = "test camera";
  return refocused(c, 3.0, "test");
}

glm::dvec2 renderPixel(const glm::dmat4& clipFromWorld, const glm::dvec3& world) {
  const glm::dvec4 clip = clipFromWorld * glm::dvec4(world, 1.0);
  return (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * glm::dvec2(kSize.widthPx, kSize.heightPx);
}

TEST(CellSpread, VanishesOnThePlaneOfFocus) {
  const ThinLensMap map(thinLensCamera({}), kSize);
  const CellSpread spread = cellSpread(map, LensSample{{0.3, -0.2}, {0.1, 0.2}}, Channel::Green);
  const glm::dmat2 atFocus = spread.at(1.0 / 3.0);
  const glm::dmat2 atInfinity = spread.at(0.0);
  for (int c = 0; c < 2; ++c)
    for (int r = 0; r < 2; ++r) EXPECT_NEAR(atFocus[c][r], 0.0, 1e-7 * std::abs(atInfinity[0][0]));
  EXPECT_GT(std::abs(atInfinity[0][0]), 1.0);  // pixels per unit of aperture: a visible blur
}

TEST(CellSpread, PredictsWhereAPointLandsFromAnotherAperturePoint) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-0.6, 0.6), ndc(0.02, 0.9);
  // Per unit of the aperture point (after the shape's map): for a circle, squeezed, and blades.
  for (const ApertureShape& shape :
       {ApertureShape{}, ApertureShape{0, 0.0, 0.0, 2.0}, ApertureShape{6, 20.0, 0.2, 1.5}}) {
    const ThinLensMap map(thinLensCamera(shape), kSize);
    const ViewSpec& spec = map.overscan().camera.view;
    for (int i = 0; i < 50; ++i) {
      const LensSample s{{u(rng), u(rng)}, {0.25, -0.1}};
      const CellSpread spread = cellSpread(map, s, Channel::Green);
      // A world point seen by the view at a random pixel and depth.
      const double zNdc = ndc(rng);
      const glm::dvec4 h = glm::inverse(map.clipFromWorld(s, Channel::Green)) * glm::dvec4(u(rng), u(rng), zNdc, 1.0);
      const glm::dvec3 world = glm::dvec3(h) / h.w;
      const double inverseDepth = 1.0 / depthFromReverseZ(spec, zNdc);
      EXPECT_NEAR(spread.inverseDepthFromNdc.x * zNdc + spread.inverseDepthFromNdc.y, inverseDepth,
                  1e-9 * inverseDepth);
      const glm::dvec2 delta(u(rng) * 0.5, u(rng) * 0.5);
      const LensSample moved{diskFromAperture(apertureFromDisk(s.lens, shape) + delta, shape), s.pixel};
      const glm::dvec2 predicted =
          renderPixel(map.clipFromWorld(s, Channel::Green), world) + spread.at(inverseDepth) * delta;
      const glm::dvec2 actual = renderPixel(map.clipFromWorld(moved, Channel::Green), world);
      EXPECT_NEAR(predicted.x, actual.x, 1e-6) << describeAperture(shape) << ", point " << i;
      EXPECT_NEAR(predicted.y, actual.y, 1e-6) << describeAperture(shape) << ", point " << i;
    }
  }
}

TEST(CellSpread, RefusesAParallelProjection) {
  Camera c = thinLensCamera({});
  c.view.projection = Projection::Parallel;
  const ThinLensMap map(c, kSize);
  EXPECT_THROW(cellSpread(map, LensSample{}, Channel::Green), std::logic_error);
}

}  // namespace
}  // namespace lenslab
