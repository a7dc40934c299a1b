#include "report/SweepReport.h"

#include "core/Text.h"
#include "lens/AperturePattern.h"
#include "plan/FramePlan.h"
#include "plan/TileBudget.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

namespace lenslab {

namespace {

constexpr std::array<double, 4> kLevels = {30.0, 35.0, 40.0, 45.0};

// The rows grouped by series ("method pattern"), the series in the order they first ran.
struct Series {
  std::map<std::string, std::vector<const SweepRow*>> rows;
  std::vector<std::string> order;

  explicit Series(const SweepResult& r) {
    for (const SweepRow& row : r.rows) {
      const std::string key = row.method + " " + row.pattern;
      if (!rows.count(key)) order.push_back(key);
      rows[key].push_back(&row);
    }
  }
  bool has(const std::string& key) const { return rows.count(key) > 0; }
  double timeOf(const std::string& key, double target) const {
    return has(key) ? secondsToReach(rows.at(key), target) : -1.0;
  }
};

// Least-squares slope of log RMSE against log samples (N = 1 included).
double convergenceSlope(const std::vector<const SweepRow*>& rows) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const SweepRow* row : rows) {
    const double x = std::log(static_cast<double>(row->samples)), y = std::log(row->rmse);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double n = static_cast<double>(rows.size());
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

void writeTimeToReach(std::ostream& s, const Series& series) {
  s << "## Time to reach a PSNR\n\nSeconds, interpolated between the series' last row below the PSNR and its first row "
       "at or above it (PSNR linear in log time); — where no row reaches it. PSNR against the reference.\n\n";
  s << "| method | 30 dB | 35 dB | 40 dB | 45 dB | best PSNR | edge RMSE at best | slope d log RMSE / d log N "
       "|\n|---|---|---|---|---|---|---|---|\n";
  for (const std::string& key : series.order) {
    const auto& rows = series.rows.at(key);
    s << "| " << key << " |";
    for (const double target : kLevels) {
      const double t = secondsToReach(rows, target);
      if (t < 0.0)
        s << " — |";
      else
        s << " " << std::setprecision(4) << t << " |";
    }
    const SweepRow* top = rows.front();
    for (const SweepRow* row : rows)
      if (row->psnr > top->psnr) top = row;
    s << " " << std::setprecision(1) << top->psnr << " dB (" << top->samples << ") | " << std::setprecision(4)
      << top->edgeRmse << " |";
    if (rows.size() >= 3 && rows.front()->method != "adaptive")
      s << " " << std::setprecision(2) << convergenceSlope(rows) << " |\n";
    else
      s << " — |\n";
  }
}

std::string secondsCell(double seconds) {
  std::ostringstream c;
  c.setf(std::ios::fixed);
  if (seconds < 0.0)
    c << "—";
  else
    c << std::setprecision(4) << seconds;
  return c.str();
}

// The equal-error table: at each PSNR, the fastest uniform pattern (named), the default pattern,
// the per-tile method and the ray caster, and the per-tile method's speed-up over the fastest
// uniform pattern — "faster" is against the best alternative, not the default.
void writeEqualError(std::ostream& s, const Series& series) {
  const std::string defaultKey = std::string("raster ") + patternName(PlanOptions{}.pattern);
  std::string adaptiveKey;
  bool anyRaster = false;
  for (const std::string& key : series.order) {
    if (key.rfind("adaptive ", 0) == 0) adaptiveKey = key;
    anyRaster |= key.rfind("raster ", 0) == 0;
  }
  if (!anyRaster || (adaptiveKey.empty() && !series.has("raycast stratified"))) return;
  s << "\n## Equal error: seconds to each PSNR, side by side\n\nThe fastest uniform raster pattern at each PSNR "
       "(named), "
       "the default pattern (`"
    << defaultKey.substr(7)
    << "`), per-tile budgets and the ray caster, each interpolated as above; "
       "the speed-up is the fastest uniform pattern's time over the per-tile budgets' time.\n\n"
       "| PSNR | fastest uniform (s) | default `"
    << defaultKey.substr(7)
    << "` (s) | per-tile budgets (s) | ray cast (s) | per-tile speed-up |\n"
       "|---|---|---|---|---|---|\n";
  for (const double target : kLevels) {
    std::string bestKey;
    double best = -1.0;
    for (const std::string& key : series.order) {
      if (key.rfind("raster ", 0) != 0) continue;
      const double t = series.timeOf(key, target);
      if (t >= 0.0 && (best < 0.0 || t < best)) best = t, bestKey = key;
    }
    const double adaptive = adaptiveKey.empty() ? -1.0 : series.timeOf(adaptiveKey, target);
    s << "| " << std::setprecision(0) << target << " dB | " << secondsCell(best);
    if (best >= 0.0) s << " (" << bestKey.substr(7) << ")";
    s << " | " << secondsCell(series.timeOf(defaultKey, target)) << " | " << secondsCell(adaptive) << " | "
      << secondsCell(series.timeOf("raycast stratified", target)) << " | ";
    if (best < 0.0 || adaptive < 0.0)
      s << "— |\n";
    else
      s << std::setprecision(2) << best / adaptive << "x |\n";
  }
}

void writeEstimate(std::ostream& s, const Series& series, double referenceNoiseRmse) {
  if (!series.has("adaptive sobol")) return;
  const double referenceMse = referenceNoiseRmse * referenceNoiseRmse;
  s << "\n## The estimate against the truth\n\nEach adaptive frame's own estimate (against its converged limit, from "
       "its two sample streams) beside its PSNR against the reference, and against the reference less the "
       "reference's own noise (its MSE, from its two halves, subtracted).\n\n"
       "| target | estimate | PSNR vs reference | less the reference's noise | estimate − truth | samples per pixel "
       "(busiest tile) |\n"
       "|---|---|---|---|---|---|\n";
  for (const SweepRow* row : series.rows.at("adaptive sobol")) {
    const double corrected = psnrFromMse(std::max(row->rmse * row->rmse - referenceMse, 1e-30));
    s << "| " << std::setprecision(1) << row->targetPsnr << " dB | " << std::setprecision(2) << row->estimatePsnr
      << " dB | " << row->psnr << " dB | " << corrected << " dB | " << std::showpos << row->estimatePsnr - corrected
      << std::noshowpos << " dB | " << std::setprecision(1) << row->meanSamples << " (" << row->maxTileSamples
      << ") |\n";
  }
}

// sweep --lens: the fit with everything against the fit with each effect left out, at the
// largest raster budget, both against the exact lens.
void writeLensEffects(std::ostream& s, const SweepResult& r) {
  const SweepRow* full = nullptr;
  std::vector<const SweepRow*> without;
  for (const SweepRow& row : r.rows)
    if (row.method == "fitted-without") without.push_back(&row);
  for (const SweepRow& row : r.rows)
    if (!without.empty() && row.method == "raster" && row.pattern == "sobol" && row.samples == without.front()->samples)
      full = &row;
  if (!full) return;
  s << "\n## The fitted lens, effect by effect\n\nThe real-time camera fitted to the lens, against the lens traced "
       "exactly, "
       "with all its effects and with each left out in turn ("
    << full->samples
    << " views, sobol): the drop is what the fitted "
       "effect buys.\n\n| fitted camera | PSNR (dB) | RMSE | drop (dB) |\n|---|---|---|---|\n";
  s << "| all effects | " << std::setprecision(2) << full->psnr << " | " << std::setprecision(5) << full->rmse
    << " | — |\n";
  for (const SweepRow* row : without)
    s << "| without " << row->pattern << " | " << std::setprecision(2) << row->psnr << " | " << std::setprecision(5)
      << row->rmse << " | " << std::setprecision(2) << full->psnr - row->psnr << " |\n";
}

void writeAllRows(std::ostream& s, const SweepResult& r) {
  s << "\n## All rows\n\n| method | pattern | samples | seconds | RMSE | PSNR (dB) | max error | edge RMSE "
       "|\n|---|---|---|---|---|---|---|---|\n";
  for (const SweepRow& row : r.rows)
    s << "| " << row.method << " | " << row.pattern << " | " << row.samples << " | " << std::setprecision(4)
      << row.seconds << " | " << std::setprecision(5) << row.rmse << " | " << std::setprecision(2) << row.psnr << " | "
      << std::setprecision(4) << row.maxError << " | " << std::setprecision(5) << row.edgeRmse << " |\n";
}

}  // namespace

std::string sweepImageName(const SweepRow& row) {
  if (row.method == "adaptive") return cat(row.method, "-", row.pattern, "-", row.targetPsnr, "dB.png");
  return cat(row.method, "-", row.pattern, "-", row.samples, ".png");
}

std::string sweepAdaptiveImageName(double targetPsnrDb) {
  SweepRow row;
  row.method = "adaptive";
  row.pattern = kAdaptivePattern;
  row.targetPsnr = targetPsnrDb;
  return sweepImageName(row);
}

double secondsToReach(const std::vector<const SweepRow*>& rows, double psnrDb) {
  // In the order run (rising budgets): the first row at or above the target, and the one before.
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i]->psnr < psnrDb) continue;
    if (i == 0 || rows[i - 1]->psnr >= rows[i]->psnr || rows[i - 1]->seconds <= 0.0) return rows[i]->seconds;
    const SweepRow& a = *rows[i - 1];
    const SweepRow& b = *rows[i];
    const double f = (psnrDb - a.psnr) / (b.psnr - a.psnr);
    return std::exp(std::log(a.seconds) + f * (std::log(b.seconds) - std::log(a.seconds)));
  }
  return -1.0;
}

std::string sweepCsv(const SweepResult& r) {
  std::ostringstream s;
  s.precision(8);
  s << "method,pattern,samples,seconds,rmse,psnr,max_error,edge_rmse,target_psnr,estimate_psnr,mean_samples,max_tile_"
       "samples\n";
  for (const SweepRow& row : r.rows)
    s << row.method << "," << row.pattern << "," << row.samples << "," << row.seconds << "," << row.rmse << ","
      << row.psnr << "," << row.maxError << "," << row.edgeRmse << "," << row.targetPsnr << "," << row.estimatePsnr
      << "," << row.meanSamples << "," << row.maxTileSamples << "\n";
  return s.str();
}

std::string sweepMarkdown(const SweepResult& r, const std::string& header) {
  const Series series(r);
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s << header << "\n";
  writeTimeToReach(s, series);
  writeEqualError(s, series);
  writeEstimate(s, series, r.referenceNoiseRmse);
  if (!series.rows.empty()) writeLensEffects(s, r);
  writeAllRows(s, r);
  return s.str();
}

}  // namespace lenslab
