// The error-against-run-time sweep on the bundled occluder: accumulation converges, and the
// post-process baseline fails where the lecture's partial obscuration matters (occlusion edges).
#include "core/Error.h"
#include "gl_test_context.h"
#include "io/CameraJson.h"
#include "report/Sweep.h"
#include "scene/GltfLoader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

const SweepRow& row(const SweepResult& r, const std::string& method, const std::string& pattern, int samples) {
  for (const SweepRow& x : r.rows)
    if (x.method == method && x.pattern == pattern && x.samples == samples) return x;
  throw std::runtime_error("no row " + method + " " + pattern + " " + std::to_string(samples));
}

TEST(Sweep, AccumulationConvergesAndBeatsThePostProcessBaselineAtOcclusionEdges) {
  LENSLAB_REQUIRE_GL();
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / "occluder/occluder.gltf");
  const Camera camera = loadCameraJson(assets / "occluder/camera-dof.json").camera;
  SweepOptions options;
  options.referenceSpp = 256;
  options.maxViews = 64;
  options.maxSpp = 2;
  options.gatherTaps = {32, 128};
  const SweepResult r = runSweep(scene, camera, {192, 128}, options);
  ASSERT_GT(r.edgeFraction, 0.05) << "the fence should give occlusion edges";

  // Error falls as N grows, for the stratified and low-discrepancy patterns (allowing 15 % noise
  // between doublings). N = 1 is the pinhole view and N = 2 two ghost copies, which can be further
  // from the blurred truth than the sharp image; the trend is checked from N = 4 on.
  for (const char* pattern : {"concentric", "r2"}) {
    SCOPED_TRACE(pattern);
    double previous = row(r, "raster", pattern, 4).rmse;
    for (int n = 8; n <= 64; n *= 2) {
      const double rmse = row(r, "raster", pattern, n).rmse;
      EXPECT_LT(rmse, previous * 1.15) << "N = " << n;
      previous = std::min(previous, rmse);
    }
    EXPECT_LT(row(r, "raster", pattern, 64).rmse, 0.4 * row(r, "raster", pattern, 1).rmse);
  }
  // The gather baseline costs about one pinhole frame plus a pass, as 8–16 views do here (see the
  // sweep report for the clock; the test compares budgets, not seconds). It cannot undo what the
  // fence hides, so its error at occlusion edges stays larger than accumulation's at 16 views.
  const double accumulated = row(r, "raster", "concentric", 16).edgeRmse;
  for (int taps : {32, 128}) EXPECT_GT(row(r, "postprocess", "gather", taps).edgeRmse, 1.5 * accumulated) << taps << " taps";
}

TEST(Sweep, RefusesAPinholeCamera) {
  LENSLAB_REQUIRE_GL();
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / "occluder/occluder.gltf");
  const Camera camera = loadCameraJson(assets / "occluder/camera.json").camera;
  EXPECT_THROW(runSweep(scene, camera, {32, 32}, SweepOptions{}), InputError);
}

TEST(Sweep, MarkdownHasTheEqualErrorTable) {
  SweepResult r;
  r.rows = {{"raster", "concentric", 1, 0.01, 0.05, 26.0, 0.5, 0.1},
            {"raster", "concentric", 2, 0.02, 0.02, 34.0, 0.4, 0.05},
            {"raster", "concentric", 4, 0.04, 0.008, 41.9, 0.2, 0.02}};
  const std::string md = sweepMarkdown(r, "# test");
  EXPECT_NE(md.find("| raster concentric | 0.0200 | 0.0400 | 0.0400 |"), std::string::npos) << md;
  EXPECT_NE(sweepCsv(r).find("raster,concentric,4,0.04,0.008,41.9,0.2,0.02"), std::string::npos);
}

}  // namespace
}  // namespace lenslab
