#include "camera/LensFitCamera.h"

#include "core/Error.h"
#include "core/Text.h"

#include <cmath>

namespace lenslab {

Camera cameraForFittedLens(const Camera& like, const FittedLens& fit, glm::dvec2 sensorMm, double worldPerMm,
                           std::string source) {
  if (!fit.usable) throw InputError(cat(source, ": no real-time camera holds this lens: ", fit.why));
  const double focusDistance = fit.inverseFocusPerMm > 0.0 ? worldPerMm / fit.inverseFocusPerMm : INFINITY;
  Camera camera = refocused(like, focusDistance, source);
  camera.source = std::move(source);
  // The whole lens is the fit's: the entrance pupil's radius, a round aperture, its barrel and effects.
  camera.lens = Lens{.apertureRadius = 0.5 * fit.entrancePupilDiameterMm * worldPerMm,
                     .aperture = ApertureShape{},
                     .barrel = fittedBarrel(fit, worldPerMm),
                     .effects = fittedEffects(fit, worldPerMm)};
  camera.calibratedSize.reset();
  // The window on the view plane at distance d = PRP.n: the sensor's half sides over F, times d,
  // about the principal point (a prescription's sensor is centred on its axis).
  const glm::dvec2 half = 0.5 * sensorMm / fit.focalLengthMm * camera.view.prp.z;
  const glm::dvec2 centre(camera.view.prp.x, camera.view.prp.y);
  camera.view.window = Window{centre.x - half.x, centre.y - half.y, centre.x + half.x, centre.y + half.y};
  return camera;
}

}  // namespace lenslab
