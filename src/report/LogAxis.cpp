#include "report/LogAxis.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace lenslab {
namespace {

// m · 10^e written out: "2000", "0.0005" for exponents -4 to 3, "2e-5" and "5e4" beyond.
std::string tickLabel(int mantissa, int exponent) {
  const std::string m = std::to_string(mantissa);
  if (exponent >= 0 && exponent <= 3) return m + std::string(exponent, '0');
  if (exponent < 0 && exponent >= -4) return "0." + std::string(-exponent - 1, '0') + m;
  return m + "e" + std::to_string(exponent);
}

}  // namespace

LogRange fittedLogRange(double minValue, double maxValue) {
  assert(minValue > 0.0 && minValue <= maxValue);
  double lo = std::log10(minValue), hi = std::log10(maxValue);
  const double minSpan = std::log10(4.0);
  if (hi - lo < minSpan) {
    const double centre = 0.5 * (lo + hi);
    lo = centre - 0.5 * minSpan;
    hi = centre + 0.5 * minSpan;
  }
  const double margin = 0.06 * (hi - lo);
  return {std::pow(10.0, lo - margin), std::pow(10.0, hi + margin)};
}

std::vector<AxisTick> logTicks(LogRange range) {
  assert(range.lo > 0.0 && range.lo < range.hi);
  const double decades = std::log10(range.hi / range.lo);
  const std::vector<int> mantissas = decades > 2.5   ? std::vector<int>{1}
                                     : decades > 0.8 ? std::vector<int>{1, 2, 5}
                                                     : std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9};
  const int e0 = static_cast<int>(std::floor(std::log10(range.lo)));
  const int e1 = static_cast<int>(std::ceil(std::log10(range.hi)));
  // A wide range's decades thinned to nine labels at most, keeping multiples of the stride.
  const int stride = mantissas.size() == 1 ? std::max(1, (e1 - e0 + 8) / 9) : 1;
  std::vector<AxisTick> ticks;
  for (int e = e0; e <= e1; ++e) {
    if (e % stride != 0) continue;
    for (int m : mantissas) {
      const double value = m * std::pow(10.0, e);
      // A tick a rounding error outside the range is still its end's tick.
      if (value >= range.lo * (1.0 - 1e-9) && value <= range.hi * (1.0 + 1e-9))
        ticks.push_back({value, tickLabel(m, e)});
    }
  }
  return ticks;
}

}  // namespace lenslab
