#pragma once
// The error-against-run-time sweep: how fast each method converges to the ray-cast truth.
//   reference   the ray caster at high spp (cached by a hash of its inputs: report/ReferenceCache.h)
//   raster      accumulation of aperture views, each pattern, N = 1, 2, 4, … (lecture17: 17)
//   cells       sobol views each spread over its cell of the aperture (the cell filter), N = 1, 2, 4, …
//   raycast     the ray caster at 1, 2, 4, … spp
//   postprocess a single-pass gather depth of field from the pinhole colour and depth (baseline)
//   adaptive    per-tile budgets to each target PSNR (plan/TileBudget.h), pre-pass included in
//               its time; its rows also give the estimate beside the truth
// The series can be chosen (SweepOptions::series). Its rows and the report written from them
// (sweep.md, sweep.csv) are in report/SweepReport.h.
// Every image is compared with the reference: RMSE, PSNR, max error, and the RMSE over occlusion
// edges (pixels within their circle of confusion of a depth discontinuity).
// Timing: GPU work finished (glFinish) and read back, the median of three runs for raster and
// post-process frames (one run for the ray caster); context creation is measured apart by the
// caller and reported in sweep.md; shader compilation happens before the rows (a warm-up frame).
#include "camera/Camera.h"
#include "camera/ImageMap.h"
#include "camera/ImageSize.h"
#include "core/Image.h"
#include "report/SweepReport.h"
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
  int maxViews = 256;  // raster budgets 1, 2, 4, … up to this
  int maxSpp = 64;     // ray-cast budgets 1, 2, 4, … up to this
  std::vector<int> gatherTaps = {8, 32, 128};
  std::vector<double> targetsDb = {25.0, 30.0, 35.0, 40.0, 45.0};  // the adaptive method's
  // Which series run: lecture17, concentric, r2, random, sobol, cells, adaptive, raycast, postprocess.
  std::vector<std::string> series = sweepSeriesNames();
  std::uint32_t seed = 1;
  // sweep --lens: the frame's real-lens map (camera/ImageMap.h), at the sweep's size. The reference
  // and the ray-cast series trace it exactly; the camera swept is its fitted() thin lens, and each
  // of `lensAblations` (that camera with one effect left out, named) is rendered once at maxViews
  // views (sobol): what each fitted effect is worth against the truth.
  const RealLensMap* exactLens = nullptr;
  // What the reference is computed from beyond the scene's own files (Scene::files) and the
  // camera: the camera file, the environment image, the lens file; and the options that change
  // it, as text ("background 0 0 0"). The cache key hashes the files' bytes and these
  // (report/ReferenceCache.h); a new option that changes the reference must be added here.
  std::vector<std::filesystem::path> inputFiles;
  std::vector<std::string> inputOptions;
  std::vector<std::pair<std::string, Camera>> lensAblations;
  std::filesystem::path outDir;                 // empty: write nothing
  OutputSet* outputs = nullptr;                 // with outDir: its files go into this set (io/AtomicFile.h),
                                                // to appear with the report when the caller commits it
  std::function<void(const std::string&)> log;  // a line as each series ends
  // How far it is: `unit` is "reference rows" (both halves of the reference), then "images".
  std::function<void(const std::string& unit, std::int64_t done, std::int64_t total)> progress;
};

// Needs a current GL context (the caller creates it and times it). Throws InputError for a
// pinhole camera: there is no depth of field to converge to.
SweepResult runSweep(const Scene& scene, const Camera& camera, ImageSize size, const SweepOptions& options);

// Pixels near a depth discontinuity lying within the local circle of confusion (radius capped at
// 32 px), from a pinhole depth map in world units (rows from the top).
std::vector<bool> occlusionEdgeMask(const Camera& camera, ImageSize size, const std::vector<double>& depth);

double maskedRmse(const Image& a, const Image& b, const std::vector<bool>& mask);

}  // namespace lenslab
