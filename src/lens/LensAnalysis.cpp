#include "lens/LensAnalysis.h"

#include "core/Error.h"
#include "core/Text.h"
#include "lens/RealLens.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace lenslab {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegrees = 180.0 / kPi;

// The prescription with each glass's index at one wavelength (and no dispersion left).
LensPrescription atWavelength(const LensPrescription& lens, double wavelengthNm) {
  LensPrescription out = lens;
  for (LensSurface& s : out.surfaces) {
    s.indexAfter = indexAtWavelength(s.indexAfter, s.abbeAfter, wavelengthNm);
    s.abbeAfter = 0.0;
  }
  return out;
}

struct Setup {
  const LensPrescription& lens;
  double stopDiameterMm;
  double filmZ;  // the film's axial position
  double exitPupilZ;
  double entrancePupilDiameterMm;
};

// The chief ray of film height h (along +y): the ray from the film point through the stop's
// centre, found by aiming at the exit pupil and correcting the aim by secant steps until the
// ray meets the stop's plane on the axis. Returned as it leaves toward the scene (rims ignored:
// a vignetted chief ray still defines where the field is).
std::optional<LensRay> chiefRay(const Setup& s, double h, double wavelengthNm) {
  const glm::dvec3 film(0.0, h, s.filmZ);
  LensTrace toStop;
  toStop.endAtStop = true;
  toStop.ignoreRims = true;
  toStop.wavelengthNm = wavelengthNm;
  const auto rayAt = [&](double aim) {
    return LensRay{film, glm::normalize(glm::dvec3(0.0, aim, s.exitPupilZ) - film)};
  };
  const auto heightAtStop = [&](double aim) -> std::optional<double> {
    const std::optional<LensRay> r = traceLens(s.lens, rayAt(aim), true, toStop);
    if (!r) return std::nullopt;
    return r->origin.y;
  };
  double a0 = 0.0, a1 = 1e-3 * (std::abs(h) + 1.0);
  std::optional<double> y0 = heightAtStop(a0), y1 = heightAtStop(a1);
  for (int i = 0; i < 60 && y0 && y1; ++i) {
    if (std::abs(*y1) < 1e-11 * (1.0 + std::abs(h))) break;
    if (*y1 == *y0) return std::nullopt;
    const double a2 = a1 - *y1 * (a1 - a0) / (*y1 - *y0);
    a0 = a1, y0 = y1;
    a1 = a2, y1 = heightAtStop(a1);
  }
  if (!y1 || std::abs(*y1) > 1e-7 * (1.0 + std::abs(h))) return std::nullopt;
  LensTrace out;
  out.ignoreRims = true;
  out.stopDiameterMm = s.stopDiameterMm;
  out.wavelengthNm = wavelengthNm;
  return traceLens(s.lens, rayAt(a1), true, out);
}

// The angle to the axis of a ray leaving toward the scene (−z).
double fieldAngle(const LensRay& toScene) {
  return std::atan2(std::hypot(toScene.direction.x, toScene.direction.y), -toScene.direction.z);
}

std::string mmText(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3f mm", v);
  return text;
}

double fieldAngleAt(const Setup& s, double h, double wavelengthNm) {
  const std::optional<LensRay> chief = chiefRay(s, h, wavelengthNm);
  if (chief) return fieldAngle(*chief);
  // How far out the lens does reach: the largest film height with a chief ray, by bisection.
  double lo = 0.0, hi = h;
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    (chiefRay(s, mid, wavelengthNm) ? lo : hi) = mid;
  }
  if (lo < 1e-3)  // not even a micrometre: no sensor would do
    throw InputError(cat(s.lens.source, ": no chief ray through the stop's centre reaches the film off the axis; ",
                         "the lens covers no field (check each row's thickness and clear aperture)"));
  throw InputError(cat(s.lens.source, ": no chief ray reaches the film ", mmText(h),
                       " off the axis; the lens covers a circle of ", mmText(lo),
                       " radius there, so give a --sensor whose diagonal is at most ", mmText(2.0 * lo)));
}

// Integrates `weight` over the rays that pass, sampled on a grid: first a coarse grid over
// `half`-wide square about `centre` finds where rays pass, then an n × n grid over that box.
// `ray(p)` makes the ray for grid point p (2-D); returns (sum of weight × cell area, the passing
// rays' landing points when `landing` is given).
template <class MakeRay, class Weight>
double integrateOverPassing(glm::dvec2 centre, double half, int n, MakeRay ray, Weight weight) {
  glm::dvec2 lo(INFINITY), hi(-INFINITY);
  const int coarse = 64;
  for (int j = 0; j < coarse; ++j)
    for (int i = 0; i < coarse; ++i) {
      const glm::dvec2 p = centre + half * glm::dvec2((i + 0.5) / coarse * 2.0 - 1.0, (j + 0.5) / coarse * 2.0 - 1.0);
      if (ray(p)) lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
  if (!(lo.x <= hi.x)) return 0.0;
  const double cell = 2.0 * half / coarse;  // one coarse cell of margin each side
  lo -= cell, hi += cell;
  const glm::dvec2 step = (hi - lo) / static_cast<double>(n);
  double sum = 0.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const glm::dvec2 p = lo + step * glm::dvec2(i + 0.5, j + 0.5);
      if (const auto r = ray(p)) sum += weight(p, *r) * step.x * step.y;
    }
  return sum;
}

// Irradiance at film height h, up to a constant: the projected solid angle of the rays that pass,
// sampled on the plane of the last vertex (distance D from the film: dA·cos⁴α / D²).
double irradiance(const Setup& s, double h, int n) {
  const LensSurface& last = s.lens.surfaces.back();
  const double lastZ = s.lens.lengthMm();
  const glm::dvec3 film(0.0, h, s.filmZ);
  LensTrace trace;
  trace.stopDiameterMm = s.stopDiameterMm;
  const auto ray = [&](glm::dvec2 p) {
    const LensRay r{film, glm::normalize(glm::dvec3(p, lastZ) - film)};
    return traceLens(s.lens, r, true, trace);
  };
  const double d = s.filmZ - lastZ;
  return integrateOverPassing(glm::dvec2(0.0), 0.75 * last.apertureMm, n, ray, [&](glm::dvec2 p, const LensRay&) {
    const double c = d / glm::length(glm::dvec3(p, lastZ) - film);
    return c * c * c * c;
  });
}

// RMS radius of the spot on the film of the bundle from the field point whose chief ray leaves
// the film at height h (from infinity when focus is at infinity, else from the object point).
double rmsSpot(const Setup& s, double h, double focusDistanceMm, int n) {
  const std::optional<LensRay> chief = chiefRay(s, h, kLineDNm);
  if (!chief) return NAN;
  const LensSurface& first = s.lens.surfaces.front();
  // In front of the first surface's rim (a surface concave toward the scene reaches forward).
  const double startZ = std::min(0.0, first.sagMm(0.5 * first.apertureMm)) - 1.0;
  const bool atInfinity = !(focusDistanceMm > 0.0) || std::isinf(focusDistanceMm);
  // The object point on the chief ray's scene-side line, focusDistance in front of the film.
  const double objectZ = s.filmZ - focusDistanceMm;
  const glm::dvec3 object = atInfinity
                                ? glm::dvec3(0.0)
                                : chief->origin + (objectZ - chief->origin.z) / chief->direction.z * chief->direction;
  LensTrace trace;
  trace.stopDiameterMm = s.stopDiameterMm;
  std::vector<glm::dvec2> landed;
  const auto ray = [&](glm::dvec2 p) -> std::optional<LensRay> {
    const glm::dvec3 start(p, startZ);
    const glm::dvec3 d = atInfinity ? -chief->direction : glm::normalize(start - object);
    return traceLens(s.lens, {start - 1e-3 * d, d}, false, trace);
  };
  const auto onFilm = [&](const LensRay& r) {
    const double t = (s.filmZ - r.origin.z) / r.direction.z;
    return glm::dvec2(r.origin + t * r.direction);
  };
  // Centred where the chief ray crosses the starting plane, over twice the entrance pupil there
  // (stretched by the obliquity: the bundle is wider across the plane off-axis).
  const glm::dvec2 centre(chief->origin + (startZ - chief->origin.z) / chief->direction.z * chief->direction);
  integrateOverPassing(centre, 2.0 * s.entrancePupilDiameterMm / std::max(0.05, -chief->direction.z), n, ray,
                       [&](glm::dvec2, const LensRay& r) {
                         landed.push_back(onFilm(r));
                         return 1.0;
                       });
  if (landed.empty()) return NAN;
  glm::dvec2 mean(0.0);
  for (const glm::dvec2& p : landed) mean += p;
  mean /= static_cast<double>(landed.size());
  double sum = 0.0;
  for (const glm::dvec2& p : landed) sum += glm::dot(p - mean, p - mean);
  return std::sqrt(sum / static_cast<double>(landed.size()));
}

// Least squares of y = k1 x + k2 x² + k3 x³ (x = r_u², y = r_d/r_u − 1), by the normal equations.
glm::dvec3 fitBrown(const std::vector<double>& x, const std::vector<double>& y) {
  glm::dmat3 a(0.0);
  glm::dvec3 b(0.0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const glm::dvec3 row(x[i], x[i] * x[i], x[i] * x[i] * x[i]);
    a += glm::outerProduct(row, row);
    b += row * y[i];
  }
  return glm::inverse(a) * b;
}

// Brown-Conrady and equidistant fits over a finer sampling of the field than the report's
// table, out to the half diagonal; `reference` is the paraxial focal length at this focus.
void fitDistortionModels(const Setup& s, double halfDiagonal, double reference, LensReport& report) {
  std::vector<double> x, y, ru, rd, thetas, heights;
  for (int k = 1; k <= 48; ++k) {
    const double h = halfDiagonal * k / 48.0;
    const double theta = fieldAngleAt(s, h, kLineDNm);
    thetas.push_back(theta);
    heights.push_back(h);
    if (theta >= 0.5 * kPi) continue;
    const double u = std::tan(theta), d = h / reference;
    ru.push_back(u), rd.push_back(d);
    x.push_back(u * u), y.push_back(d / u - 1.0);
  }
  if (x.size() >= 3) {
    report.brownK = fitBrown(x, y);
    double sum = 0.0;
    for (std::size_t i = 0; i < ru.size(); ++i) {
      const double r2 = ru[i] * ru[i];
      const double model = ru[i] * (1.0 + r2 * (report.brownK.x + r2 * (report.brownK.y + r2 * report.brownK.z)));
      sum += std::pow((model - rd[i]) / rd[i], 2.0);
    }
    report.brownRmsErrorPercent = 100.0 * std::sqrt(sum / static_cast<double>(ru.size()));
  }
  if (report.fisheye) {
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < thetas.size(); ++i) num += heights[i] * thetas[i], den += thetas[i] * thetas[i];
    report.equidistantFocalMm = num / den;
    double sum = 0.0;
    for (std::size_t i = 0; i < thetas.size(); ++i)
      sum += std::pow((report.equidistantFocalMm * thetas[i] - heights[i]) / heights[i], 2.0);
    report.equidistantRmsErrorPercent = 100.0 * std::sqrt(sum / static_cast<double>(thetas.size()));
  }
}

// Axial colour (F line's focus against C's) and lateral colour at the half diagonal.
void measureColour(const Setup& s, double halfDiagonal, LensReport& report) {
  const LensPrescription blue = atWavelength(s.lens, kLineFNm), red = atWavelength(s.lens, kLineCNm);
  report.axialColourMm = filmDistanceForFocusMm(blue, INFINITY) - filmDistanceForFocusMm(red, INFINITY);
  // The same scene angle as the d line's chief ray at the half diagonal, found at F and at C.
  const double target = fieldAngleAt(s, halfDiagonal, kLineDNm);
  const auto heightFor = [&](double wavelengthNm) {
    double h0 = halfDiagonal, h1 = 1.001 * halfDiagonal;
    double e0 = fieldAngleAt(s, h0, wavelengthNm) - target, e1 = fieldAngleAt(s, h1, wavelengthNm) - target;
    for (int i = 0; i < 40 && std::abs(e1) > 1e-13 && e1 != e0; ++i) {
      const double h2 = h1 - e1 * (h1 - h0) / (e1 - e0);
      h0 = h1, e0 = e1, h1 = h2, e1 = fieldAngleAt(s, h1, wavelengthNm) - target;
    }
    return h1;
  };
  report.lateralColourMm = heightFor(kLineFNm) - heightFor(kLineCNm);
}

}  // namespace

LensReport analyseLens(const LensPrescription& lens, const LensAnalysisOptions& o) {
  LensReport report;
  report.firstOrder = firstOrder(lens);
  report.stopDiameterMm = stopDiameterForFNumber(lens, o.fNumber);
  if (o.fNumber) report.firstOrder = firstOrder(lens, report.stopDiameterMm);
  const bool atInfinity = !(o.focusDistanceMm > 0.0) || std::isinf(o.focusDistanceMm);
  report.filmDistanceMm = filmDistanceForFocusMm(lens, atInfinity ? INFINITY : o.focusDistanceMm);

  // Paraxial working f-number and magnification at the focus distance.
  const RayTransfer m = lensTransfer(lens);
  const double epRadius = 0.5 * report.firstOrder.entrancePupilDiameterMm;
  if (atInfinity) {
    report.workingFNumber = 1.0 / (2.0 * std::abs(m.c) * epRadius);
  } else {
    const double s = o.focusDistanceMm - lens.lengthMm() - report.filmDistanceMm;  // object → first vertex
    const double u = epRadius / (s + report.firstOrder.entrancePupilMm);
    report.workingFNumber = 1.0 / (2.0 * std::abs(m.c * s * u + m.d * u));
    report.magnification = m.a + report.filmDistanceMm * m.c;
  }

  const Setup setup{lens, report.stopDiameterMm, lens.lengthMm() + report.filmDistanceMm, report.firstOrder.exitPupilMm,
                    report.firstOrder.entrancePupilDiameterMm};
  const double halfDiagonal = 0.5 * glm::length(o.sensorMm);
  report.fieldOfViewDegrees =
      2.0 * kDegrees *
      glm::dvec3(fieldAngleAt(setup, 0.5 * o.sensorMm.x, kLineDNm), fieldAngleAt(setup, 0.5 * o.sensorMm.y, kLineDNm),
                 fieldAngleAt(setup, halfDiagonal, kLineDNm));
  report.fisheye = report.fieldOfViewDegrees.z >= 120.0;

  // The rectilinear reference: the paraxial focal length at this focus, h / tan θ near the axis.
  const double hSmall = 1e-4 * halfDiagonal;
  const double reference = hSmall / std::tan(fieldAngleAt(setup, hSmall, kLineDNm));
  const double axialIrradiance = irradiance(setup, 0.0, o.pupilSamples);
  for (int k = 0; k < o.fieldSamples; ++k) {
    FieldSample f;
    f.fieldFraction = static_cast<double>(k) / std::max(1, o.fieldSamples - 1);
    f.imageHeightMm = f.fieldFraction * halfDiagonal;
    const double theta = f.imageHeightMm > 0.0 ? fieldAngleAt(setup, f.imageHeightMm, kLineDNm) : 0.0;
    f.fieldAngleDegrees = theta * kDegrees;
    f.distortionPercent = f.imageHeightMm > 0.0 && theta < 0.5 * kPi
                              ? 100.0 * (f.imageHeightMm / (reference * std::tan(theta)) - 1.0)
                              : 0.0;
    f.relativeIllumination =
        axialIrradiance > 0.0 ? irradiance(setup, f.imageHeightMm, o.pupilSamples) / axialIrradiance : 0.0;
    report.field.push_back(f);
  }

  fitDistortionModels(setup, halfDiagonal, reference, report);
  report.dispersion = lens.hasDispersion();
  if (report.dispersion) measureColour(setup, halfDiagonal, report);

  const double focus = atInfinity ? INFINITY : o.focusDistanceMm;
  report.rmsSpotMm = {rmsSpot(setup, 0.0, focus, o.pupilSamples),
                      rmsSpot(setup, 0.5 * halfDiagonal, focus, o.pupilSamples),
                      rmsSpot(setup, halfDiagonal, focus, o.pupilSamples)};
  return report;
}

}  // namespace lenslab
