#include "plan/VisibleBlur.h"

#include "camera/LensMap.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace lenslab {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// Running extreme over a window of 2·radius + 1 along one line (van Herk / Gil–Werman: three
// comparisons a sample whatever the radius). `better(a, b)` is true when a should win over b.
template <class Better>
void runningExtreme(const float* in, float* out, int n, int stride, int radius, float identity, Better better,
                    std::vector<float>& forward, std::vector<float>& backward) {
  const int w = 2 * radius + 1;
  const int padded = n + 2 * radius;
  const int blocks = (padded + w - 1) / w;
  const int size = blocks * w;
  forward.assign(static_cast<std::size_t>(size), identity);
  backward.assign(static_cast<std::size_t>(size), identity);
  auto at = [&](int i) {
    const int j = i - radius;
    return (j >= 0 && j < n) ? in[static_cast<std::ptrdiff_t>(j) * stride] : identity;
  };
  for (int i = 0; i < size; ++i) {
    const float v = at(i);
    forward[static_cast<std::size_t>(i)] = (i % w == 0 || better(v, forward[static_cast<std::size_t>(i - 1)]))
                                               ? v
                                               : forward[static_cast<std::size_t>(i - 1)];
  }
  for (int i = size - 1; i >= 0; --i) {
    const float v = at(i);
    backward[static_cast<std::size_t>(i)] = (i % w == w - 1 || better(v, backward[static_cast<std::size_t>(i + 1)]))
                                                ? v
                                                : backward[static_cast<std::size_t>(i + 1)];
  }
  // Output j covers padded [j, j + w − 1]: the backward run from j and the forward run to j + w − 1.
  for (int j = 0; j < n; ++j) {
    const float a = backward[static_cast<std::size_t>(j)], b = forward[static_cast<std::size_t>(j + w - 1)];
    out[static_cast<std::ptrdiff_t>(j) * stride] = better(a, b) ? a : b;
  }
}

// Separable square filter of half-width `radius`.
template <class Better>
std::vector<float> squareExtreme(const std::vector<float>& image, ImageSize size, int radius, float identity,
                                 Better better) {
  std::vector<float> rows(image.size()), out(image.size()), f, b;
  for (int y = 0; y < size.heightPx; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * static_cast<std::size_t>(size.widthPx);
    runningExtreme(&image[row], &rows[row], size.widthPx, 1, radius, identity, better, f, b);
  }
  for (int x = 0; x < size.widthPx; ++x)
    runningExtreme(&rows[static_cast<std::size_t>(x)], &out[static_cast<std::size_t>(x)], size.heightPx, size.widthPx,
                   radius, identity, better, f, b);
  return out;
}

double percentile(std::vector<float> values, double p) {
  if (values.empty()) return 0.0;
  const std::size_t k = std::min(values.size() - 1, static_cast<std::size_t>(p * static_cast<double>(values.size())));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

}  // namespace

ImageSize prepassSizeFor(ImageSize image, int targetWidthPx) {
  const int factor = std::max(1, image.widthPx / std::max(targetWidthPx, 1));
  return {std::max(1, image.widthPx / factor), std::max(1, image.heightPx / factor)};
}

double VisibleBlur::maxOver(int x0, int y0, int x1, int y1) const {
  const double s = imagePxPerPrepassPx;
  // Every pre-pass pixel that overlaps the image rectangle.
  const int px0 = std::clamp(static_cast<int>(std::floor(x0 / s)), 0, prepass.widthPx - 1);
  const int py0 = std::clamp(static_cast<int>(std::floor(y0 / s)), 0, prepass.heightPx - 1);
  const int px1 = std::clamp(static_cast<int>(std::ceil(x1 / s)), px0 + 1, prepass.widthPx);
  const int py1 = std::clamp(static_cast<int>(std::ceil(y1 / s)), py0 + 1, prepass.heightPx);
  float m = 0.0f;
  for (int y = py0; y < py1; ++y)
    for (int x = px0; x < px1; ++x) m = std::max(m, reachingPx[static_cast<std::size_t>(y * prepass.widthPx + x)]);
  return m;
}

VisibleBlur visibleBlur(const Camera& camera, ImageSize image, ImageSize prepass, const std::vector<double>& depth,
                        bool backgroundAtInfinity) {
  if (depth.size() != static_cast<std::size_t>(prepass.pixelCount()))
    throw std::invalid_argument("visibleBlur: the depth map does not match the pre-pass size");
  VisibleBlur blur;
  blur.prepass = prepass;
  blur.imagePxPerPrepassPx = static_cast<double>(image.widthPx) / prepass.widthPx;
  const double pxPerWindowUnit = image.widthPx / camera.view.window.width();

  // The frame plan's focus shifts: each colour's plane of focus, flat and at the corners.
  const std::vector<double> shifts = extremeFocusShifts(camera);

  const std::size_t n = depth.size();
  blur.ownPx.assign(n, 0.0f);
  std::vector<float> depthF(n, kInf);
  double ownMin = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const double z = depth[i];
    // Nothing seen: a constant background has no circle; an environment has infinity's.
    if (!(z > 0.0) || (std::isinf(z) && !(backgroundAtInfinity && camera.view.projection == Projection::Perspective)))
      continue;
    double c = 0.0;
    if (!camera.lens.isPinhole())
      for (const double shift : shifts) c = std::max(c, cocDiameterOnWindow(camera, z, shift) * pxPerWindowUnit);
    blur.ownPx[i] = static_cast<float>(std::min(c, 1e9));
    depthF[i] = static_cast<float>(z);
    ownMin = std::min(ownMin, c);
  }
  blur.ownMinPx = std::isfinite(ownMin) ? ownMin : 0.0;

  // Dilation, a power of two of radius at a time: circles of radius (2^(k−1), 2^k] pre-pass pixels
  // spread over the square of half-width 2^k around them, onto pixels farther than the nearest of them.
  blur.reachingPx = blur.ownPx;
  const double maxRadius = *std::max_element(blur.ownPx.begin(), blur.ownPx.end()) / 2.0 / blur.imagePxPerPrepassPx;
  const int maxSide = std::max(prepass.widthPx, prepass.heightPx);
  for (int k = 0; k < 31; ++k) {
    const double lo = k == 0 ? 0.0 : std::ldexp(1.0, k - 1), hi = std::ldexp(1.0, k);
    if (lo >= maxRadius) break;
    std::vector<float> levelDepth(n, kInf), levelCoc(n, 0.0f);
    bool any = false;
    for (std::size_t i = 0; i < n; ++i) {
      const double r = blur.ownPx[i] / 2.0 / blur.imagePxPerPrepassPx;
      if (blur.ownPx[i] > 1.0f && r > lo && r <= hi) {
        levelDepth[i] = depthF[i];
        levelCoc[i] = blur.ownPx[i];
        any = true;
      }
    }
    if (!any) continue;
    const int radius = std::min(static_cast<int>(std::ceil(hi)), maxSide);
    const std::vector<float> nearest =
        squareExtreme(levelDepth, prepass, radius, kInf, [](float a, float b) { return a < b; });
    const std::vector<float> largest =
        squareExtreme(levelCoc, prepass, radius, 0.0f, [](float a, float b) { return a > b; });
    for (std::size_t i = 0; i < n; ++i)
      if (nearest[i] < depthF[i]) blur.reachingPx[i] = std::max(blur.reachingPx[i], largest[i]);
  }

  std::array<std::size_t, 5> counts{};
  for (const float c : blur.reachingPx) {
    std::size_t bin = 0;
    while (bin < VisibleBlur::kBinEdgesPx.size() && c > VisibleBlur::kBinEdgesPx[bin]) ++bin;
    ++counts[bin];
  }
  for (std::size_t bin = 0; bin < counts.size(); ++bin)
    blur.fractions[bin] = static_cast<double>(counts[bin]) / static_cast<double>(n);
  blur.p50Px = percentile(blur.reachingPx, 0.5);
  blur.p90Px = percentile(blur.reachingPx, 0.9);
  blur.p99Px = percentile(blur.reachingPx, 0.99);
  blur.maxPx = n ? *std::max_element(blur.reachingPx.begin(), blur.reachingPx.end()) : 0.0;
  return blur;
}

}  // namespace lenslab
