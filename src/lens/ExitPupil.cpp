#include "lens/ExitPupil.h"

#include <algorithm>
#include <cmath>

namespace lenslab {
namespace {

// Half the side of the square searched on the rear vertex's plane: the element's rim, with room
// for rays that cross the plane off the rim and meet the curved surface within it.
double searchHalf(const LensPrescription& lens) { return 0.75 * lens.surfaces.back().apertureMm; }

std::optional<LensRay> traceFrom(const LensPrescription& lens, glm::dvec3 film, glm::dvec2 onRear, double rearZ,
                                 const LensTrace& trace) {
  return traceLens(lens, {film, glm::normalize(glm::dvec3(onRear, rearZ) - film)}, true, trace);
}

}  // namespace

double filmIrradianceBySearch(const LensPrescription& lens, double filmZ, double radiusMm, const LensTrace& trace,
                              int n) {
  const double rearZ = lens.lengthMm(), half = searchHalf(lens), d = filmZ - rearZ;
  const glm::dvec3 film(radiusMm, 0.0, filmZ);
  const double cell = 2.0 * half / n;
  double sum = 0.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const glm::dvec2 p(-half + (i + 0.5) * cell, -half + (j + 0.5) * cell);
      if (!traceFrom(lens, film, p, rearZ, trace)) continue;
      const double c = d / glm::length(glm::dvec3(p, rearZ) - film);
      sum += c * c * c * c * cell * cell / (d * d);
    }
  return sum;
}

ExitPupil::ExitPupil(const LensPrescription& lens, double filmZ, double filmRadiusMm, const LensTrace& trace, int rings)
    : lens_(&lens), trace_(trace), filmZ_(filmZ), filmRadiusMm_(filmRadiusMm), rearZ_(lens.lengthMm()) {
  trace_.path = nullptr;
  const double half = searchHalf(lens);
  constexpr int kSearch = 64;       // cells per side of the search
  constexpr int kRadiiPerRing = 4;  // both ends and two between
  const double cell = 2.0 * half / kSearch;
  boxes_.resize(static_cast<std::size_t>(rings));
  for (int k = 0; k < rings; ++k) {
    PupilBox box{glm::dvec2(INFINITY), glm::dvec2(-INFINITY)};
    for (int s = 0; s < kRadiiPerRing; ++s) {
      const double r = filmRadiusMm * (k + static_cast<double>(s) / (kRadiiPerRing - 1)) / rings;
      const glm::dvec3 film(r, 0.0, filmZ);
      // The passing region is symmetric about the meridional plane (y = 0): search y ≥ 0.
      for (int j = kSearch / 2; j < kSearch; ++j)
        for (int i = 0; i < kSearch; ++i) {
          const glm::dvec2 p(-half + (i + 0.5) * cell, -half + (j + 0.5) * cell);
          if (!traceFrom(lens, film, p, rearZ_, trace_)) continue;
          box.lo = glm::min(box.lo, glm::dvec2(p.x, -p.y));
          box.hi = glm::max(box.hi, p);
        }
    }
    if (box.lo.x <= box.hi.x) {
      // Grown by a cell and a half: the search saw each passing region only at cell centres.
      box.lo -= 1.5 * cell;
      box.hi += 1.5 * cell;
    }
    boxes_[static_cast<std::size_t>(k)] = box;
  }
  axialIrradiance_ = filmIrradianceBySearch(lens, filmZ, 0.0, trace_, 256);
}

const PupilBox& ExitPupil::boxAt(double radiusMm) const {
  const double t = filmRadiusMm_ > 0.0 ? radiusMm / filmRadiusMm_ : 0.0;
  const auto k = static_cast<std::size_t>(
      std::clamp(t * static_cast<double>(boxes_.size()), 0.0, static_cast<double>(boxes_.size() - 1)));
  return boxes_[k];
}

std::optional<FilmRay> ExitPupil::sample(glm::dvec2 filmMm, glm::dvec2 u) const {
  const double r = glm::length(filmMm);
  const PupilBox& box = boxAt(r);
  if (box.empty() || !(axialIrradiance_ > 0.0)) return std::nullopt;
  // The box's frame turned to the film point's azimuth (x along its radius).
  const glm::dvec2 radial = r > 0.0 ? filmMm / r : glm::dvec2(1.0, 0.0);
  const glm::dvec2 across(-radial.y, radial.x);
  const glm::dvec2 local = box.lo + u * (box.hi - box.lo);
  const glm::dvec2 onRear = local.x * radial + local.y * across;
  const glm::dvec3 film(filmMm, filmZ_);
  const std::optional<LensRay> out = traceFrom(*lens_, film, onRear, rearZ_, trace_);
  if (!out) return std::nullopt;
  const double d = filmZ_ - rearZ_;
  const double c = d / glm::length(glm::dvec3(onRear, rearZ_) - film);
  return FilmRay{*out, c * c * c * c * box.area() / (d * d) / axialIrradiance_};
}

}  // namespace lenslab
