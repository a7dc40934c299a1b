// The error-against-run-time sweep on the bundled occluder: accumulation converges, and the
// post-process baseline fails where the lecture's partial obscuration matters (occlusion edges).
#include "../common/temp_dir_test.h"
#include "core/Error.h"
#include "../common/gl_test_context.h"
#include "io/AtomicFile.h"
#include "io/CameraJson.h"
#include "lens/AperturePattern.h"
#include "plan/FramePlan.h"
#include "report/Sweep.h"
#include "scene/GltfLoader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <utility>
#include <vector>

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
  for (int taps : {32, 128})
    EXPECT_GT(row(r, "postprocess", "gather", taps).edgeRmse, 1.5 * accumulated) << taps << " taps";
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
            {"raster", "concentric", 4, 0.04, 0.008, 41.9, 0.2, 0.02},
            {"adaptive", "sobol", 3, 0.007, 0.028, 31.0, 0.3, 0.04, 30.0, 31.2, 4, 3.0},
            {"adaptive", "sobol", 9, 0.015, 0.0094, 40.5, 0.1, 0.02, 40.0, 40.1, 16, 9.0}};
  const std::string md = sweepMarkdown(r, "# test");
  // Interpolated in log time between the rows around each PSNR: 30 dB lies halfway from 26 to 34
  // (0.01·√2 s), 35 and 40 dB between 34 and 41.9; 45 dB is not reached.
  EXPECT_NE(md.find("| raster concentric | 0.0141 | 0.0218 | 0.0339 | — |"), std::string::npos) << md;
  // The speed-up: 0.0141 / 0.007 (the adaptive series' first row is already above 30 dB), and at
  // 40 dB 0.0339 / 0.0144 (between its rows at 31 and 40.5 dB).
  // The default pattern's column shows its own series (here none, unless the default is concentric).
  const bool concentricIsDefault = std::string(patternName(PlanOptions{}.pattern)) == "concentric";
  const auto defaultCell = [&](const char* concentric, const char* sobol) {
    return std::string(concentricIsDefault                                          ? concentric
                       : patternName(PlanOptions{}.pattern) == std::string("sobol") ? sobol
                                                                                    : "—");
  };
  EXPECT_NE(md.find("| 30 dB | 0.0141 (concentric) | " + defaultCell("0.0141", "—") + " | 0.0070 | — | 2.02x |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| 40 dB | 0.0339 (concentric) | " + defaultCell("0.0339", "—") + " | 0.0144 | — | 2.35x |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| 40.0 dB | 40.10 dB | 40.50 dB |"), std::string::npos) << md;
  // The side-by-side table names the fastest uniform pattern at each PSNR, not the default: here
  // sobol at 30 dB (0.005·√2 s), concentric at 40 dB (sobol's 0.01·8^0.76 s is slower); the ray
  // caster's first row is already at 30 dB.
  r.rows.push_back({"raster", "sobol", 1, 0.005, 0.05, 26.0, 0.5, 0.1});
  r.rows.push_back({"raster", "sobol", 2, 0.01, 0.02, 34.0, 0.4, 0.05});
  r.rows.push_back({"raster", "sobol", 4, 0.08, 0.008, 41.9, 0.2, 0.02});
  r.rows.push_back({"raycast", "stratified", 1, 0.1, 0.03, 30.0, 0.3, 0.05});
  const std::string both = sweepMarkdown(r, "# test");
  EXPECT_NE(both.find("| 30 dB | 0.0071 (sobol) | " + defaultCell("0.0141", "0.0071") + " | 0.0070 | 0.1000 | 1.01x |"),
            std::string::npos)
      << both;
  EXPECT_NE(both.find("| 40 dB | 0.0339 (concentric) | " + defaultCell("0.0339", "0.0485") + " | 0.0144 | — | 2.35x |"),
            std::string::npos)
      << both;
  EXPECT_NE(sweepCsv(r).find("raster,concentric,4,0.04,0.008,41.9,0.2,0.02,0,0,0,0"), std::string::npos);
}

TEST(Sweep, ImagesAreNamedByTheirOwnParameter) {
  SweepRow views{"raster", "concentric", 16, 0.1, 0.01, 40.0, 0.0, 0.0};
  EXPECT_EQ(sweepImageName(views), "raster-concentric-16.png");
  SweepRow spp{"raycast", "stratified", 4, 0.1, 0.01, 40.0, 0.0, 0.0};
  EXPECT_EQ(sweepImageName(spp), "raycast-stratified-4.png");
  // Two adaptive rows with the same mean sample count keep apart by their targets.
  SweepRow a{"adaptive", "sobol", 8, 0.1, 0.01, 40.0, 0.0, 0.0, 25.0},
      b{"adaptive", "sobol", 8, 0.1, 0.01, 40.0, 0.0, 0.0, 32.5};
  EXPECT_EQ(sweepImageName(a), "adaptive-sobol-25dB.png");
  EXPECT_EQ(sweepImageName(b), "adaptive-sobol-32.5dB.png");
}

class SweepFiles : public test::TempDirTest {};

TEST_F(SweepFiles, EveryRowHasItsOwnImage) {
  LENSLAB_REQUIRE_GL();
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / "occluder/occluder.gltf");
  const Camera camera = loadCameraJson(assets / "occluder/camera-dof.json").camera;
  OutputSet outputs;
  SweepOptions options;
  options.referenceSpp = 4;
  options.maxViews = 2;
  options.maxSpp = 1;
  options.gatherTaps = {8};
  // Targets so low and close on an image this small that both stop at the first round: the same
  // mean sample count, which used to name both images alike.
  options.targetsDb = {15.0, 16.0};
  options.series = {"concentric", "adaptive", "raycast", "postprocess"};
  options.outDir = dir_;
  options.outputs = &outputs;
  std::vector<std::pair<std::int64_t, std::int64_t>> progress;
  options.progress = [&](const std::string& unit, std::int64_t done, std::int64_t total) {
    if (unit == "images") progress.emplace_back(done, total);
  };
  const SweepResult r = runSweep(scene, camera, {24, 16}, options);
  outputs.commit();
  std::set<std::string> files;
  for (const auto& entry : fs::directory_iterator(dir_ / "images")) files.insert(entry.path().filename().string());
  ASSERT_EQ(r.rows.size(), 2u + 2u + 1u + 1u);
  EXPECT_EQ(files.size(), r.rows.size());
  for (const SweepRow& row : r.rows) EXPECT_EQ(files.count(row.image), 1u) << row.image;
  ASSERT_EQ(progress.size(), r.rows.size());  // one report an image, of the count it will make
  EXPECT_EQ(progress.back(), std::make_pair(std::int64_t{6}, std::int64_t{6}));
}

TEST(Sweep, SecondsToReachInterpolatesInLogTime) {
  const SweepRow a{"raster", "concentric", 1, 1.0, 0.1, 20.0, 0.0, 0.0},
      b{"raster", "concentric", 2, 4.0, 0.01, 40.0, 0.0, 0.0};
  EXPECT_NEAR(secondsToReach({&a, &b}, 30.0), 2.0, 1e-12);  // halfway in PSNR: the geometric mean of the times
  EXPECT_EQ(secondsToReach({&a, &b}, 20.0), 1.0);
  EXPECT_LT(secondsToReach({&a, &b}, 41.0), 0.0);
}

}  // namespace
}  // namespace lenslab
