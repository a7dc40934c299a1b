#include "lens/RealLens.h"

#include <cmath>

namespace lenslab {

double indexAtWavelength(double indexD, double abbe, double wavelengthNm) {
  if (abbe <= 0.0 || indexD == 1.0) return indexD;
  // n = A + B/λ²: n_F − n_C = B (1/λ_F² − 1/λ_C²) = (n_d − 1)/V_d, and n_d = A + B/λ_d².
  const auto inverseSquare = [](double nm) { return 1.0 / (nm * nm); };
  const double b = (indexD - 1.0) / abbe / (inverseSquare(kLineFNm) - inverseSquare(kLineCNm));
  return indexD + b * (inverseSquare(wavelengthNm) - inverseSquare(kLineDNm));
}

std::optional<SurfaceHit> intersectSurface(const LensPrescription& lens, std::size_t i, const LensRay& ray) {
  const LensSurface& s = lens.surfaces[i];
  const double vertex = lens.vertexMm(i);
  SurfaceHit hit;
  if (s.isStop() || s.isPlane()) {
    if (ray.direction.z == 0.0) return std::nullopt;
    const double t = (vertex - ray.origin.z) / ray.direction.z;
    if (!(t > 0.0)) return std::nullopt;
    hit.point = ray.origin + t * ray.direction;
    hit.normal = {0.0, 0.0, ray.direction.z > 0.0 ? -1.0 : 1.0};
  } else {
    // The sphere about centre C = (0, 0, vertex + R): |o + t·d − C|² = R², the root on the cap
    // through the vertex (the other lies across the sphere, beyond any real element).
    const glm::dvec3 centre(0.0, 0.0, vertex + s.radiusMm);
    const glm::dvec3 oc = ray.origin - centre;
    const double b = glm::dot(oc, ray.direction);
    const double c = glm::dot(oc, oc) - s.radiusMm * s.radiusMm;
    const double discriminant = b * b - c;
    if (discriminant < 0.0) return std::nullopt;
    const double root = std::sqrt(discriminant);
    // Written without cancellation: t = −b ± √(b² − c), the small root as c / (−b ∓ √…).
    const double q = -b - std::copysign(root, b);
    const double t0 = q != 0.0 ? c / q : 0.0, t1 = q;
    // The cap: the vertex side of the centre, (z − C_z) with the sign of −R.
    bool found = false;
    for (double t : {std::min(t0, t1), std::max(t0, t1)}) {
      if (!(t > 0.0)) continue;
      const glm::dvec3 p = ray.origin + t * ray.direction;
      if ((p.z - centre.z) * -s.radiusMm > 0.0) {
        hit.point = p;
        found = true;
        break;
      }
    }
    if (!found) return std::nullopt;
    hit.normal = (hit.point - centre) / std::abs(s.radiusMm);
    if (glm::dot(hit.normal, ray.direction) > 0.0) hit.normal = -hit.normal;
  }
  const double r2 = hit.point.x * hit.point.x + hit.point.y * hit.point.y;
  hit.withinAperture = r2 <= 0.25 * s.apertureMm * s.apertureMm;
  return hit;
}

std::optional<glm::dvec3> refract(const glm::dvec3& incident, const glm::dvec3& normal, double n1, double n2) {
  const double eta = n1 / n2;
  const double cosIncident = -glm::dot(normal, incident);
  const double sin2Transmitted = eta * eta * std::max(0.0, 1.0 - cosIncident * cosIncident);
  if (sin2Transmitted > 1.0) return std::nullopt;
  const double cosTransmitted = std::sqrt(1.0 - sin2Transmitted);
  return glm::normalize(eta * incident + (eta * cosIncident - cosTransmitted) * normal);
}

std::optional<LensRay> traceLens(const LensPrescription& lens, const LensRay& ray, bool toScene,
                                 const LensTrace& options) {
  LensRay r = ray;
  const std::size_t n = lens.surfaces.size();
  const auto index = [&](double indexD, double abbe) { return indexAtWavelength(indexD, abbe, options.wavelengthNm); };
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = toScene ? n - 1 - k : k;
    const LensSurface& s = lens.surfaces[i];
    const std::optional<SurfaceHit> hit = intersectSurface(lens, i, r);
    if (!hit) return std::nullopt;
    r.origin = hit->point;
    if (options.path) options.path->push_back(hit->point);
    if (s.isStop()) {
      if (options.endAtStop) return r;
      const double diameter = options.stopDiameterMm.value_or(s.apertureMm);
      if (hit->point.x * hit->point.x + hit->point.y * hit->point.y > 0.25 * diameter * diameter) return std::nullopt;
      continue;
    }
    if (!hit->withinAperture && !options.ignoreRims) return std::nullopt;
    const double before = index(lens.indexBefore(i), i == 0 ? 0.0 : lens.surfaces[i - 1].abbeAfter);
    const double after = index(s.indexAfter, s.abbeAfter);
    const std::optional<glm::dvec3> d =
        refract(r.direction, hit->normal, toScene ? after : before, toScene ? before : after);
    if (!d) return std::nullopt;
    r.direction = *d;
  }
  return r;
}

}  // namespace lenslab
