// Thin-lens depth of field by accumulation, checked against the lecture's geometry.
#include "camera/Camera.h"
#include "camera/Projection.h"
#include "camera/Ray.h"
#include "../common/gl_test_context.h"
#include "io/CameraJson.h"
#include "io/ImageCompare.h"
#include "plan/FramePlan.h"
#include "render/Renderer.h"
#include "scene/GltfLoader.h"
#include "scene/ProceduralScenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

// Camera at the origin looking down −z, view plane (= plane of focus) at `focus`, window 2 wide.
Camera lensCamera(double focus, double apertureRadius, double aspect = 1.0) {
  ViewSpec v;
  v.vrp = {0.0, 0.0, -focus};
  v.vpn = {0.0, 0.0, 1.0};
  v.prp = {0.0, 0.0, focus};
  v.window = {-1.0, -1.0 / aspect, 1.0, 1.0 / aspect};
  v.nearDistance = 0.01;
  return cameraFocusedOnViewPlane(v, apertureRadius, "test");
}

FramePlan planWith(const Scene& scene, const Camera& camera, ImageSize size, AperturePattern pattern, int samples) {
  return makeFramePlan(scene, camera, size, PlanOptions{pattern, samples, samples, 5});
}

// A pinhole rendered with the same sub-pixel jitter as `plan` (lens offsets × radius 0), so that
// only the lens differs between the two images.
Image pinholeWithSameJitter(Renderer& renderer, Camera camera, const FramePlan& plan, ImageSize size) {
  camera.lens.apertureRadius = 0.0;
  return renderer.render(camera, plan, size);
}

Scene checkerQuadAt(double depth, double halfSize) {
  Scene scene;
  scene.source = "checker quad";
  TextureImage image;
  image.width = image.height = 64;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const std::uint8_t c = ((x / 8 + y / 8) % 2) ? 230 : 30;
      image.rgba8.insert(image.rgba8.end(), {c, static_cast<std::uint8_t>(255 - c), 128, 255});
    }
  scene.images.push_back(image);
  scene.textures.push_back({0, Sampler{}});
  Material m;
  m.unlit = true;
  m.baseColorTexture.texture = 0;
  scene.materials.push_back(m);
  scene.meshes.push_back(quadMesh(halfSize, halfSize, 0));
  scene.instances.push_back({0, glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -depth))});
  scene.bounds = computeBounds(scene);
  return scene;
}

TEST(DepthOfField, ThePlaneOfFocusShowsNoParallax) {
  LENSLAB_REQUIRE_GL();
  const Scene scene = checkerQuadAt(4.0, 1.5);
  const Camera camera = lensCamera(4.0, 0.4);
  const ImageSize size{160, 160};
  Renderer renderer(scene);
  const FramePlan plan = planWith(scene, camera, size, AperturePattern::Concentric, 64);
  const Image lens = renderer.render(camera, plan, size);
  const Image pinhole = pinholeWithSameJitter(renderer, camera, plan, size);
  const double psnr = compareImages(lens, pinhole, 0.0).psnrDb;
  EXPECT_GE(psnr, 50.0);
  // and the aperture is wide: the same quad 10% off the plane of focus is visibly blurred
  const Scene off = checkerQuadAt(4.4, 1.5);
  Renderer offRenderer(off);
  const double offPsnr =
      compareImages(offRenderer.render(camera, plan, size), pinholeWithSameJitter(offRenderer, camera, plan, size), 0.0)
          .psnrDb;
  EXPECT_LT(offPsnr, 30.0);
}

// Fraction of a disk of diameter c (centred at s) lying left of x = 0, convolved with a 1-pixel box
// (the sub-pixel jitter): the expected profile across a blurred straight edge.
double edgeProfile(double x, double c) {
  auto disk = [c](double s) {
    const double r = c / 2.0;
    if (s <= -r) return 1.0;
    if (s >= r) return 0.0;
    // area of the circular segment beyond distance s from the centre, over the whole disk
    const double segment = r * r * std::acos(s / r) - s * std::sqrt(r * r - s * s);
    return segment / (std::numbers::pi * r * r);
  };
  double sum = 0.0;
  const int steps = 200;
  for (int i = 0; i < steps; ++i) sum += disk(x + (i + 0.5) / steps - 0.5);
  return sum / steps;
}

double widthBetween(const std::function<double(double)>& profile, double lo, double hi) {
  // the profile falls from 1 to 0 as x grows: find where it crosses `hi` and `lo`
  auto cross = [&](double level) {
    double a = -1e3, b = 1e3;
    for (int i = 0; i < 200; ++i) {
      const double m = 0.5 * (a + b);
      (profile(m) > level ? a : b) = m;
    }
    return 0.5 * (a + b);
  };
  return cross(lo) - cross(hi);
}

// A white half-plane (x < 0) at 6 m on black.
Scene edgeScene() {
  Scene scene;
  scene.source = "edge";
  scene.lighting.background = glm::vec3(0.0f);
  addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(-50.0, 0.0, -6.0)), 50.0, 50.0, glm::vec3(1.0f));
  return scene;
}

// The 10–90 % width of the edge along row y (pixel centres at x + 0.5, linear in between).
double measuredEdgeWidth(const Image& image, int y) {
  auto at = [&](double x) {
    const int i = std::clamp(static_cast<int>(std::floor(x - 0.5)), 0, image.width - 2);
    const double t = std::clamp(x - 0.5 - i, 0.0, 1.0);
    return (1 - t) * image.at(i, y).g + t * image.at(i + 1, y).g;
  };
  return widthBetween(at, 0.1, 0.9);
}

TEST(DepthOfField, AStraightEdgeBlursToTheCircleOfConfusion) {
  LENSLAB_REQUIRE_GL();
  // Focus at 3 m, the edge at 6 m: CoC on the window = 2R·|z − z_f|/z = R.
  const Scene scene = edgeScene();
  const double radius = 0.2;
  const Camera camera = lensCamera(3.0, radius, 3.0);
  const ImageSize size{300, 100};
  const double cocPx = cocDiameterOnWindow(camera, 6.0) * size.widthPx / camera.view.window.width();
  ASSERT_NEAR(cocPx, 30.0, 1e-9);
  Renderer renderer(scene);
  const Image image = renderer.render(camera, planWith(scene, camera, size, AperturePattern::Concentric, 1024), size);
  const double measured =
      (measuredEdgeWidth(image, 40) + measuredEdgeWidth(image, 50) + measuredEdgeWidth(image, 60)) / 3.0;
  const double expected = widthBetween([&](double x) { return edgeProfile(x, cocPx); }, 0.1, 0.9);
  EXPECT_NEAR(measured, expected, 0.1 * expected) << "CoC " << cocPx << " px";
}

TEST(DepthOfField, Lecture17SplitsAnOffFocusMarkerIntoSeventeenCopies) {
  LENSLAB_REQUIRE_GL();
  // A tiny marker at 8 m, focus at 2 m: CoC on the window 2R·(8 − 2)/8 = 1.5 R.
  Scene scene;
  scene.source = "marker";
  scene.lighting.background = glm::vec3(0.0f);
  // About 1.5 px wide on the image; copies 60 px apart at the rim, 12 px on the inner ring.
  addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -8.0)), 0.03, 0.03, glm::vec3(1.0f));
  const Camera camera = lensCamera(2.0, 0.4);
  const ImageSize size{200, 200};
  const double cocPx = cocDiameterOnWindow(camera, 8.0) * size.widthPx / camera.view.window.width();  // 60 px
  Renderer renderer(scene);
  const FramePlan plan = planWith(scene, camera, size, AperturePattern::Lecture17, 0);
  ASSERT_EQ(plan.apertureSamples, 17);
  const Image image = renderer.render(camera, plan, size);

  // Connected components of lit pixels, with their centroids.
  std::vector<int> label(static_cast<std::size_t>(size.widthPx * size.heightPx), -1);
  std::vector<glm::dvec3> blobs;  // (sum x·w, sum y·w, sum w)
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      if (image.at(x, y).g < 0.004f || label[static_cast<std::size_t>(y * size.widthPx + x)] >= 0) continue;
      const int id = static_cast<int>(blobs.size());
      blobs.push_back(glm::dvec3(0.0));
      std::vector<glm::ivec2> stack{{x, y}};
      label[static_cast<std::size_t>(y * size.widthPx + x)] = id;
      while (!stack.empty()) {
        const glm::ivec2 p = stack.back();
        stack.pop_back();
        const double w = image.at(p.x, p.y).g;
        blobs[static_cast<std::size_t>(id)] += glm::dvec3((p.x + 0.5) * w, (p.y + 0.5) * w, w);
        for (const glm::ivec2 d : {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1)}) {
          const glm::ivec2 q = p + d;
          if (q.x < 0 || q.y < 0 || q.x >= size.widthPx || q.y >= size.heightPx) continue;
          int& l = label[static_cast<std::size_t>(q.y * size.widthPx + q.x)];
          if (l < 0 && image.at(q.x, q.y).g >= 0.004f) {
            l = id;
            stack.push_back(q);
          }
        }
      }
    }
  ASSERT_EQ(blobs.size(), 17u);
  // Each copy sits at the pattern's point scaled by the CoC radius (behind the plane of focus the
  // image moves with the lens point; image y runs against v). Sub-pixel jitter moves each ≤ ½ px.
  const glm::dvec2 centre(100.0, 100.0);
  for (const LensSample& s : makeApertureSamples(AperturePattern::Lecture17, 17, plan.seed)) {
    const glm::dvec2 expected = centre + glm::dvec2(s.lens.x, -s.lens.y) * (cocPx / 2.0);
    double nearest = 1e9;
    for (const glm::dvec3& b : blobs) nearest = std::min(nearest, glm::length(glm::dvec2(b) / b.z - expected));
    EXPECT_LT(nearest, 1.0) << "no copy near (" << expected.x << ", " << expected.y << ")";
  }
}

TEST(DepthOfField, PartialObscurationKeepsTheFractionOfApertureThatSeesThrough) {
  LENSLAB_REQUIRE_GL();
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / "occluder/occluder.gltf");
  Camera camera = loadCameraJson(assets / "occluder/camera.json").camera;
  camera.lens.apertureRadius = 0.05 / (2.0 * 2.0);  // 50 mm at f/2
  const ImageSize size{240, 160};
  Renderer renderer(scene);
  const FramePlan plan = planWith(scene, camera, size, AperturePattern::Concentric, 256);
  const Image image = renderer.render(camera, plan, size);

  // The bars (from tools/make_assets.py): 11 boxes 1.5 cm square in x and z, centred at x = 0.12·k,
  // z = −1, y from 0.2 to 1.8. The wall, on the plane of focus at z = −4, is a 16 × 16 checker
  // over x ∈ [−2, 2], y ∈ [−0.5, 2.5]; white cells are sRGB 250, the bars orange (0.9, 0.45, 0.1).
  auto blocked = [](const glm::dvec3& from, const glm::dvec3& to) {
    for (int k = -5; k <= 5; ++k) {
      const glm::dvec3 lo(0.12 * k - 0.0075, 0.2, -1.0075), hi(0.12 * k + 0.0075, 1.8, -0.9925);
      double t0 = 0.0, t1 = 1.0;  // slab test along the segment
      bool hit = true;
      for (int a = 0; a < 3 && hit; ++a) {
        const double d = to[a] - from[a];
        if (std::abs(d) < 1e-15) {
          hit = from[a] >= lo[a] && from[a] <= hi[a];
        } else {
          double ta = (lo[a] - from[a]) / d, tb = (hi[a] - from[a]) / d;
          if (ta > tb) std::swap(ta, tb);
          t0 = std::max(t0, ta);
          t1 = std::min(t1, tb);
          hit = t0 <= t1;
        }
      }
      if (hit) return true;
    }
    return false;
  };
  const double white = std::pow((250.0 / 255.0 + 0.055) / 1.055, 2.4);
  const auto samples = makeApertureSamples(plan.pattern, plan.apertureSamples, plan.seed);
  const ViewBasis b = viewBasis(camera.view);
  const glm::dvec3 prp = prpWorld(camera.view);
  const Window& w = camera.view.window;
  const glm::dvec2 pixelSize(w.width() / size.widthPx, w.height() / size.heightPx);
  int checked = 0;
  double worst = 0.0;
  for (int y = 60; y < 100; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      const glm::dvec2 uv = windowFromPixel(w, {x + 0.5, y + 0.5}, size.widthPx, size.heightPx);
      const glm::dvec3 wallPoint = viewPlanePoint(camera.view, uv);
      // Only pixels well inside a white cell: the wall's colour is then the same for every sample.
      const double cu = (wallPoint.x + 2.0) / 0.25, cv = (2.5 - wallPoint.y) / 0.1875;
      const double edge = std::min({cu - std::floor(cu), std::ceil(cu) - cu, cv - std::floor(cv), std::ceil(cv) - cv});
      if (edge < 0.2 || (static_cast<int>(std::floor(cu)) + static_cast<int>(std::floor(cv))) % 2 != 0) continue;
      int visible = 0;
      for (const LensSample& s : samples) {
        const glm::dvec3 lens = prp + camera.lens.apertureRadius * (s.lens.x * b.u + s.lens.y * b.v);
        const glm::dvec3 through = wallPoint + s.pixel.x * pixelSize.x * b.u - s.pixel.y * pixelSize.y * b.v;
        visible += !blocked(lens, through);
      }
      const double fraction = static_cast<double>(visible) / static_cast<double>(samples.size());
      if (fraction < 0.05 || fraction > 0.95) continue;
      const double expected = fraction * white + (1.0 - fraction) * 0.45;
      worst = std::max(worst, std::abs(image.at(x, y).g - expected));
      ++checked;
    }
  EXPECT_GE(checked, 10) << "too few partly obscured pixels to judge";
  // Measured worst: 0.0023 over 286 pixels (rasterisation samples pixel centres exactly as the
  // geometry here does); 0.01 leaves room for driver rounding, a wrong fraction is off by tenths.
  EXPECT_LT(worst, 0.01) << checked << " pixels; brightness differs from the visible fraction of the aperture";
}

TEST(DepthOfField, ShrinkingTheApertureConvergesToThePinhole) {
  LENSLAB_REQUIRE_GL();
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / "rows/rows.gltf");
  Camera camera = loadCameraJson(assets / "rows/camera.json").camera;
  const ImageSize size{180, 120};
  Renderer renderer(scene);
  camera.lens.apertureRadius = 0.02;
  const FramePlan plan = planWith(scene, camera, size, AperturePattern::R2, 16);
  const Image pinhole = pinholeWithSameJitter(renderer, camera, plan, size);
  double previous = 0.0;
  for (double radius : {0.02, 0.002, 0.0002, 0.00002}) {
    camera.lens.apertureRadius = radius;
    const double psnr = compareImages(renderer.render(camera, plan, size), pinhole, 0.0).psnrDb;
    EXPECT_GT(psnr, previous) << "radius " << radius;
    previous = psnr;
  }
  EXPECT_GT(previous, 50.0);
}

TEST(DepthOfField, ParallelProjectionBlursInProportionToDistanceFromTheViewPlane) {
  LENSLAB_REQUIRE_GL();
  // The edge test again, with a parallel projection: CoC on the window = 2R·|z − d|/d.
  const Scene scene = edgeScene();
  Camera camera = lensCamera(3.0, 0.1, 3.0);
  camera.view.projection = Projection::Parallel;
  camera.view.nearDistance = 0.0;
  camera.view.farDistance = 20.0;
  const ImageSize size{300, 100};
  const double cocPx = cocDiameterOnWindow(camera, 6.0) * size.widthPx / camera.view.window.width();
  ASSERT_NEAR(cocPx, 2.0 * 0.1 * 3.0 / 3.0 * 150.0, 1e-9);
  Renderer renderer(scene);
  const Image image = renderer.render(camera, planWith(scene, camera, size, AperturePattern::Concentric, 1024), size);
  const double expected = widthBetween([&](double x) { return edgeProfile(x, cocPx); }, 0.1, 0.9);
  EXPECT_NEAR(measuredEdgeWidth(image, 50), expected, 0.1 * expected);
}

}  // namespace
}  // namespace lenslab
