#include "lens/LensFit.h"

#include "core/Text.h"
#include "lens/ExitPupil.h"
#include "lens/effects/Vignetting.h"
#include "lens/LensCamera.h"
#include "lens/ParaxialLens.h"
#include "lens/RealLens.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

namespace lenslab {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A rectilinear image cannot reach 90° off the axis; beyond about 80° its magnification grows
// past six times the centre's and the fit has nothing left to hold.
constexpr double kMaxFieldDegrees = 80.0;

// What the rays traced backward from one film point do in the scene. Each ray's transverse
// position at depth Z in front of the entrance pupil is a + b·Z (mm; b the ray's slope), so the
// bundle is a set of lines; where they come closest (least squares across the axis) is the scene
// point the film point sees sharply.
struct Bundle {
  double share = 0.0;          // relative illumination: the mean sample weight
  glm::dvec2 meanA{0.0}, meanB{0.0};
  double inverseFocusPerMm = 0.0;
  double rmsAngle = 0.0;       // RMS of the rays' angular spread about their centre at that depth
};

Bundle traceBundle(const ExitPupil& pupil, glm::dvec2 filmMm, double entrancePupilZ, int n) {
  struct Line {
    glm::dvec2 a, b;
    double w;
  };
  std::vector<Line> lines;
  Bundle out;
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

// Weighted least squares of y ≈ Σ c_k·x^(p0 + k·step) for k < terms. The columns are scaled to
// the largest |x| (a telephoto's field reaches x = 0.09, where x⁷ would span 17 decades unscaled),
// and the rows by √w, and the system is solved by Householder QR with column pivoting: it works on
// the design matrix itself, whose condition number is the square root of the normal equations',
// so a nearly dependent basis loses half as many digits. A rank-deficient basis (all x equal) gets
// a basic solution: zero in the columns the pivoting finds dependent.
std::vector<double> fitPowers(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& w, int firstPower, int step,
                              int terms) {
  double scale = 0.0;
  for (double v : x) scale = std::max(scale, std::abs(v));
  if (!(scale > 0.0)) scale = 1.0;
  const auto rows = static_cast<Eigen::Index>(x.size());
  Eigen::MatrixXd design(rows, terms);
  Eigen::VectorXd target(rows);
  for (Eigen::Index i = 0; i < rows; ++i) {
    const auto s = static_cast<std::size_t>(i);
    const double rootWeight = std::sqrt(w[s]);
    for (int k = 0; k < terms; ++k) design(i, k) = rootWeight * std::pow(x[s] / scale, firstPower + k * step);
    target(i) = rootWeight * y[s];
  }
  const Eigen::VectorXd scaled = design.colPivHouseholderQr().solve(target);
  std::vector<double> c(static_cast<std::size_t>(terms));
  for (int k = 0; k < terms; ++k) {
    const double ck = scaled(k) / std::pow(scale, firstPower + k * step);
    c[static_cast<std::size_t>(k)] = std::isfinite(ck) ? ck : 0.0;
  }
  return c;
}

// The barrel (distance, radius; mm) whose overlap with the aperture best matches the cat's-eye
// shares measured at undistorted radii x: for each distance on a grid, the radius by golden
// section; the best pair kept.
std::pair<double, double> fitBarrel(const std::vector<double>& x, const std::vector<double>& share, double apertureRadiusMm, double inverseFocusPerMm,
                                    double focalLengthMm) {
  const auto cost = [&](double distance, double radius) {
    const LensBarrel barrel{distance, radius};
    double sum = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double e = roundApertureThroughBarrel(barrel, apertureRadiusMm, glm::dvec2(x[i], 0.0), inverseFocusPerMm) - share[i];
      sum += e * e;
    }
    return sum;
  };
  double xMax = 0.0;
  for (double v : x) xMax = std::max(xMax, v);
  std::pair<double, double> best{0.0, 0.0};
  double bestCost = INFINITY;
  constexpr int kDistances = 160;
  for (int k = 1; k <= kDistances; ++k) {
    const double distance = 4.0 * focalLengthMm * k / kDistances;
    // The opening from barely larger than nothing to wide enough never to clip.
    double lo = 1e-3 * apertureRadiusMm, hi = apertureRadiusMm * std::abs(1.0 - distance * inverseFocusPerMm) + distance * xMax;
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int i = 0; i < 60; ++i) {
      const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
      if (cost(distance, m1) < cost(distance, m2))
        hi = m2;
      else
        lo = m1;
    }
    const double radius = 0.5 * (lo + hi), c = cost(distance, radius);
    if (c < bestCost) bestCost = c, best = {distance, radius};
  }
  return best;
}

double polynomial(const Distortion& d, double x) {
  const double x2 = x * x;
  return x * (1.0 + x2 * (d.k1 + x2 * (d.k2 + x2 * d.k3)));
}

double gainAt(const glm::dvec3& a, double r2) { return vignettingPolynomial(r2, a.x, a.y, a.z); }

}  // namespace

double LensFitError::worstUm() const { return std::max(positionUm + lateralColourUm, 0.5 * focusBlurUm + aberrationBlurUm); }

FittedLens fitLens(const LensPrescription& lens, const LensFitSettings& s) {
  FittedLens fit;
  const FirstOrder open = firstOrder(lens);
  const double stopMm = stopDiameterForFNumber(lens, s.fNumber);
  const FirstOrder stopped = firstOrder(lens, stopMm);
  fit.entrancePupilDiameterMm = stopped.entrancePupilDiameterMm;
  const double epZ = open.entrancePupilMm;
  const double focusMm = s.focusDistanceMm;
  const double nominalInverseFocus = std::isinf(focusMm) ? 0.0 : 1.0 / focusMm;
  const double filmZ = lens.lengthMm() + (std::isinf(focusMm) ? filmDistanceForFocusMm(lens, INFINITY) : filmDistanceForObjectMm(lens, focusMm - epZ));
  const double halfDiagonal = 0.5 * glm::length(s.sensorMm);

  // The channels the exact render traces (one without dispersion), green first.
  const bool dispersion = lens.hasDispersion();
  const std::vector<int> channels = dispersion ? std::vector<int>{1, 0, 2} : std::vector<int>{1};
  std::array<std::unique_ptr<ExitPupil>, 3> pupils;
  LensTrace trace;
  trace.stopDiameterMm = stopMm;
  const int rings = std::max(16, 2 * s.fieldSamples);
  for (int c : channels) {
    trace.wavelengthNm = dispersion ? kChannelWavelengthsNm[static_cast<std::size_t>(c)] : kLineDNm;
    pupils[static_cast<std::size_t>(c)] = std::make_unique<ExitPupil>(lens, filmZ, halfDiagonal, trace, rings);
  }
  LensTrace unclipped = trace;
  unclipped.wavelengthNm = dispersion ? kChannelWavelengthsNm[1] : kLineDNm;
  unclipped.ignoreRims = true;
  const ExitPupil stopOnly(lens, filmZ, halfDiagonal, unclipped, rings);

  // Film points at heights h below the axis image points h above it (the film is inverted).
  const int n = std::max(4, s.fieldSamples);
  std::array<std::vector<Bundle>, 3> bundles;
  std::vector<double> heights, catsEye;
  for (int k = 0; k < n; ++k) {
    const double h = halfDiagonal * k / (n - 1);
    heights.push_back(h);
    for (int c : channels) {
      const Bundle b = traceBundle(*pupils[static_cast<std::size_t>(c)], glm::dvec2(0.0, -h), epZ, s.pupilSamples);
      if (!(b.share > 0.0)) {
        // Past the image circle (a fisheye's on a larger sensor): the exact trace renders the
        // circle; no rectilinear camera holds it.
        fit.why = cat("no ray through the lens reaches the film ", std::round(h * 1000.0) / 1000.0,
                      " mm off the axis: the image circle ends inside the sensor (its half diagonal is ",
                      std::round(halfDiagonal * 1000.0) / 1000.0, " mm)");
        return fit;
      }
      bundles[static_cast<std::size_t>(c)].push_back(b);
    }
    const Bundle free = traceBundle(stopOnly, glm::dvec2(0.0, -h), epZ, s.pupilSamples);
    catsEye.push_back(free.share > 0.0 ? std::min(1.0, bundles[1].back().share / free.share) : 0.0);
  }
  // Shares relative to the axis's on this same grid (the thin lens's is 1 there by definition; the
  // grid's own estimate of the axis differs from the exit pupil's finer one by its cell edges).
  for (int c : channels) {
    std::vector<Bundle>& b = bundles[static_cast<std::size_t>(c)];
    const double axis = b.front().share;
    for (Bundle& each : b) each.share /= axis;
  }
  // Where each film point's blur centre lies in the scene at the focus distance, as a tangent.
  const auto undistortedOf = [&](const Bundle& b) { return b.meanB.y + b.meanA.y * nominalInverseFocus; };
  const std::vector<Bundle>& green = bundles[1];
  std::vector<double> xu, xs, hs, ones;
  for (int k = 0; k < n; ++k) {
    xu.push_back(undistortedOf(green[static_cast<std::size_t>(k)]));
    if (k > 0) xs.push_back(xu.back()), hs.push_back(heights[static_cast<std::size_t>(k)]), ones.push_back(1.0);
  }
  const double maxAngle = std::atan(xu.back()) * 180.0 / kPi;
  if (!(maxAngle < kMaxFieldDegrees) || !std::isfinite(xu.back())) {
    fit.why = cat("the field reaches ", std::round(maxAngle), "° off the axis at the sensor's corner; a rectilinear camera with distortion "
                  "holds at most ", kMaxFieldDegrees, "°");
    return fit;
  }

  // Focal length and distortion: h = F·x(1 + k1 x² + k2 x⁴ + k3 x⁶). Of the orders whose
  // distortion does not fold inside the image, the lowest that places the image within 0.05 µm
  // of the best: a telephoto's 5° field would otherwise buy a few nm with k3 in the thousands.
  struct Candidate {
    double focal;
    Distortion distortion;
    double worstMm;
  };
  std::vector<Candidate> candidates;
  for (int terms = 1; terms <= 4; ++terms) {
    const std::vector<double> c = fitPowers(xs, hs, ones, 1, 2, terms);
    Candidate candidate{c[0], {}, 0.0};
    Distortion& d = candidate.distortion;
    d.k1 = terms > 1 ? c[1] / c[0] : 0.0;
    d.k2 = terms > 2 ? c[2] / c[0] : 0.0;
    d.k3 = terms > 3 ? c[3] / c[0] : 0.0;
    const glm::dvec2 half = 0.5 * s.sensorMm / candidate.focal;
    if (!(candidate.focal > 0.0) || findFoldOver(d, -half, half)) continue;
    for (std::size_t i = 0; i < xs.size(); ++i)
      candidate.worstMm = std::max(candidate.worstMm, std::abs(candidate.focal * polynomial(d, xs[i]) - hs[i]));
    candidates.push_back(candidate);
  }
  double bestMm = INFINITY;
  for (const Candidate& c : candidates) bestMm = std::min(bestMm, c.worstMm);
  for (const Candidate& c : candidates)
    if (c.worstMm <= bestMm + 5e-5) {
      fit.focalLengthMm = c.focal;
      fit.distortion = c.distortion;
      fit.usable = true;
      break;
    }
  if (!fit.usable) {
    fit.why = "every fitted distortion folds over inside the image";
    return fit;
  }
  const double focal = fit.focalLengthMm;
  const auto imageHeight = [&](double x) { return focal * polynomial(fit.distortion, x); };

  // Focus and field curvature: 1/z = 1/z_f + c·x², over the field.
  std::vector<double> phi;
  for (const Bundle& b : green) phi.push_back(b.inverseFocusPerMm);
  const std::vector<double> focus = fitPowers(xu, phi, std::vector<double>(xu.size(), 1.0), 0, 2, 2);
  // A best focus beyond infinity (1/z < 0) cannot be a thin lens's focus: held at infinity.
  fit.inverseFocusPerMm = std::max(0.0, focus[0]);
  fit.fieldCurvaturePerMm = focus[1];
  const auto fittedFocus = [&](double x, double shift) { return fit.inverseFocusPerMm + shift + fit.fieldCurvaturePerMm * x * x; };

  // Colour: each channel's focus shift on average over the field, and its magnification.
  double& lateralRed = fit.lateralRed;
  double& lateralBlue = fit.lateralBlue;
  for (int c : {0, 2}) {
    if (!dispersion) break;
    const std::vector<Bundle>& b = bundles[static_cast<std::size_t>(c)];
    double shift = 0.0, num = 0.0, den = 0.0;
    for (int k = 0; k < n; ++k) {
      const double x = undistortedOf(b[static_cast<std::size_t>(k)]);
      shift += b[static_cast<std::size_t>(k)].inverseFocusPerMm - fittedFocus(x, 0.0);
      const double p = imageHeight(x);
      num += p * (heights[static_cast<std::size_t>(k)] - p);
      den += p * p;
    }
    (c == 0 ? fit.inverseFocusShiftRedPerMm : fit.inverseFocusShiftBluePerMm) = shift / n;
    (c == 0 ? lateralRed : lateralBlue) = den > 0.0 ? num / den : 0.0;
  }

  // The cat's eye, then the rest of the relative illumination over the distorted radius².
  const double apertureRadius = 0.5 * fit.entrancePupilDiameterMm;
  double leastShare = 1.0;
  for (double v : catsEye) leastShare = std::min(leastShare, v);
  if (leastShare < 0.999) {
    const auto [distance, radius] = fitBarrel(xu, catsEye, apertureRadius, fit.inverseFocusPerMm, focal);
    fit.barrelDistanceMm = distance;
    fit.barrelRadiusMm = radius;
  }
  const LensBarrel barrel{fit.barrelDistanceMm, fit.barrelRadiusMm};
  const auto barrelShare = [&](double x) {
    return barrel.present() ? roundApertureThroughBarrel(barrel, apertureRadius, glm::dvec2(x, 0.0), fit.inverseFocusPerMm) : 1.0;
  };
  std::vector<double> r2s, rest, restWeights;
  for (int k = 1; k < n; ++k) {
    const double share = barrelShare(xu[static_cast<std::size_t>(k)]);
    if (!(share > 1e-3)) continue;
    const double r = heights[static_cast<std::size_t>(k)] / focal;
    r2s.push_back(r * r);
    rest.push_back(green[static_cast<std::size_t>(k)].share / share - 1.0);
    restWeights.push_back(share * share);  // an error in the gain shows scaled by the share
  }
  if (r2s.size() >= 3) {
    const std::vector<double> a = fitPowers(r2s, rest, restWeights, 1, 1, 3);
    fit.illuminationGain = {a[0], a[1], a[2]};
  }

  // The errors, per effect, over the field.
  LensFitError& e = fit.error;
  for (int k = 0; k < n; ++k) {
    const std::size_t i = static_cast<std::size_t>(k);
    const double h = heights[i], x = xu[i];
    e.positionUm = std::max(e.positionUm, 1000.0 * std::abs(imageHeight(x) - h));
    const double r = h / focal;
    e.illumination = std::max(e.illumination, std::abs(barrelShare(x) * std::max(0.0, gainAt(fit.illuminationGain, r * r)) - green[i].share));
    for (int c : channels) {
      const Bundle& b = bundles[static_cast<std::size_t>(c)][i];
      const double xc = undistortedOf(b);
      const double lateral = c == 0 ? lateralRed : c == 2 ? lateralBlue : 0.0;
      const double shift = c == 0 ? fit.inverseFocusShiftRedPerMm : c == 2 ? fit.inverseFocusShiftBluePerMm : 0.0;
      if (c != 1) e.lateralColourUm = std::max(e.lateralColourUm, 1000.0 * std::abs((1.0 + lateral) * imageHeight(xc) - h));
      // A thin lens's blur on the film for a focus error Δ(1/z): the pupil's diameter × F × |Δ(1/z)|.
      e.focusBlurUm = std::max(e.focusBlurUm, 1000.0 * fit.entrancePupilDiameterMm * focal * std::abs(b.inverseFocusPerMm - fittedFocus(xc, shift)));
      e.aberrationBlurUm = std::max(e.aberrationBlurUm, 1000.0 * focal * b.rmsAngle);
    }
    FittedLensSample sample;
    sample.imageHeightMm = h;
    sample.undistorted = x;
    sample.inverseFocusPerMm = green[i].inverseFocusPerMm;
    sample.relativeIllumination = green[i].share;
    sample.catsEye = catsEye[i];
    sample.rmsBlurUm = 1000.0 * focal * green[i].rmsAngle;
    fit.samples.push_back(sample);
  }
  return fit;
}

LensEffects fittedEffects(const FittedLens& fit, double worldPerMm) {
  LensEffects effects;
  effects.distortion = fit.distortion;
  effects.chromatic.lateralRed = fit.lateralRed;
  effects.chromatic.lateralBlue = fit.lateralBlue;
  // Inverse distances: 1/mm over world units per mm.
  effects.chromatic.inverseFocusShiftRed = fit.inverseFocusShiftRedPerMm / worldPerMm;
  effects.chromatic.inverseFocusShiftBlue = fit.inverseFocusShiftBluePerMm / worldPerMm;
  effects.fieldCurvature.inverseFocusPerRadius2 = fit.fieldCurvaturePerMm / worldPerMm;
  effects.vignetting = {fit.illuminationGain.x, fit.illuminationGain.y, fit.illuminationGain.z};
  return effects;
}

LensBarrel fittedBarrel(const FittedLens& fit, double worldPerMm) {
  if (!(fit.barrelRadiusMm > 0.0)) return {};
  return {fit.barrelDistanceMm * worldPerMm, fit.barrelRadiusMm * worldPerMm};
}

}  // namespace lenslab
