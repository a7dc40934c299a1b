#pragma once
// The error-against-run-time report: how fast each method converges to the ray-cast truth.
//   reference   the ray caster at high spp (cached by a hash of scene, camera and options)
//   raster      accumulation of aperture views, each pattern, N = 1, 2, 4, … (lecture17: 17)
//   raycast     the ray caster at 1, 2, 4, … spp
//   postprocess a single-pass gather depth of field from the pinhole colour and depth (baseline)
//   adaptive    per-tile budgets to each target PSNR (plan/TileBudget.h), pre-pass included in
//               its time; its rows also give the estimate beside the truth
// The series can be chosen (SweepOptions::series); the equal-error tables give each series' time
// to reach 30/35/40/45 dB, interpolated between its rows, and side by side the fastest uniform
// pattern, the default pattern, per-tile budgets and the ray caster, with the per-tile budgets'
// speed-up over the fastest uniform pattern.
// Every image is compared with the reference: RMSE, PSNR, max error, and the RMSE over occlusion
// edges (pixels within their circle of confusion of a depth discontinuity).
// Timing: GPU work finished (glFinish) and read back, the median of three runs for raster and
// post-process frames (one run for the ray caster); context creation is measured apart by the
// caller and reported in sweep.md; shader compilation happens before the rows (a warm-up frame).
#include "camera/Camera.h"
#include "lens/LensCamera.h"
#include "camera/ImageSize.h"
#include "core/Image.h"
#include "scene/Scene.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace lenslab {

class OutputSet;

std::vector<std::string> sweepSeriesNames();

struct SweepOptions {
  int referenceSpp = 1024;
  int maxViews = 256;                 // raster budgets 1, 2, 4, … up to this
  int maxSpp = 64;                    // ray-cast budgets 1, 2, 4, … up to this
  std::vector<int> gatherTaps = {8, 32, 128};
  std::vector<double> targetsDb = {25.0, 30.0, 35.0, 40.0, 45.0};  // the adaptive method's
  // Which series run: lecture17, concentric, r2, random, sobol, adaptive, raycast, postprocess.
  std::vector<std::string> series = sweepSeriesNames();
  std::uint32_t seed = 1;
  // sweep --lens: the reference and the ray-cast series trace this real lens exactly
  // (lens/LensCamera.h); the camera swept is the thin lens fitted to it, and each of
  // `lensAblations` (that camera with one effect left out, named) is rendered once at maxViews
  // views (sobol): what each fitted effect is worth against the truth. `lensKey` (the lens
  // file's text and settings) goes into the reference's key.
  const LensCamera* exactLens = nullptr;
  std::string lensKey;
  std::vector<std::pair<std::string, Camera>> lensAblations;
  std::filesystem::path outDir;       // empty: write nothing
  OutputSet* outputs = nullptr;       // with outDir: its files go into this set (io/AtomicFile.h),
                                      // to appear with the report when the caller commits it
  std::function<void(const std::string&)> log;  // a line as each series ends
  // How far it is: `unit` is "reference rows" (both halves of the reference), then "images".
  std::function<void(const std::string& unit, std::int64_t done, std::int64_t total)> progress;
};

struct SweepRow {
  std::string method;   // raster, raycast, postprocess
  std::string pattern;  // aperture pattern, "stratified" for raycast, "gather" for postprocess
  int samples = 0;      // views, spp, taps
  double seconds = 0.0;
  double rmse = 0.0;
  double psnr = 0.0;
  double maxError = 0.0;
  double edgeRmse = 0.0;
  double targetPsnr = 0.0;    // adaptive: the target asked for
  double estimatePsnr = 0.0;  // adaptive: what its estimate said when it stopped
  int maxTileSamples = 0;     // adaptive: samples of the busiest tile (`samples` is the mean, rounded)
  double meanSamples = 0.0;   // adaptive: samples per pixel
  std::string image = {};     // its file in outDir/images (sweepImageName), empty when none was written
};

// A row's image file name: method, pattern and the row's own parameter — views, spp or taps, and
// for adaptive the target ("adaptive-sobol-40dB.png"), since two targets can end at the same
// mean sample count.
std::string sweepImageName(const SweepRow& row);
// The name sweepImageName gives the adaptive series' image for a target ("adaptive-sobol-40dB.png").
// Targets are told apart to 10 significant digits, so that a caller can refuse two that share a
// name before any work.
std::string sweepAdaptiveImageName(double targetPsnrDb);

struct SweepResult {
  std::vector<SweepRow> rows;
  double referenceSeconds = 0.0;  // 0 when it came from the cache
  bool referenceCached = false;
  double referenceNoiseRmse = 0.0;  // the reference's RMSE against its own converged limit (from its two halves)
  double setupSeconds = 0.0;      // scene upload, shader compilation and a warm-up frame (not in rows)
  double edgeFraction = 0.0;      // share of pixels in the occlusion-edge mask
};

// Needs a current GL context (the caller creates it and times it). Throws InputError for a
// pinhole camera: there is no depth of field to converge to.
SweepResult runSweep(const Scene& scene, const Camera& camera, ImageSize size, const SweepOptions& options);

// The key a cached ray-cast reference is stored under: a hash of everything the reference
// depends on (geometry, materials, textures, lights, the environment's maps, intensity and
// rotation, camera, size, samples), so that a cached
// reference is never reused for another scene.
std::string referenceKey(const Scene& scene, const Camera& camera, ImageSize size, const SweepOptions& options);

// Pixels near a depth discontinuity lying within the local circle of confusion (radius capped at
// 32 px), from a pinhole depth map in world units (rows from the top).
std::vector<bool> occlusionEdgeMask(const Camera& camera, ImageSize size, const std::vector<double>& depth);

double maskedRmse(const Image& a, const Image& b, const std::vector<bool>& mask);

// Seconds a series takes to reach `psnrDb`: interpolated between the last row below and the first
// at or above it, linearly in PSNR against log time; negative where no row reaches it.
double secondsToReach(const std::vector<const SweepRow*>& rows, double psnrDb);

// sweep.md: the rows' summary, the equal-error table (time to reach 30 / 35 / 40 / 45 dB) and the
// convergence slope of each series (d log RMSE / d log samples).
std::string sweepMarkdown(const SweepResult& result, const std::string& header);
std::string sweepCsv(const SweepResult& result);

}  // namespace lenslab
