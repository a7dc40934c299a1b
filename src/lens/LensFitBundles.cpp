#include "lens/LensFitBundles.h"

#include "core/Text.h"
#include "lens/ExitPupil.h"
#include "lens/LensCamera.h"
#include "lens/RealLens.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

namespace lenslab {

LensFitBundle traceLensFitBundle(const ExitPupil& pupil, glm::dvec2 filmMm, double entrancePupilZ, int n) {
  struct Line {
    glm::dvec2 a, b;
    double w;
  };
  std::vector<Line> lines;
  LensFitBundle out;
  double weightSum = 0.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::optional<FilmRay> r = pupil.sample(filmMm, glm::dvec2((i + 0.5) / n, (j + 0.5) / n));
      if (!r || !(r->weight > 0.0)) continue;
      const glm::dvec3 o = r->ray.origin, d = r->ray.direction;  // d.z < 0: toward the scene
      const glm::dvec2 b = -glm::dvec2(d) / d.z;
      const glm::dvec2 a = glm::dvec2(o) + (entrancePupilZ - o.z) / d.z * glm::dvec2(d);
      lines.push_back({a, b, r->weight});
      weightSum += r->weight;
      out.meanA += r->weight * a;
      out.meanB += r->weight * b;
    }
  out.share = weightSum / (static_cast<double>(n) * n);
  if (!(weightSum > 0.0)) return out;
  out.meanA /= weightSum;
  out.meanB /= weightSum;
  // The blur on the film is the bundle's angular spread seen from the pupil times F, and at
  // depth Z = 1/φ that spread is (a' + b'Z)/Z = a'·φ + b' (primes: about the bundle's centre).
  // Σ w |a'·φ + b'|² is least at φ = −Σ w a'·b' / Σ w |a'|²: well conditioned at infinity focus
  // (φ near 0), and through it, where an astigmatic bundle's two foci lie either side of infinity.
  double aa = 0.0, ab = 0.0;
  for (const Line& l : lines) {
    const glm::dvec2 a = l.a - out.meanA, b = l.b - out.meanB;
    aa += l.w * glm::dot(a, a);
    ab += l.w * glm::dot(a, b);
  }
  out.inverseFocusPerMm = aa > 0.0 ? -ab / aa : 0.0;
  // The spread that remains there: what no thin lens has.
  double spread = 0.0;
  for (const Line& l : lines) {
    const glm::dvec2 e = (l.a - out.meanA) * out.inverseFocusPerMm + (l.b - out.meanB);
    spread += l.w * glm::dot(e, e);
  }
  out.rmsAngle = std::sqrt(spread / weightSum);
  return out;
}

LensFitField traceLensFitField(const LensPrescription& lens, const LensFitSettings& s, double filmZ, double stopMm,
                               double entrancePupilZ) {
  LensFitField field;
  const double halfDiagonal = 0.5 * glm::length(s.sensorMm);

  // The channels the exact render traces (one without dispersion), green first.
  field.dispersion = lens.hasDispersion();
  const bool dispersion = field.dispersion;
  field.channels = dispersion ? std::vector<int>{1, 0, 2} : std::vector<int>{1};
  std::array<std::unique_ptr<ExitPupil>, 3> pupils;
  LensTrace trace;
  trace.stopDiameterMm = stopMm;
  const int rings = std::max(16, 2 * s.fieldSamples);
  for (int c : field.channels) {
    trace.wavelengthNm = dispersion ? kChannelWavelengthsNm[static_cast<std::size_t>(c)] : kLineDNm;
    pupils[static_cast<std::size_t>(c)] = std::make_unique<ExitPupil>(lens, filmZ, halfDiagonal, trace, rings);
  }
  // The same lens with its rims ignored: the light the stop alone would pass, the cat's eye's unit.
  LensTrace unclipped = trace;
  unclipped.wavelengthNm = dispersion ? kChannelWavelengthsNm[1] : kLineDNm;
  unclipped.ignoreRims = true;
  const ExitPupil stopOnly(lens, filmZ, halfDiagonal, unclipped, rings);

  // Film points at heights h below the axis image points h above it (the film is inverted).
  const int n = std::max(4, s.fieldSamples);
  for (int k = 0; k < n; ++k) {
    const double h = halfDiagonal * k / (n - 1);
    field.heights.push_back(h);
    for (int c : field.channels) {
      const LensFitBundle b =
          traceLensFitBundle(*pupils[static_cast<std::size_t>(c)], glm::dvec2(0.0, -h), entrancePupilZ, s.pupilSamples);
      if (!(b.share > 0.0)) {
        // Past the image circle (a fisheye's on a larger sensor): the exact trace renders the
        // circle; no rectilinear camera holds it.
        field.why = cat("no ray through the lens reaches the film ", std::round(h * 1000.0) / 1000.0,
                        " mm off the axis: the image circle ends inside the sensor (its half diagonal is ",
                        std::round(halfDiagonal * 1000.0) / 1000.0, " mm)");
        return field;
      }
      field.bundles[static_cast<std::size_t>(c)].push_back(b);
    }
    const LensFitBundle free = traceLensFitBundle(stopOnly, glm::dvec2(0.0, -h), entrancePupilZ, s.pupilSamples);
    field.catsEye.push_back(free.share > 0.0 ? std::min(1.0, field.bundles[1].back().share / free.share) : 0.0);
  }
  // Shares relative to the axis's on this same grid (the thin lens's is 1 there by definition; the
  // grid's own estimate of the axis differs from the exit pupil's finer one by its cell edges).
  for (int c : field.channels) {
    std::vector<LensFitBundle>& b = field.bundles[static_cast<std::size_t>(c)];
    const double axis = b.front().share;
    for (LensFitBundle& each : b) each.share /= axis;
  }
  return field;
}

}  // namespace lenslab
