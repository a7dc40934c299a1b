#include "lens/AperturePattern.h"

#include "lens/ApertureCells.h"
#include "lens/SobolSequence.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>

namespace lenslab {

namespace {

// The one list of the patterns' names: the command line, the panel and the reports read it.
constexpr std::array<std::pair<AperturePattern, const char*>, 6> kNames{{
    {AperturePattern::Lecture17, "lecture17"},
    {AperturePattern::Concentric, "concentric"},
    {AperturePattern::R2, "r2"},
    {AperturePattern::Random, "random"},
    {AperturePattern::Sobol, "sobol"},
    {AperturePattern::Rings, "rings"},
}};

}  // namespace

const char* patternName(AperturePattern p) {
  for (const auto& [pattern, name] : kNames)
    if (pattern == p) return name;
  return "?";
}

std::optional<AperturePattern> patternFromName(const std::string& name) {
  for (const auto& [pattern, text] : kNames)
    if (name == text) return pattern;
  return std::nullopt;
}

std::vector<std::string> patternNameList() {
  std::vector<std::string> names;
  for (const auto& entry : kNames) names.emplace_back(entry.second);
  return names;
}

std::string patternNames() {
  std::string joined;
  for (const auto& entry : kNames) joined += (joined.empty() ? "" : ", ") + std::string(entry.second);
  return joined;
}

glm::dvec2 concentricDisk(glm::dvec2 u) {
  const glm::dvec2 offset = 2.0 * u - 1.0;
  if (offset.x == 0.0 && offset.y == 0.0) return {0.0, 0.0};
  constexpr double kQuarterPi = std::numbers::pi / 4.0;
  double r, theta;
  if (std::abs(offset.x) > std::abs(offset.y)) {
    r = offset.x;
    theta = kQuarterPi * (offset.y / offset.x);
  } else {
    r = offset.y;
    theta = 2.0 * kQuarterPi - kQuarterPi * (offset.x / offset.y);
  }
  return r * glm::dvec2(std::cos(theta), std::sin(theta));
}

glm::dvec2 concentricSquare(glm::dvec2 disk) {
  constexpr double kQuarterPi = std::numbers::pi / 4.0;
  const double r = glm::length(disk);
  const double phi = std::atan2(disk.y, disk.x);
  glm::dvec2 offset;
  // The four triangles of the square, each a quarter turn of the disk: r along the axis it faces,
  // the angle from that axis along the other (concentricDisk's two branches, solved for a and b).
  if (std::abs(phi) <= kQuarterPi) {
    offset = {r, r * phi / kQuarterPi};
  } else if (std::abs(phi) >= 3.0 * kQuarterPi) {
    const double theta = phi > 0.0 ? phi - std::numbers::pi : phi + std::numbers::pi;
    offset = {-r, -r * theta / kQuarterPi};
  } else if (phi > 0.0) {
    offset = {r * (2.0 * kQuarterPi - phi) / kQuarterPi, r};
  } else {
    const double theta = phi + std::numbers::pi;
    offset = {-r * (2.0 * kQuarterPi - theta) / kQuarterPi, -r};
  }
  return 0.5 * (offset + 1.0);
}

namespace {

double fract(double x) { return x - std::floor(x); }

std::vector<LensSample> lecture17(std::uint32_t seed) {
  std::vector<LensSample> samples;
  samples.push_back({{0.0, 0.0}, {0.0, 0.0}});
  for (double radius : {0.5, 1.0})
    for (int k = 0; k < 8; ++k) {
      const double angle = k * std::numbers::pi / 4.0;
      samples.push_back({radius * glm::dvec2(std::cos(angle), std::sin(angle)), {0.0, 0.0}});
    }
  // Sub-pixel offsets from the R2 sequence (two dimensions), so the 17 views also anti-alias.
  constexpr double g = 1.32471795724474602596;  // the plastic number: x³ = x + 1
  std::mt19937 rng(seed);
  const double offset = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double n = static_cast<double>(i + 1);
    samples[i].pixel = {fract(offset + n / g) - 0.5, fract(offset + n / (g * g)) - 0.5};
  }
  return samples;
}

std::vector<LensSample> concentric(int count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(0.0, 1.0);
  // The smallest grid of at least `count` strata; when count is not a product, a random subset
  // of the strata is used (each still jittered within its cell).
  const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
  const int rows = (count + columns - 1) / columns;
  std::vector<int> cells(static_cast<std::size_t>(columns * rows));
  for (std::size_t i = 0; i < cells.size(); ++i) cells[i] = static_cast<int>(i);
  std::shuffle(cells.begin(), cells.end(), rng);
  cells.resize(static_cast<std::size_t>(count));
  std::sort(cells.begin(), cells.end());
  // Pixel offsets: an independently shuffled stratification of the pixel square (as pbrt's
  // stratified sampler pairs dimensions), so lens and pixel positions are not correlated.
  std::vector<int> pixelCells = cells;
  std::shuffle(pixelCells.begin(), pixelCells.end(), rng);
  std::vector<LensSample> samples;
  for (int i = 0; i < count; ++i) {
    const int c = cells[static_cast<std::size_t>(i)];
    const glm::dvec2 u((c % columns + jitter(rng)) / columns, (c / columns + jitter(rng)) / rows);
    const int p = pixelCells[static_cast<std::size_t>(i)];
    const glm::dvec2 px((p % columns + jitter(rng)) / columns, (p / columns + jitter(rng)) / rows);
    samples.push_back({concentricDisk(u), px - 0.5});
  }
  return samples;
}

std::vector<LensSample> r2(int count, std::uint32_t seed) {
  // Roberts' R-sequence in d = 4 dimensions: g is the root of x^5 = x + 1; alpha_i = 1 / g^(i+1).
  constexpr double g = 1.1673039782614187;
  const double alpha[4] = {1.0 / g, 1.0 / (g * g), 1.0 / (g * g * g), 1.0 / (g * g * g * g)};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> start(0.0, 1.0);
  const double offset[4] = {start(rng), start(rng), start(rng), start(rng)};
  std::vector<LensSample> samples;
  for (int i = 0; i < count; ++i) {
    const double n = static_cast<double>(i + 1);
    double x[4];
    for (int d = 0; d < 4; ++d) x[d] = fract(offset[d] + n * alpha[d]);
    samples.push_back({concentricDisk({x[0], x[1]}), {x[2] - 0.5, x[3] - 0.5}});
  }
  return samples;
}

std::vector<LensSample> random(int count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<LensSample> samples;
  for (int i = 0; i < count; ++i) {
    const glm::dvec2 lens = concentricDisk({u(rng), u(rng)});
    samples.push_back({lens, {u(rng) - 0.5, u(rng) - 0.5}});
  }
  return samples;
}

}  // namespace

std::vector<LensSample> makeApertureSamples(AperturePattern pattern, int count, std::uint32_t seed) {
  count = std::max(count, 1);
  switch (pattern) {
    case AperturePattern::Lecture17: return lecture17(seed);
    case AperturePattern::Concentric: return concentric(count, seed);
    case AperturePattern::R2: return r2(count, seed);
    case AperturePattern::Random: return random(count, seed);
    case AperturePattern::Rings: return makeCellSamples(AperturePattern::Rings, count, seed).samples;
    case AperturePattern::Sobol: {
      // One stream: the N points are one 4-D net (per-tile budgets use sobolSample's two streams).
      std::vector<LensSample> samples;
      const std::uint32_t scramble = sobolStreamSeed(seed, 0);
      for (int i = 0; i < count; ++i) samples.push_back(sobolPoint(static_cast<std::uint32_t>(i), scramble));
      return samples;
    }
  }
  return {};
}

}  // namespace lenslab
