#pragma once
// A logarithmic plot axis fitted to its data: the range the data span with a margin (not widened
// to whole decades), and ticks a reader can take in at a glance. Pure: no drawing.
#include <string>
#include <vector>

namespace lenslab {

// An axis's ends, as values (not logarithms): 0 < lo < hi.
struct LogRange {
  double lo = 0.0;
  double hi = 0.0;
};

// The range of data in [minValue, maxValue] (0 < minValue <= maxValue): at least 0.6 of a decade
// (a factor of 4, centred on the data), then 6 % of its span added at each end in log space.
LogRange fittedLogRange(double minValue, double maxValue);

struct AxisTick {
  double value = 0.0;
  std::string label;  // "0.05", "20", "2e-5": plain for 0.0001 to 9000, mantissa and exponent beyond
};

// Ticks inside the range: every decade when it spans more than 2.5 decades (every second, third,
// ... decade past nine decades, so that ten at most are labelled), 1-2-5 in each decade when it
// spans more than 0.8, and every mantissa 1 to 9 for a narrower one, so that a fitted range has
// at least two.
std::vector<AxisTick> logTicks(LogRange range);

}  // namespace lenslab
