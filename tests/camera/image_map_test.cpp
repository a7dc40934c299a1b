// camera/ImageMap: the frame's one map from pixels to rays. Round trips pixel → ray → pixel on
// fixed-seed random points (perspective and parallel, oblique, with an aperture, with and without
// distortion and lateral colour) through the lecture's projection formula; the raster's
// clipFromWorld sends every point of a sample's ray to the pixel the ray left; and the real-lens
// map's rays are LensCamera's traced rays.
#include "camera/Camera.h"
#include "camera/ImageMap.h"
#include "camera/LensMap.h"
#include "camera/Projection.h"
#include "camera/Ray.h"
#include "core/TextFile.h"
#include "lens/LensCamera.h"
#include "lens/LensPrescription.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

namespace lenslab {
namespace {

constexpr ImageSize kSize{160, 110};

// An oblique camera (the PRP off the window's centre) with an aperture, focused off its view plane.
Camera obliqueCamera(Projection projection) {
  Camera c;
  c.view.projection = projection;
  c.view.vrp = {0.3, -0.2, 1.0};
  c.view.vpn = glm::normalize(glm::dvec3(0.2, 0.1, 1.0));
  c.view.prp = {0.08, -0.05, 2.0};
  c.view.window = {-0.7, -0.45, 0.75, 0.55};
  c.lens.apertureRadius = 0.04;
  c.source = "test camera";
  return projection == Projection::Perspective ? refocused(c, 5.0, "test") : c;
}

struct Lens {
  const char* name;
  Distortion distortion;
  double lateralRed = 0.0, lateralBlue = 0.0;
  double axialRed = 0.0, axialBlue = 0.0;
};

const Lens kLenses[] = {
    {"none", {}},
    {"barrel", Distortion{-0.18, 0.03, 0.001, -0.0008, 0.0}},
    {"pincushion + lateral + axial colour", Distortion{0.12, -0.01, 0.0, 0.0, 0.0}, 0.004, -0.003, 0.02, -0.015},
};

Camera withLens(Camera c, const Lens& lens) {
  c.lens.effects.distortion = lens.distortion;
  c.lens.effects.chromatic.lateralRed = lens.lateralRed;
  c.lens.effects.chromatic.lateralBlue = lens.lateralBlue;
  c.lens.effects.chromatic.inverseFocusShiftRed = lens.axialRed;
  c.lens.effects.chromatic.inverseFocusShiftBlue = lens.axialBlue;
  validateLensEffects(c, "test");
  return c;
}

glm::dvec2 randomOnDisk(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double r = std::sqrt(u(rng)), phi = 2.0 * std::numbers::pi * u(rng);
  return {r * std::cos(phi), r * std::sin(phi)};
}

// Where the output image shows channel `c`'s true perspective pixel position `ideal`: the lens
// model applied forward (distortion, then the channel's magnification).
glm::dvec2 outputPixel(const ThinLensMap& map, Channel c, glm::dvec2 ideal) {
  if (!map.camera().lens.effects.needsRemap()) return ideal;
  return map.pixelFromNormalised(map.camera().lens.effects.distortChannel(c, map.normalisedFromPixel(ideal)));
}

// Every point of the ray from lens point s through output pixel p lands back on p: projected by
// the lecture's formula (projectToWindow) from that lens point's view (focused for the channel),
// then carried through the forward lens model.
TEST(ImageMap, PixelToRayToPixelRoundTrips) {
  for (const Projection projection : {Projection::Perspective, Projection::Parallel}) {
    for (const Lens& lens : kLenses) {
      if (projection == Projection::Parallel && lens.distortion.k1 != 0.0) continue;  // lens effects need a perspective
      const Camera camera = withLens(obliqueCamera(projection), lens);
      const ThinLensMap map(camera, kSize);
      EXPECT_EQ(map.rayChannels(), lens.lateralRed != 0.0 ? 3 : 1) << lens.name;
      std::mt19937 rng(7);
      std::uniform_real_distribution<double> x(-5.0, kSize.widthPx + 5.0), y(-5.0, kSize.heightPx + 5.0), t(0.5, 30.0);
      double worst = 0.0;
      for (int i = 0; i < 400; ++i) {
        const glm::dvec2 pixel(x(rng), y(rng));
        const glm::dvec2 disk = i % 4 == 0 ? glm::dvec2(0.0) : randomOnDisk(rng);
        for (int channel = 0; channel < 3; ++channel) {
          const Channel c = static_cast<Channel>(channel);
          const std::optional<CameraRay> r = map.ray(pixel, disk, channel);
          ASSERT_TRUE(r);
          EXPECT_NEAR(glm::length(r->ray.direction), 1.0, 1e-12);
          const glm::dvec3 point = r->ray.origin + t(rng) * r->ray.direction;
          const ViewSpec seenFrom = viewThroughLens(camera, camera.lens.lensOffset(disk), {0.0, 0.0},
                                                    camera.lens.effects.chromatic.inverseFocusShift(c));
          const glm::dvec2 ideal =
              pixelFromWindow(seenFrom.window, projectToWindow(seenFrom, point), kSize.widthPx, kSize.heightPx);
          const double error = glm::length(outputPixel(map, c, ideal) - pixel);
          worst = std::max(worst, error);
          ASSERT_LT(error, 1e-6) << lens.name << (projection == Projection::Parallel ? ", parallel" : ", perspective")
                                 << ", pixel " << pixel.x << "," << pixel.y << ", channel " << channel;
        }
      }
      std::printf("  %s, %s: worst round trip %.2g px\n",
                  projection == Projection::Parallel ? "parallel" : "perspective", lens.name, worst);
    }
  }
}

// Without lens effects the map's ray is the lecture's lens ray (camera/Ray.h), bit for bit; and the
// map's conversions invert each other.
TEST(ImageMap, PlainCameraRaysAreLensRaysAndConversionsInvert) {
  for (const Projection projection : {Projection::Perspective, Projection::Parallel}) {
    const Camera camera = obliqueCamera(projection);
    const ThinLensMap map(camera, kSize);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> x(0.0, kSize.widthPx), y(0.0, kSize.heightPx);
    for (int i = 0; i < 200; ++i) {
      const glm::dvec2 pixel(x(rng), y(rng)), disk = randomOnDisk(rng);
      const Ray expected = lensRay(camera, camera.lens.lensOffset(disk), pixel, kSize);
      const CameraRay r = *map.ray(pixel, disk, 1);
      EXPECT_EQ(r.ray.origin, expected.origin);
      EXPECT_EQ(r.ray.direction, expected.direction);
      EXPECT_EQ(r.ray.tNear, expected.tNear);
      EXPECT_FALSE(r.blocked);
      const Ray over = map.footprintRay(r, {0.25, -0.5});
      EXPECT_EQ(over.direction,
                lensRay(camera, camera.lens.lensOffset(disk), pixel + glm::dvec2(0.25, -0.5), kSize).direction);
      EXPECT_NEAR(glm::length(map.pixelFromWindow(map.windowFromPixel(pixel)) - pixel), 0.0, 1e-9);
      if (projection == Projection::Perspective) {
        EXPECT_NEAR(glm::length(map.pixelFromNormalised(map.normalisedFromPixel(pixel)) - pixel), 0.0, 1e-9);
      }
    }
    EXPECT_EQ(map.gainAt({3.5, 7.5}), 1.0);
  }
}

// The raster's view of one aperture sample (lens point and sub-pixel jitter) sends every point of
// the ray the ray caster casts for that sample to the pixel the ray left: the two renderers ask
// one map. With distortion the view shows the true perspective image over the overscan render;
// the lens pass's forward map (outputFromRenderPixel, green) carries it to the output pixel.
TEST(ImageMap, ClipFromWorldAgreesWithRay) {
  for (const Projection projection : {Projection::Perspective, Projection::Parallel}) {
    for (const Lens& lens : kLenses) {
      if (projection == Projection::Parallel && lens.distortion.k1 != 0.0) continue;
      const ThinLensMap map = ThinLensMap(withLens(obliqueCamera(projection), lens), kSize).overscanned();
      const ImageSize render = map.overscan().size;
      if (lens.distortion.k1 < 0.0) {
        EXPECT_GT(map.overscan().padPx.x, 2) << "barrel pulls the render's border in: " << lens.name;
      }
      std::mt19937 rng(3);
      std::uniform_real_distribution<double> x(0.0, kSize.widthPx), y(0.0, kSize.heightPx), t(0.5, 30.0), j(-0.5, 0.5);
      for (int i = 0; i < 300; ++i) {
        const LensSample s{randomOnDisk(rng), {j(rng), j(rng)}};
        const glm::dvec2 pixel(x(rng), y(rng));
        for (int channel = 0; channel < 3; ++channel) {
          const Channel c = static_cast<Channel>(channel);
          // The ray through the film point the jittered view's pixel centre stands for.
          const CameraRay r = *map.ray(pixel, s.lens, channel);
          const glm::dvec4 clip = map.clipFromWorld(s, c) * glm::dvec4(r.ray.origin + t(rng) * r.ray.direction, 1.0);
          ASSERT_GT(clip.w, 0.0);
          const glm::dvec2 ndc(clip.x / clip.w, clip.y / clip.w);
          // GL's viewport: NDC onto the render's pixels (image rows run down); the jitter undone.
          const glm::dvec2 inView(0.5 * (ndc.x + 1.0) * render.widthPx, 0.5 * (1.0 - ndc.y) * render.heightPx);
          const glm::dvec2 renderPixel = inView + s.pixel;
          EXPECT_NEAR(glm::length(renderPixel - glm::dvec2(map.overscan().padPx) - r.pixel), 0.0, 1e-6)
              << lens.name << ", channel " << channel;
          if (c == Channel::Green) {
            EXPECT_NEAR(glm::length(map.outputFromRenderPixel(renderPixel) - pixel), 0.0, 1e-6) << lens.name;
            EXPECT_NEAR(glm::length(map.renderPixelFromOutput(pixel) - renderPixel), 0.0, 1e-6) << lens.name;
          }
        }
      }
    }
  }
}

// Vignetting moves no ray and scales the pixel by the gain at its place on the film.
TEST(ImageMap, VignettingIsAGainNotARay) {
  Camera camera = obliqueCamera(Projection::Perspective);
  camera.lens.effects.vignetting.a1 = -0.3;
  const ThinLensMap map(camera, kSize);
  EXPECT_FALSE(map.start({3.5, 2.5}, 1)) << "vignetting alone solves no inverse";
  const glm::dvec2 corner(0.5, 0.5);
  const glm::dvec2 n = map.normalisedFromPixel(corner);
  EXPECT_DOUBLE_EQ(map.gainAt(corner), 1.0 - 0.3 * glm::dot(n, n));
  EXPECT_EQ(map.ray(corner, {0.3, 0.2}, 1)->ray.direction,
            lensRay(camera, camera.lens.lensOffset({0.3, 0.2}), corner, kSize).direction);
}

LensPrescription bundled(const std::string& name) {
  const std::string path = std::string(LENSLAB_UNIT_ASSET_DIR) + "/lenses/" + name;
  return parseLensPrescription(readTextFile(path, "lens file"), path);
}

// The real-lens map's rays are the prescription's traced rays (LensCamera::ray), stopped where it
// stops them; its footprint rays are the neighbouring film points' with the same pupil sample.
TEST(ImageMap, RealLensRaysAreTheTracedRays) {
  const auto prescription = std::make_shared<const LensPrescription>(bundled("double-gauss-50mm.lens"));
  LensCameraSettings settings;
  settings.focusDistance = 3.0;
  LensCameraPose pose;
  pose.eye = {0.5, 1.2, 4.0};
  const LensCamera lens(prescription, settings, pose);
  const Camera placed = obliqueCamera(Projection::Perspective);
  const RealLensMap map(lens, placed, kSize);
  EXPECT_EQ(map.lensDomain(), LensDomain::Square);
  EXPECT_EQ(map.rayChannels(), lens.dispersion() ? 3 : 1);
  EXPECT_EQ(map.camera().source, placed.source);
  EXPECT_THROW(map.fitted(), std::logic_error);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> x(0.0, kSize.widthPx), y(0.0, kSize.heightPx), u(0.0, 1.0);
  int passed = 0, stopped = 0;
  for (int i = 0; i < 400; ++i) {
    const glm::dvec2 pixel(x(rng), y(rng)), pupil(u(rng), u(rng));
    const int channel = i % 3;
    const std::optional<LensCamera::WorldRay> expected = lens.ray(pixel, kSize.widthPx, kSize.heightPx, pupil, channel);
    const std::optional<CameraRay> r = map.ray(pixel, pupil, channel);
    ASSERT_EQ(r.has_value(), expected.has_value());
    if (!r) {
      ++stopped;
      continue;
    }
    ++passed;
    EXPECT_EQ(r->ray.origin, expected->origin);
    EXPECT_EQ(r->ray.direction, expected->direction);
    EXPECT_EQ(r->weight, expected->weight);
    EXPECT_FALSE(r->blocked);
    const std::optional<LensCamera::WorldRay> over =
        lens.ray(pixel + glm::dvec2(0.0, 0.3), kSize.widthPx, kSize.heightPx, pupil, channel);
    EXPECT_EQ(map.footprintRay(*r, {0.0, 0.3}).direction, over ? over->direction : r->ray.direction);
  }
  EXPECT_GT(passed, 100);
  EXPECT_GT(stopped, 0) << "the pupil's box should hold samples the lens stops";

  // With its fitted thin lens, fitted() is that camera's map at the same size.
  Camera fittedCamera = placed;
  fittedCamera.source = "fitted";
  const RealLensMap withFit(lens, placed, kSize, fittedCamera);
  EXPECT_EQ(withFit.fitted().camera().source, "fitted");
  EXPECT_EQ(withFit.fitted().size().widthPx, kSize.widthPx);
}

}  // namespace
}  // namespace lenslab
