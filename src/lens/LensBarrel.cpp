#include "lens/LensBarrel.h"

#include "core/Text.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace lenslab {
namespace {

constexpr double kMetresPerMillimetre = 1e-3;

// Area of the overlap of two circles of radii a and b whose centres are d apart.
double circleOverlap(double a, double b, double d) {
  if (d >= a + b) return 0.0;
  if (d <= std::abs(a - b)) return glm::pi<double>() * std::min(a, b) * std::min(a, b);
  const double alpha = std::acos(std::clamp((d * d + a * a - b * b) / (2.0 * d * a), -1.0, 1.0));
  const double beta = std::acos(std::clamp((d * d + b * b - a * a) / (2.0 * d * b), -1.0, 1.0));
  return a * a * (alpha - std::sin(2.0 * alpha) / 2.0) + b * b * (beta - std::sin(2.0 * beta) / 2.0);
}

}  // namespace

bool throughBarrel(const LensBarrel& barrel, glm::dvec2 lensOffset, glm::dvec2 normalised, double inverseFocus) {
  if (!barrel.present()) return true;
  const glm::dvec2 atOpening = lensOffset * (1.0 - barrel.distance * inverseFocus) + barrel.distance * normalised;
  return glm::dot(atOpening, atOpening) <= barrel.radius * barrel.radius;
}

double roundApertureThroughBarrel(const LensBarrel& barrel, double apertureRadius, glm::dvec2 normalised,
                                  double inverseFocus) {
  if (!barrel.present() || !(apertureRadius > 0.0)) return 1.0;
  const double seen = apertureRadius * std::abs(1.0 - barrel.distance * inverseFocus);
  if (seen == 0.0) return throughBarrel(barrel, {0.0, 0.0}, normalised, inverseFocus) ? 1.0 : 0.0;
  return circleOverlap(seen, barrel.radius, barrel.distance * glm::length(normalised)) /
         (glm::pi<double>() * seen * seen);
}

std::optional<BarrelProblem> barrelProblem(double distanceMm, double diameterMm) {
  if (!(std::isfinite(distanceMm) && distanceMm > 0.0 && distanceMm <= 1e4))
    return BarrelProblem{"distance_mm", cat("is ", distanceMm,
                                            "; give the opening's distance in front of the aperture, "
                                            "more than 0 and at most 10000 mm")};
  if (!(std::isfinite(diameterMm) && diameterMm > 0.0 && diameterMm <= 1e4))
    return BarrelProblem{"diameter_mm",
                         cat("is ", diameterMm, "; give the opening's diameter, more than 0 and at most 10000 mm")};
  return std::nullopt;
}

LensBarrel barrelFromMillimetres(double distanceMm, double diameterMm) {
  return {distanceMm * kMetresPerMillimetre, 0.5 * diameterMm * kMetresPerMillimetre};
}

}  // namespace lenslab
