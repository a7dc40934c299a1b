#pragma once
// A camera with a real lens: a sensor behind a lens prescription, placed in the world. For each
// point of the film and each sample of the exit pupil, the ray leaves the lens into the scene
// (lens/ExitPupil); this is what the ray caster casts for `raycast --lens`, the reference image of
// that lens. Pure math (GLM + std), no GL.
//
// Placement: the entrance pupil's centre is the camera's eye (the point all chief rays aim at from
// the scene, the lecture's PRP), the axis along `forward`. The film is inverted behind the lens: a
// scene point up and to the right lands down and to the left on the film, and the image is the
// film seen from behind, upright.
#include "lens/ExitPupil.h"
#include "lens/LensPrescription.h"

#include <glm/glm.hpp>

#include <array>
#include <memory>
#include <optional>

namespace lenslab {

struct LensCameraPose {
  glm::dvec3 eye{0.0};                 // where the entrance pupil's centre is, world
  glm::dvec3 right{1.0, 0.0, 0.0};     // unit, world
  glm::dvec3 up{0.0, 1.0, 0.0};        // unit, world, ⟂ right
  glm::dvec3 forward{0.0, 0.0, -1.0};  // unit, world: right × up
  double worldPerMm = 1e-3;            // the scene's units per millimetre (metres: 1e-3)
};

struct LensCameraSettings {
  glm::dvec2 sensorMm{36.0, 24.0};
  double focusDistance = INFINITY;  // world units, from the entrance pupil; +inf: infinity
  std::optional<double> fNumber;    // paraxial; the design's full opening when not given
};

// Wavelengths a channel is traced at when the lens has Abbe numbers (nm).
constexpr std::array<double, 3> kChannelWavelengthsNm = {610.0, 550.0, 465.0};

class LensCamera {
 public:
  LensCamera(std::shared_ptr<const LensPrescription> lens, const LensCameraSettings& settings,
             const LensCameraPose& pose);

  struct WorldRay {
    glm::dvec3 origin;     // world, on the first surface
    glm::dvec3 direction;  // unit, world, into the scene
    double weight;         // relative illumination sample (ExitPupil's): 1 on the axis, on average
  };
  // The ray through continuous pixel position `pixel` (x right, y down, from the image's top-left
  // corner) of a width × height image, through pupil sample `u` ∈ [0, 1)², for `channel` (0 red,
  // 1 green, 2 blue; one wavelength for all without dispersion); nullopt where the lens stops it.
  std::optional<WorldRay> ray(glm::dvec2 pixel, int widthPx, int heightPx, glm::dvec2 u, int channel = 1) const;
  // The film point (mm, lens coordinates: the image turned by 180°) behind continuous pixel
  // position `pixel` of a width × height image, as ray() uses it.
  glm::dvec2 filmMmOf(glm::dvec2 pixel, int widthPx, int heightPx) const;
  // A ray in lens coordinates (mm; origin relative to the first vertex, z toward the film) placed
  // in the world: the origin as ray() places it, the direction made unit.
  WorldRay toWorld(const glm::dvec3& originMm, const glm::dvec3& direction, double weight) const;

  bool dispersion() const { return pupils_[0] != pupils_[1]; }
  const LensPrescription& lens() const { return *lens_; }
  double filmDistanceMm() const { return filmDistanceMm_; }  // last vertex → film
  double stopDiameterMm() const { return stopDiameterMm_; }
  const LensCameraPose& pose() const { return pose_; }
  const ExitPupil& pupil(int channel) const { return *pupils_[static_cast<std::size_t>(channel)]; }
  double entrancePupilMm() const { return entrancePupilMm_; }  // from the first vertex, along +z
  double halfDiagonalMm() const { return 0.5 * glm::length(settings_.sensorMm); }

 private:
  std::shared_ptr<const LensPrescription> lens_;
  LensCameraSettings settings_;
  LensCameraPose pose_;
  double filmDistanceMm_ = 0.0;
  double stopDiameterMm_ = 0.0;
  double entrancePupilMm_ = 0.0;
  std::array<std::shared_ptr<const ExitPupil>, 3> pupils_;  // per channel; one shared without dispersion
};

}  // namespace lenslab
