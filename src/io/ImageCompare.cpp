#include "io/ImageCompare.h"

#include "io/ImageFile.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace lenslab {

ImageDifference compareImages(const Image& a, const Image& b, double threshold) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("images differ in size: " + std::to_string(a.width) + "x" +
                                std::to_string(a.height) + " vs " + std::to_string(b.width) + "x" +
                                std::to_string(b.height));
  ImageDifference d;
  double sumSquares = 0.0;
  std::size_t over = 0;
  const std::size_t pixels = static_cast<std::size_t>(a.width) * a.height;
  for (std::size_t i = 0; i < pixels; ++i) {
    double pixelMax = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double diff = std::abs(static_cast<double>(a.rgba[i * 4 + k]) - b.rgba[i * 4 + k]);
      sumSquares += diff * diff;
      pixelMax = std::max(pixelMax, diff);
    }
    d.maxAbs = std::max(d.maxAbs, pixelMax);
    if (pixelMax > threshold) ++over;
  }
  const double mse = pixels ? sumSquares / (3.0 * static_cast<double>(pixels)) : 0.0;
  d.rmse = std::sqrt(mse);
  d.psnrDb = mse > 0.0 ? 10.0 * std::log10(1.0 / mse) : std::numeric_limits<double>::infinity();
  d.fractionOver = pixels ? static_cast<double>(over) / static_cast<double>(pixels) : 0.0;
  return d;
}

Image displayEncoded(const Image& linear) {
  Image out(linear.width, linear.height);
  for (std::size_t i = 0; i < linear.rgba.size(); ++i) {
    const float v = i % 4 == 3 ? linear.rgba[i] : srgbFromLinear(linear.rgba[i]);
    out.rgba[i] = std::round(std::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f;
  }
  return out;
}

Image differenceImage(const Image& a, const Image& b, float gain) {
  Image out(a.width, a.height);
  for (std::size_t i = 0; i < out.rgba.size(); ++i)
    out.rgba[i] = i % 4 == 3 ? 1.0f : std::abs(a.rgba[i] - b.rgba[i]) * gain;
  return out;
}

}  // namespace lenslab
