#pragma once
// A sweep's rows and the report written from them: sweep.md (the time to reach each PSNR, the
// equal-error table, the estimate against the truth, the fitted lens effect by effect, every row)
// and sweep.csv. No GL and no ray casting: rows in, text out.
#include <string>
#include <vector>

namespace lenslab {

// The adaptive series' aperture pattern: its rows' pattern and its images' names.
inline constexpr const char* kAdaptivePattern = "sobol";

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
  double setupSeconds = 0.0;        // scene upload, shader compilation and a warm-up frame (not in rows)
  double edgeFraction = 0.0;        // share of pixels in the occlusion-edge mask
};

// Seconds a series takes to reach `psnrDb`: interpolated between the last row below and the first
// at or above it, linearly in PSNR against log time; negative where no row reaches it.
double secondsToReach(const std::vector<const SweepRow*>& rows, double psnrDb);

// sweep.md: the rows' summary, the equal-error table (time to reach 30 / 35 / 40 / 45 dB) and the
// convergence slope of each series (d log RMSE / d log samples).
std::string sweepMarkdown(const SweepResult& result, const std::string& header);
std::string sweepCsv(const SweepResult& result);

}  // namespace lenslab
