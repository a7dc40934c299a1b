#include "camera/Metering.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

double luminance(double r, double g, double b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }

bool inCentreCircle(int x, int y, int width, int height) {
  const double radius = 0.5 * kCentreCircleDiameter * std::min(width, height);
  const double dx = x + 0.5 - 0.5 * width, dy = y + 0.5 - 0.5 * height;
  return dx * dx + dy * dy <= radius * radius;
}

double ev100ForMeteredLuminance(double averageLuminance) {
  return std::log2(averageLuminance * 100.0 / kReflectedMeterK);
}

namespace {

double pixelLuminance(const Image& image, int x, int y) {
  const float* p = &image.rgba[image.offset(x, y)];
  return luminance(p[0], p[1], p[2]);
}

// The frame's plain average luminance over its finite pixels: the floor's reference.
double plainAverage(const Image& image) {
  double sum = 0.0;
  std::int64_t count = 0;
  for (int y = 0; y < image.height; ++y) {
    double row = 0.0;  // summed by rows: a row's sum is small beside the frame's
    for (int x = 0; x < image.width; ++x)
      if (const double v = pixelLuminance(image, x, y); std::isfinite(v)) row += v, ++count;
    sum += row;
  }
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

// A product of many positive factors as mantissa × 2^exponent, which neither overflows nor
// underflows: the log of a geometric mean, with one log2 at the end instead of one a pixel.
struct LogProduct {
  double mantissa = 1.0;
  std::int64_t exponent = 0;
  std::int64_t count = 0;

  void multiply(double factor) {
    mantissa *= factor;
    // Renormalised every 4 factors: each is under 2^130 (a float's range) and over 2^-150, so
    // the mantissa stays within a double's normal range in between.
    if (++count % 4 == 0) normalise();
  }
  void normalise() {
    int e = 0;
    mantissa = std::frexp(mantissa, &e);
    exponent += e;
  }
  // mean(log2 factor).
  double meanLog2() {
    normalise();
    return (std::log2(mantissa) + static_cast<double>(exponent)) / static_cast<double>(count);
  }
};

}  // namespace

MeterReading meterFrame(const Image& image) {
  MeterReading reading;
  const double average = plainAverage(image);
  if (!(average > 0.0) || !std::isfinite(average)) return reading;
  const double floor = average * std::exp2(-kMeterFloorStops);
  LogProduct centre, rest;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const double v = pixelLuminance(image, x, y);
      if (!std::isfinite(v) || v < floor) continue;
      (inCentreCircle(x, y, image.width, image.height) ? centre : rest).multiply(v);
    }
  reading.pixels = centre.count + rest.count;
  if (reading.pixels == 0) return reading;
  // A region with no pixel left leaves the reading to the other.
  const double logL = centre.count == 0 ? rest.meanLog2()
                      : rest.count == 0
                          ? centre.meanLog2()
                          : kCentreCircleWeight * centre.meanLog2() + (1.0 - kCentreCircleWeight) * rest.meanLog2();
  reading.luminance = std::exp2(logL);
  reading.ev100 = logL + std::log2(100.0 / kReflectedMeterK);  // ev100ForMeteredLuminance, without exp2's round trip
  return reading;
}

}  // namespace lenslab
