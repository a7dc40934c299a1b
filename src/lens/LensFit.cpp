#include "lens/LensFit.h"

#include "core/Text.h"
#include "lens/LensFitBundles.h"
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

// Weighted least squares of y ≈ Σ c_k·x^(p0 + k·step) for k < terms. The columns are scaled to
// the largest |x| (a telephoto's field reaches x = 0.09, where x⁷ would span 17 decades unscaled),
// and the rows by √w, and the system is solved by Householder QR with column pivoting: it works on
// the design matrix itself, whose condition number is the square root of the normal equations',
// so a nearly dependent basis loses half as many digits. A rank-deficient basis (all x equal) gets
// a basic solution: zero in the columns the pivoting finds dependent.
std::vector<double> fitPowers(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& w,
                              int firstPower, int step, int terms) {
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
std::pair<double, double> fitBarrel(const std::vector<double>& x, const std::vector<double>& share,
                                    double apertureRadiusMm, double inverseFocusPerMm, double focalLengthMm) {
  const auto cost = [&](double distance, double radius) {
    const LensBarrel barrel{distance, radius};
    double sum = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double e =
          roundApertureThroughBarrel(barrel, apertureRadiusMm, glm::dvec2(x[i], 0.0), inverseFocusPerMm) - share[i];
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
    double lo = 1e-3 * apertureRadiusMm,
           hi = apertureRadiusMm * std::abs(1.0 - distance * inverseFocusPerMm) + distance * xMax;
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

// Where a film point's blur centre lies in the scene at the focus distance, as a tangent.
double undistortedOf(const LensFitBundle& b, double nominalInverseFocus) {
  return b.meanB.y + b.meanA.y * nominalInverseFocus;
}

double imageHeight(const FittedLens& fit, double x) { return fit.focalLengthMm * polynomial(fit.distortion, x); }

double fittedFocus(const FittedLens& fit, double x, double shift) {
  return fit.inverseFocusPerMm + shift + fit.fieldCurvaturePerMm * x * x;
}

// Focal length and distortion: h = F·x(1 + k1 x² + k2 x⁴ + k3 x⁶). Of the orders whose
// distortion does not fold inside the image, the lowest that places the image within 0.05 µm
// of the best: a telephoto's 5° field would otherwise buy a few nm with k3 in the thousands.
// False (and fit.why) when every order folds.
bool fitFocalAndDistortion(const std::vector<double>& xs, const std::vector<double>& hs, glm::dvec2 sensorMm,
                           FittedLens& fit) {
  const std::vector<double> ones(xs.size(), 1.0);
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
    const glm::dvec2 half = 0.5 * sensorMm / candidate.focal;
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
  if (!fit.usable) fit.why = "every fitted distortion folds over inside the image";
  return fit.usable;
}

// Focus and field curvature: 1/z = 1/z_f + c·x², over the field.
void fitFocusAndFieldCurvature(const std::vector<double>& xu, const std::vector<LensFitBundle>& green,
                               FittedLens& fit) {
  std::vector<double> phi;
  for (const LensFitBundle& b : green) phi.push_back(b.inverseFocusPerMm);
  const std::vector<double> focus = fitPowers(xu, phi, std::vector<double>(xu.size(), 1.0), 0, 2, 2);
  // A best focus beyond infinity (1/z < 0) cannot be a thin lens's focus: held at infinity.
  fit.inverseFocusPerMm = std::max(0.0, focus[0]);
  fit.fieldCurvaturePerMm = focus[1];
}

// Colour: each channel's focus shift on average over the field, and its magnification.
void fitColour(const LensFitField& field, double nominalInverseFocus, FittedLens& fit) {
  const int n = field.size();
  for (int c : {0, 2}) {
    if (!field.dispersion) break;
    const std::vector<LensFitBundle>& b = field.bundles[static_cast<std::size_t>(c)];
    double shift = 0.0, num = 0.0, den = 0.0;
    for (int k = 0; k < n; ++k) {
      const double x = undistortedOf(b[static_cast<std::size_t>(k)], nominalInverseFocus);
      shift += b[static_cast<std::size_t>(k)].inverseFocusPerMm - fittedFocus(fit, x, 0.0);
      const double p = imageHeight(fit, x);
      num += p * (field.heights[static_cast<std::size_t>(k)] - p);
      den += p * p;
    }
    (c == 0 ? fit.inverseFocusShiftRedPerMm : fit.inverseFocusShiftBluePerMm) = shift / n;
    (c == 0 ? fit.lateralRed : fit.lateralBlue) = den > 0.0 ? num / den : 0.0;
  }
}

// The share of the aperture the fitted barrel leaves at undistorted x (1 without a barrel).
double barrelShare(const FittedLens& fit, double x) {
  const LensBarrel barrel{fit.barrelDistanceMm, fit.barrelRadiusMm};
  return barrel.present() ? roundApertureThroughBarrel(barrel, 0.5 * fit.entrancePupilDiameterMm, glm::dvec2(x, 0.0),
                                                       fit.inverseFocusPerMm)
                          : 1.0;
}

// The cat's eye, then the rest of the relative illumination over the distorted radius².
void fitIllumination(const LensFitField& field, const std::vector<double>& xu, FittedLens& fit) {
  const double apertureRadius = 0.5 * fit.entrancePupilDiameterMm;
  double leastShare = 1.0;
  for (double v : field.catsEye) leastShare = std::min(leastShare, v);
  if (leastShare < 0.999) {
    const auto [distance, radius] =
        fitBarrel(xu, field.catsEye, apertureRadius, fit.inverseFocusPerMm, fit.focalLengthMm);
    fit.barrelDistanceMm = distance;
    fit.barrelRadiusMm = radius;
  }
  const std::vector<LensFitBundle>& green = field.bundles[1];
  std::vector<double> r2s, rest, restWeights;
  for (int k = 1; k < field.size(); ++k) {
    const double share = barrelShare(fit, xu[static_cast<std::size_t>(k)]);
    if (!(share > 1e-3)) continue;
    const double r = field.heights[static_cast<std::size_t>(k)] / fit.focalLengthMm;
    r2s.push_back(r * r);
    rest.push_back(green[static_cast<std::size_t>(k)].share / share - 1.0);
    restWeights.push_back(share * share);  // an error in the gain shows scaled by the share
  }
  if (r2s.size() >= 3) {
    const std::vector<double> a = fitPowers(r2s, rest, restWeights, 1, 1, 3);
    fit.illuminationGain = {a[0], a[1], a[2]};
  }
}

// The errors, per effect, over the field, and the samples the report plots.
void measureFitErrors(const LensFitField& field, const std::vector<double>& xu, double nominalInverseFocus,
                      FittedLens& fit) {
  const double focal = fit.focalLengthMm;
  const std::vector<LensFitBundle>& green = field.bundles[1];
  LensFitError& e = fit.error;
  for (int k = 0; k < field.size(); ++k) {
    const std::size_t i = static_cast<std::size_t>(k);
    const double h = field.heights[i], x = xu[i];
    e.positionUm = std::max(e.positionUm, 1000.0 * std::abs(imageHeight(fit, x) - h));
    const double r = h / focal;
    e.illumination =
        std::max(e.illumination,
                 std::abs(barrelShare(fit, x) * std::max(0.0, gainAt(fit.illuminationGain, r * r)) - green[i].share));
    for (int c : field.channels) {
      const LensFitBundle& b = field.bundles[static_cast<std::size_t>(c)][i];
      const double xc = undistortedOf(b, nominalInverseFocus);
      const double lateral = c == 0 ? fit.lateralRed : c == 2 ? fit.lateralBlue : 0.0;
      const double shift = c == 0 ? fit.inverseFocusShiftRedPerMm : c == 2 ? fit.inverseFocusShiftBluePerMm : 0.0;
      if (c != 1)
        e.lateralColourUm = std::max(e.lateralColourUm, 1000.0 * std::abs((1.0 + lateral) * imageHeight(fit, xc) - h));
      // A thin lens's blur on the film for a focus error Δ(1/z): the pupil's diameter × F × |Δ(1/z)|.
      e.focusBlurUm = std::max(e.focusBlurUm, 1000.0 * fit.entrancePupilDiameterMm * focal *
                                                  std::abs(b.inverseFocusPerMm - fittedFocus(fit, xc, shift)));
      e.aberrationBlurUm = std::max(e.aberrationBlurUm, 1000.0 * focal * b.rmsAngle);
    }
    FittedLensSample sample;
    sample.imageHeightMm = h;
    sample.undistorted = x;
    sample.inverseFocusPerMm = green[i].inverseFocusPerMm;
    sample.relativeIllumination = green[i].share;
    sample.catsEye = field.catsEye[i];
    sample.rmsBlurUm = 1000.0 * focal * green[i].rmsAngle;
    fit.samples.push_back(sample);
  }
}

}  // namespace

double LensFitError::worstUm() const {
  return std::max(positionUm + lateralColourUm, 0.5 * focusBlurUm + aberrationBlurUm);
}

FittedLens fitLens(const LensPrescription& lens, const LensFitSettings& s) {
  FittedLens fit;
  const FirstOrder open = firstOrder(lens);
  const double stopMm = stopDiameterForFNumber(lens, s.fNumber);
  const FirstOrder stopped = firstOrder(lens, stopMm);
  fit.entrancePupilDiameterMm = stopped.entrancePupilDiameterMm;
  const double epZ = open.entrancePupilMm;
  const double focusMm = s.focusDistanceMm;
  const double nominalInverseFocus = std::isinf(focusMm) ? 0.0 : 1.0 / focusMm;
  const double filmZ = lens.lengthMm() + (std::isinf(focusMm) ? filmDistanceForFocusMm(lens, INFINITY)
                                                              : filmDistanceForObjectMm(lens, focusMm - epZ));

  const LensFitField field = traceLensFitField(lens, s, filmZ, stopMm, epZ);
  if (!field.why.empty()) {
    fit.why = field.why;
    return fit;
  }
  // Where each film point's blur centre lies in the scene at the focus distance, as a tangent.
  std::vector<double> xu, xs, hs;
  for (int k = 0; k < field.size(); ++k) {
    xu.push_back(undistortedOf(field.bundles[1][static_cast<std::size_t>(k)], nominalInverseFocus));
    if (k > 0) xs.push_back(xu.back()), hs.push_back(field.heights[static_cast<std::size_t>(k)]);
  }
  const double maxAngle = std::atan(xu.back()) * 180.0 / kPi;
  if (!(maxAngle < kMaxFieldDegrees) || !std::isfinite(xu.back())) {
    fit.why = cat("the field reaches ", std::round(maxAngle),
                  "° off the axis at the sensor's corner; a rectilinear camera with distortion "
                  "holds at most ",
                  kMaxFieldDegrees, "°");
    return fit;
  }
  if (!fitFocalAndDistortion(xs, hs, s.sensorMm, fit)) return fit;
  fitFocusAndFieldCurvature(xu, field.bundles[1], fit);
  fitColour(field, nominalInverseFocus, fit);
  fitIllumination(field, xu, fit);
  measureFitErrors(field, xu, nominalInverseFocus, fit);
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
