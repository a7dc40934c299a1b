// Ground truth under a real lens (`render --lens`, `raycast --lens` with `--aov`): the AOVs follow
// the traced lens (the mean line of each pixel's bundle, lens/CentreRays.h) and line up with the
// image of either renderer; alpha is coverage over the rays the lens passes in both, so the
// raster's (the fitted thin lens, its barrel stopping views) and the ray cast's (rays the rims
// stop) agree. Measured at a marker's edges, away from the axis where the lens distorts and its
// rims cut the pupil.
#include "camera/ImageMap.h"
#include "camera/LensFitCamera.h"
#include "camera/PhysicalCamera.h"
#include "core/TextFile.h"
#include "io/ImageCompare.h"
#include "lens/LensCamera.h"
#include "lens/LensFit.h"
#include "plan/FramePlan.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "scene/ProceduralScenes.h"
#include "../common/gl_test_context.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

namespace lenslab {
namespace {

constexpr int kMarkerNode = 7;

// Per row through the marker, where its left and right edges are: in the instance AOV (midway
// between the pixel centres either side of the change) and in the image's alpha (where it crosses
// ½, linear between pixel centres). Rows where the marker's run is short (its turned corners) are
// left out.
struct EdgeOffsets {
  std::vector<double> offsetsPx;  // AOV edge − image edge, left and right edges of each row
  double meanPx() const {
    double s = 0.0;
    for (double o : offsetsPx) s += o;
    return offsetsPx.empty() ? 1e9 : s / static_cast<double>(offsetsPx.size());
  }
  double worstPx() const {
    double w = 0.0;
    for (double o : offsetsPx) w = std::max(w, std::abs(o));
    return offsetsPx.empty() ? 1e9 : w;
  }
};

EdgeOffsets edgeOffsets(const std::vector<float>& instance, const Image& image) {
  const int w = image.width, h = image.height;
  std::vector<int> first(h, -1), last(h, -1);
  int longest = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x)
      if (instance[static_cast<std::size_t>(y * w + x)] == static_cast<float>(kMarkerNode)) {
        if (first[y] < 0) first[y] = x;
        last[y] = x;
      }
    if (first[y] >= 0) longest = std::max(longest, last[y] - first[y] + 1);
  }
  // The alpha ½ crossing between pixel centres x − ½ and x + ½ (alpha rising toward `inward`).
  const auto crossing = [&](int y, int x, int inward) {
    const double outside = image.at(x - inward, y).a, inside = image.at(x, y).a;
    if (!(inside >= 0.5 && outside < 0.5)) return std::nan("");
    return x + 0.5 - inward * (inside - 0.5) / (inside - outside);
  };
  EdgeOffsets out;
  for (int y = 0; y < h; ++y) {
    if (first[y] < 2 || last[y] > w - 3 || last[y] - first[y] + 1 < longest * 4 / 5) continue;
    // The image's edge is found near the AOV's: the first pixel from outside with alpha ≥ ½.
    int x = first[y] - 2;
    while (x < last[y] && image.at(x, y).a < 0.5) ++x;
    const double left = crossing(y, x, 1);
    x = last[y] + 2;
    while (x > first[y] && image.at(x, y).a < 0.5) --x;
    const double right = crossing(y, x, -1);
    if (std::isnan(left) || std::isnan(right)) {
      out.offsetsPx.push_back(1e9);  // no clean edge: fails the bound
      continue;
    }
    out.offsetsPx.push_back(first[y] - left);
    out.offsetsPx.push_back(last[y] + 1 - right);
  }
  return out;
}

TEST(LensGroundTruth, AovsFollowTheTracedLensAndAlphaAgreesBetweenTheRenderers) {
  LENSLAB_REQUIRE_GL();
  const std::filesystem::path path =
      std::filesystem::path(LENSLAB_TEST_ASSET_DIR) / "lenses" / "double-gauss-50mm.lens";
  const auto lens =
      std::make_shared<LensPrescription>(parseLensPrescription(readTextFile(path, "lens file"), path.string()));

  // A marker turned 5° (its edges sweep every sub-pixel phase) at the focus distance, out toward
  // the upper-right corner; an occluder nearer, out of focus, toward the lower left.
  Scene scene;
  scene.source = "marker through the double Gauss";
  scene.lighting.background = glm::vec3(0.0f);
  const glm::dmat4 marker = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0.56, 0.34, -2.0)),
                                        glm::radians(5.0), glm::dvec3(0.0, 0.0, 1.0));
  addUnlitQuad(scene, marker, 0.12, 0.12, glm::vec3(0.9f, 0.8f, 0.7f));
  scene.instances.back().gltfNode = kMarkerNode;
  addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(-0.36, -0.2, -1.5)), 0.07, 0.07,
               glm::vec3(0.3f, 0.5f, 0.9f));
  scene.instances.back().gltfNode = 3;
  scene.bounds = computeBounds(scene);

  PhysicalCamera physical;
  physical.eye = {0.0, 0.0, 0.0};
  physical.target = {0.0, 0.0, -1.0};
  physical.focalLengthMm = 50.0;
  physical.fNumber = 2.8;
  physical.focusDistance = 2.0;
  const Camera like = toCamera(physical, "marker through the double Gauss");
  LensCameraSettings settings;
  settings.fNumber = 2.8;
  settings.focusDistance = like.focusDistance();
  LensCameraPose pose;
  pose.eye = physical.eye;
  const LensCamera exactLens(lens, settings, pose);
  LensFitSettings fitSettings;
  fitSettings.fNumber = 2.8;
  fitSettings.focusDistanceMm = settings.focusDistance / pose.worldPerMm;
  const FittedLens fit = fitLens(*lens, fitSettings);
  ASSERT_TRUE(fit.usable) << fit.why;
  const Camera fitted = cameraForFittedLens(like, fit, settings.sensorMm, pose.worldPerMm, "fitted");
  ASSERT_TRUE(fitted.lens.hasBarrel());  // the cat's eye the raster's alpha must see past

  const ImageSize size{180, 120};
  const RealLensMap frame(exactLens, like, size);
  const RayCaster caster(scene);
  AovSelection selection;
  selection.instance = true;
  const std::vector<float> instance = caster.aovImages(frame, selection).instance;
  const Image traced = caster.render(frame, RaycastOptions{256, 5});
  Renderer renderer(scene);
  const Image raster = renderer.render(
      fitted, makeFramePlan(scene, fitted, size, PlanOptions{AperturePattern::Sobol, 256, 256, 1}), size);

  const EdgeOffsets tracedEdges = edgeOffsets(instance, traced), rasterEdges = edgeOffsets(instance, raster);
  Image tracedAlpha = traced, rasterAlpha = raster;
  for (Image* image : {&tracedAlpha, &rasterAlpha})
    for (int y = 0; y < image->height; ++y)
      for (int x = 0; x < image->width; ++x) {
        const float a = image->at(x, y).a;
        image->set(x, y, glm::vec4(a, a, a, 1.0f));
      }
  const double alphaDb = compareImages(rasterAlpha, tracedAlpha, 0.0).psnrDb;
  std::printf(
      "[ measure  ] marker edges, AOV − image: ray cast mean %+.3f px (worst %.3f), raster %+.3f px (worst %.3f) over "
      "%zu edges; alpha raster vs ray cast %.1f dB\n",
      tracedEdges.meanPx(), tracedEdges.worstPx(), rasterEdges.meanPx(), rasterEdges.worstPx(),
      tracedEdges.offsetsPx.size(), alphaDb);
  // The marker spans some 30 rows; each edge is found to ±½ px by the AOV's pixel centres.
  ASSERT_GE(tracedEdges.offsetsPx.size(), 40u);
  EXPECT_LE(std::abs(tracedEdges.meanPx()), 0.15);
  EXPECT_LE(tracedEdges.worstPx(), 0.75);
  EXPECT_LE(std::abs(rasterEdges.meanPx()), 0.3);  // the fit's own error adds
  EXPECT_LE(rasterEdges.worstPx(), 1.0);
  EXPECT_GE(alphaDb, 40.0);
}

}  // namespace
}  // namespace lenslab
