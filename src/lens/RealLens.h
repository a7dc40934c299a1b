#pragma once
// Real rays through a lens prescription: each surface met exactly (a sphere, a plane, the stop's
// plane), refracted by Snell's law in vector form, and stopped at each element's rim and at the
// stop. Pure math (GLM + std), no GL. Units mm; the axis is +z from the first surface's vertex
// (z = 0) toward the film, x and y across it (LensPrescription's frame).
#include "lens/LensPrescription.h"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace lenslab {

struct LensRay {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, 1.0};  // unit
};

// Wavelengths of the Fraunhofer lines the Abbe number is defined by (nm).
constexpr double kLineDNm = 587.5618;  // helium d: where n_d is given
constexpr double kLineFNm = 486.1327;  // hydrogen F
constexpr double kLineCNm = 656.2725;  // hydrogen C

// The index at `wavelengthNm` of a glass with index n_d and Abbe number V_d (0: no dispersion),
// from Cauchy's two-term formula n(λ) = A + B/λ² fitted to n_d and n_F − n_C = (n_d − 1)/V_d:
// what the two numbers of a catalogue's glass determine, good to about 1e-3 across the visible.
double indexAtWavelength(double indexD, double abbe, double wavelengthNm);

// Where a ray meets surface `i` (its sphere's cap about the vertex, or its plane), and whether
// it lands within the clear aperture there.
struct SurfaceHit {
  glm::dvec3 point{0.0};
  glm::dvec3 normal{0.0};  // unit, facing back along the incoming ray
  bool withinAperture = false;
};
std::optional<SurfaceHit> intersectSurface(const LensPrescription& lens, std::size_t i, const LensRay& ray);

// Snell's law: the unit direction refracted at a surface of unit normal `normal` (facing back
// along `incident`), from index n1 to n2; nullopt at total internal reflection.
std::optional<glm::dvec3> refract(const glm::dvec3& incident, const glm::dvec3& normal, double n1, double n2);

// The ray traced through every surface, from the film side toward the scene (`toScene`) or from
// the scene toward the film; nullopt where a rim or the stop stops it, or it reflects totally.
// `stopDiameterMm` replaces the stop row's diameter when given (the camera's f-number);
// `wavelengthNm` selects each glass's index (n_d where the lens has no Abbe numbers).
struct LensTrace {
  std::optional<double> stopDiameterMm;
  double wavelengthNm = kLineDNm;
  // Analysis only: no rim stops the ray (the stop still does unless `endAtStop`).
  bool ignoreRims = false;
  // Analysis only: end at the stop's plane, returning where the ray meets it (unclipped).
  bool endAtStop = false;
  // Pictures: when given, each point where the ray meets a surface is appended.
  std::vector<glm::dvec3>* path = nullptr;
};
std::optional<LensRay> traceLens(const LensPrescription& lens, const LensRay& ray, bool toScene,
                                 const LensTrace& options = {});

}  // namespace lenslab
