#include "lens/LensCamera.h"

#include "core/Error.h"
#include "core/Text.h"
#include "lens/ParaxialLens.h"

#include <cmath>

namespace lenslab {

LensCamera::LensCamera(std::shared_ptr<const LensPrescription> lens, const LensCameraSettings& settings,
                       const LensCameraPose& pose)
    : lens_(std::move(lens)), settings_(settings), pose_(pose) {
  stopDiameterMm_ = stopDiameterForFNumber(*lens_, settings.fNumber);
  entrancePupilMm_ = firstOrder(*lens_).entrancePupilMm;
  // Focusing moves the film: the object lies focusDistance in front of the entrance pupil.
  const double focusMm = settings.focusDistance / pose.worldPerMm;
  filmDistanceMm_ = std::isinf(focusMm) ? filmDistanceForFocusMm(*lens_, INFINITY)
                                        : filmDistanceForObjectMm(*lens_, focusMm - entrancePupilMm_);
  const double filmZ = lens_->lengthMm() + filmDistanceMm_;
  const double halfDiagonal = 0.5 * glm::length(settings.sensorMm);
  LensTrace trace;
  trace.stopDiameterMm = stopDiameterMm_;
  if (lens_->hasDispersion()) {
    for (std::size_t c = 0; c < 3; ++c) {
      trace.wavelengthNm = kChannelWavelengthsNm[c];
      pupils_[c] = std::make_shared<ExitPupil>(*lens_, filmZ, halfDiagonal, trace);
    }
  } else {
    const auto pupil = std::make_shared<ExitPupil>(*lens_, filmZ, halfDiagonal, trace);
    pupils_ = {pupil, pupil, pupil};
  }
}

glm::dvec2 LensCamera::filmMmOf(glm::dvec2 pixel, int widthPx, int heightPx) const {
  // The image point (mm, right and up from the sensor's centre), and the film point behind the
  // lens that sees it: the film holds the image turned by 180°.
  const glm::dvec2 imageMm((pixel.x / widthPx - 0.5) * settings_.sensorMm.x,
                           (0.5 - pixel.y / heightPx) * settings_.sensorMm.y);
  return -imageMm;
}

LensCamera::WorldRay LensCamera::toWorld(const glm::dvec3& originMm, const glm::dvec3& direction, double weight) const {
  // Lens coordinates: x right, y up, z toward the film (backward), the entrance pupil at the eye.
  const auto world = [&](const glm::dvec3& v) { return v.x * pose_.right + v.y * pose_.up - v.z * pose_.forward; };
  const glm::dvec3 origin = pose_.eye + pose_.worldPerMm * world(originMm - glm::dvec3(0.0, 0.0, entrancePupilMm_));
  return WorldRay{origin, glm::normalize(world(direction)), weight};
}

std::optional<LensCamera::WorldRay> LensCamera::ray(glm::dvec2 pixel, int widthPx, int heightPx, glm::dvec2 u,
                                                    int channel) const {
  const std::optional<FilmRay> r =
      pupils_[static_cast<std::size_t>(channel)]->sample(filmMmOf(pixel, widthPx, heightPx), u);
  if (!r) return std::nullopt;
  return toWorld(r->ray.origin, r->ray.direction, r->weight);
}

}  // namespace lenslab
