#include "lens/ApertureShape.h"

#include "core/Text.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace lenslab {
namespace {

constexpr double kMinSqueeze = 0.1, kMaxSqueeze = 10.0;

// One blade's sector, θ ∈ [−α, α] from the blade's normal: boundary R(θ) = a / cos θ + b, the
// straight blade (a = (1 − roundness)·cos α, whose ends are the polygon's vertices at radius 1)
// blended with the unit circle (b = roundness). G(θ) = ∫₀^θ R² is the sector's area up to θ, twice.
struct Sector {
  double alpha = 0.0, a = 0.0, b = 1.0;

  explicit Sector(const ApertureShape& s) {
    alpha = glm::pi<double>() / s.blades;
    a = (1.0 - s.roundness) * std::cos(alpha);
    b = s.roundness;
  }
  double boundary(double theta) const { return a / std::cos(theta) + b; }
  double twiceArea(double theta) const {
    const double t = std::tan(theta);
    return a * a * t + 2.0 * a * b * std::asinh(t) + b * b * theta;
  }
  // The θ whose area fraction of the sector, from −α, is `fraction` ∈ [0, 1]: Newton's method on
  // the monotone G (G' = R² > 0), started from the straight blade's closed form.
  double angleAtFraction(double fraction) const {
    const double target = (2.0 * fraction - 1.0) * twiceArea(alpha);
    double theta = std::atan((2.0 * fraction - 1.0) * std::tan(alpha));
    for (int i = 0; i < 40; ++i) {
      const double r = boundary(theta);
      const double step = (twiceArea(theta) - target) / (r * r);
      theta = std::clamp(theta - step, -alpha, alpha);
      if (std::abs(step) < 1e-15) break;
    }
    return theta;
  }
};

// Scales the polygon (vertices at radius 1) to the unit disk's area π.
double areaScale(const ApertureShape& s) {
  if (s.blades == 0) return 1.0;
  const Sector sector(s);
  return std::sqrt(glm::pi<double>() / (s.blades * sector.twiceArea(sector.alpha)));
}

// The direction of the first blade's normal: a vertex straight up, turned by the rotation.
double firstNormalAngle(const ApertureShape& s) {
  return glm::half_pi<double>() + glm::radians(s.rotationDeg) + glm::pi<double>() / s.blades;
}

glm::dvec2 squeezed(glm::dvec2 p, const ApertureShape& s) {
  if (s.anamorphicSqueeze == 1.0) return p;
  const double q = std::sqrt(s.anamorphicSqueeze);
  return {p.x / q, p.y * q};
}

// The blade whose sector holds the polar angle `angle`: its normal's direction, and the angle
// from that normal (within ±α).
struct BladeAngle {
  double normal = 0.0, fromNormal = 0.0;
};
BladeAngle bladeAngle(double angle, const ApertureShape& s, const Sector& sector) {
  const double normal0 = firstNormalAngle(s);
  const double normal = normal0 + 2.0 * sector.alpha * std::round((angle - normal0) / (2.0 * sector.alpha));
  return {normal, std::clamp(angle - normal, -sector.alpha, sector.alpha)};
}

}  // namespace

std::optional<ApertureProblem> apertureShapeProblem(const ApertureShape& s) {
  if (s.blades != 0 && (s.blades < 3 || s.blades > ApertureShape::kMaxBlades))
    return ApertureProblem{"blades",
                           cat("is ", s.blades, "; give 0 (a circle) or 3 to ", ApertureShape::kMaxBlades, " blades")};
  if (!std::isfinite(s.rotationDeg))
    return ApertureProblem{"rotation_deg", cat("is ", s.rotationDeg, "; give an angle in degrees")};
  if (!(s.roundness >= 0.0 && s.roundness <= 1.0))
    return ApertureProblem{"roundness", cat("is ", s.roundness, "; give 0 (straight blades) to 1 (a circle)")};
  if (!(s.anamorphicSqueeze >= kMinSqueeze && s.anamorphicSqueeze <= kMaxSqueeze))
    return ApertureProblem{"anamorphic_squeeze",
                           cat("is ", s.anamorphicSqueeze, "; give a ratio from ", kMinSqueeze, " to ", kMaxSqueeze,
                               " (1: none; 1.33, 1.5 and 2 are common anamorphic lenses)")};
  return std::nullopt;
}

glm::dvec2 apertureFromDisk(glm::dvec2 p, const ApertureShape& s) {
  if (s.blades == 0 || s.roundness >= 1.0) return squeezed(p, s);
  const double r = glm::length(p);
  if (r == 0.0) return p;
  const Sector sector(s);
  // The blade whose sector holds φ, and φ's place in it.
  const auto [normal, d] = bladeAngle(std::atan2(p.y, p.x), s, sector);
  const double theta = sector.angleAtFraction((d + sector.alpha) / (2.0 * sector.alpha));
  const double radius = areaScale(s) * r * sector.boundary(theta);
  return squeezed(radius * glm::dvec2(std::cos(normal + theta), std::sin(normal + theta)), s);
}

glm::dvec2 diskFromAperture(glm::dvec2 a, const ApertureShape& s) {
  const double q = std::sqrt(s.anamorphicSqueeze);
  const glm::dvec2 p(a.x * q, a.y / q);
  if (s.blades == 0 || s.roundness >= 1.0) return p;
  const double r = glm::length(p);
  if (r == 0.0) return p;
  const Sector sector(s);
  const auto [normal, theta] = bladeAngle(std::atan2(p.y, p.x), s, sector);
  // G is odd: the area from −α to θ over the sector's, as a fraction of the disk's sector 2α.
  const double whole = sector.twiceArea(sector.alpha);
  const double fraction = 0.5 * (sector.twiceArea(theta) + whole) / whole;
  const double phi = normal - sector.alpha + 2.0 * sector.alpha * fraction;
  const double radius = r / (areaScale(s) * sector.boundary(theta));
  return radius * glm::dvec2(std::cos(phi), std::sin(phi));
}

ApertureSectors apertureSectors(const ApertureShape& s) {
  ApertureSectors out;
  out.squeezeRoot = std::sqrt(s.anamorphicSqueeze);
  if (s.blades == 0 || s.roundness >= 1.0) return out;
  const Sector sector(s);
  out.blades = s.blades;
  out.firstNormalRad = firstNormalAngle(s);
  out.halfAngleRad = sector.alpha;
  out.straight = sector.a;
  out.round = sector.b;
  out.scale = areaScale(s);
  out.twiceArea = sector.twiceArea(sector.alpha);
  return out;
}

double apertureReach(const ApertureShape& s) {
  const double q = std::sqrt(s.anamorphicSqueeze);
  const double squeeze = std::max(q, 1.0 / q);
  if (s.blades == 0 || s.roundness >= 1.0) return squeeze;
  return areaScale(s) * squeeze;  // the vertices, at radius 1 before scaling
}

std::vector<glm::dvec2> apertureOutline(const ApertureShape& s, int pointsPerSide) {
  std::vector<glm::dvec2> out;
  if (s.blades == 0 || s.roundness >= 1.0) {
    for (int i = 0; i < pointsPerSide; ++i) {
      const double phi = glm::two_pi<double>() * i / pointsPerSide;
      out.push_back(squeezed({std::cos(phi), std::sin(phi)}, s));
    }
    return out;
  }
  const Sector sector(s);
  const double scale = areaScale(s);
  for (int k = 0; k < s.blades; ++k) {
    const double normal = firstNormalAngle(s) + 2.0 * sector.alpha * k;
    for (int i = 0; i < pointsPerSide; ++i) {
      const double theta = -sector.alpha + 2.0 * sector.alpha * i / pointsPerSide;
      out.push_back(
          squeezed(scale * sector.boundary(theta) * glm::dvec2(std::cos(normal + theta), std::sin(normal + theta)), s));
    }
  }
  return out;
}

std::vector<glm::dvec2> apertureVertices(const ApertureShape& s) {
  std::vector<glm::dvec2> out;
  if (s.blades == 0) return out;
  const double scale = areaScale(s);
  for (int k = 0; k < s.blades; ++k) {
    const double angle = glm::half_pi<double>() + glm::radians(s.rotationDeg) + glm::two_pi<double>() * k / s.blades;
    out.push_back(squeezed(scale * glm::dvec2(std::cos(angle), std::sin(angle)), s));
  }
  return out;
}

std::string describeAperture(const ApertureShape& s) {
  std::string out = s.blades == 0 ? std::string("circle") : cat(s.blades, " blades");
  if (s.blades != 0 && s.rotationDeg != 0.0) out += cat(", rotated ", s.rotationDeg, " deg");
  if (s.blades != 0 && s.roundness != 0.0) out += cat(", roundness ", s.roundness);
  if (s.anamorphicSqueeze != 1.0) out += cat(", anamorphic squeeze ", s.anamorphicSqueeze);
  return out;
}

}  // namespace lenslab
