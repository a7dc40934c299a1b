#pragma once
// Sampling the light that reaches a film point through a real lens: rays from the film point
// aimed at points of a box on the plane of the last surface's vertex, traced to the scene. Only
// rays through every rim and the stop carry light, and from an off-axis point they pass through
// a small, shifted, cat's-eye-shaped part of the rear element: sampling the whole element would
// waste most rays. So the box is precomputed per ring of film radius — the exit pupil's bounds as
// seen from that ring — in the film point's own radial frame (x along its radius, y across it).
//
// Rings would appear in an image if a ring's box were computed at one radius only and missed rays
// that pass at another radius of the same ring. Each box is the union of the passing regions
// found at several radii across its ring, both ends included, grown by a search cell: it holds
// every passing ray of the ring (tests/lens/exit_pupil_test.cpp checks this against a search of
// the whole rear element). Pure math (GLM + std), no GL.
#include "lens/LensPrescription.h"
#include "lens/RealLens.h"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace lenslab {

struct PupilBox {
  glm::dvec2 lo{0.0}, hi{0.0};  // on the last vertex's plane, mm, in the radial frame
  bool empty() const { return !(lo.x < hi.x && lo.y < hi.y); }
  double area() const { return empty() ? 0.0 : (hi.x - lo.x) * (hi.y - lo.y); }
};

// A ray from the film into the scene, and what it carries: its projected solid angle at the film
// point (cos⁴α · box area / D² per unit of the sample square) over the axis's total, so that a
// uniformly bright scene gives 1 at the image's centre and the lens's relative illumination
// elsewhere.
struct FilmRay {
  LensRay ray;    // leaving the first surface toward the scene, lens coordinates (mm)
  double weight;  // the mean of weight over u is the film point's relative illumination
};

class ExitPupil {
 public:
  // For the film at axial position `filmZ` (mm) and film points out to `filmRadiusMm`, with the
  // stop and wavelength of `trace`. `rings` boxes over [0, filmRadiusMm].
  ExitPupil(const LensPrescription& lens, double filmZ, double filmRadiusMm, const LensTrace& trace, int rings = 64);

  // The box of film radius r (r beyond filmRadiusMm takes the last ring's).
  const PupilBox& boxAt(double radiusMm) const;
  // The ray from film point (x, y) (mm, lens coordinates) through the box at u ∈ [0, 1)², or
  // nullopt where a rim or the stop blocks it (weight 0: still one sample of the mean).
  std::optional<FilmRay> sample(glm::dvec2 filmMm, glm::dvec2 u) const;
  // The axis's irradiance, the weights' unit (dA·cos⁴α / D², integrated by a fine search).
  double axialIrradiance() const { return axialIrradiance_; }
  double filmZ() const { return filmZ_; }

 private:
  const LensPrescription* lens_;
  LensTrace trace_;
  double filmZ_;
  double filmRadiusMm_;
  double rearZ_;  // the plane the boxes lie on
  std::vector<PupilBox> boxes_;
  double axialIrradiance_ = 0.0;
};

// The irradiance at film radius r (dA·cos⁴α / D² over the rays that pass), by an n × n search of
// the whole rear element's neighbourhood: slow, for the constructor's normalisation and for tests.
double filmIrradianceBySearch(const LensPrescription& lens, double filmZ, double radiusMm, const LensTrace& trace,
                              int n);

}  // namespace lenslab
