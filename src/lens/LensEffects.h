#pragma once
// The lecture's last part: real lenses are not pinholes. "Points are distorted geometrically from
// the true perspective position"; "points also become more blurred as they approach the edge of
// the image"; "the focal length of a lens is a function of the wavelength of the light".
//
// All three act in normalised image coordinates: the point where a ray from the PRP crosses a
// view plane at unit distance, measured from the principal point (the foot of the PRP on the view
// plane). In lenslab's eye frame that is (x, y) = (X/Z, Y/Z), x right and y UP. OpenCV's normalised
// coordinates are the same with y DOWN; the distortion below converts so that its coefficients
// mean exactly what they mean in OpenCV (a calibration's k1, k2, p1, p2, k3 can be used as given).
//
// Each effect's model and module live in lens/effects/ (LensEffectModule.h); LensEffects holds
// the four that act on the image, as one value.
#include "lens/effects/Chromatic.h"
#include "lens/effects/Distortion.h"
#include "lens/effects/FieldCurvature.h"
#include "lens/effects/Vignetting.h"

#include <glm/glm.hpp>

#include <optional>

namespace lenslab {

struct LensEffects {
  Distortion distortion;
  Chromatic chromatic;
  FieldCurvature fieldCurvature;
  Vignetting vignetting;

  bool isZero() const {
    return distortion.isZero() && !chromatic.hasLateral() && !chromatic.hasAxial() && fieldCurvature.isZero() &&
           vignetting.isZero();
  }
  // The post pass (distortion and lateral colour, both geometric remaps of the image) is needed.
  bool needsRemap() const { return !distortion.isZero() || chromatic.hasLateral(); }
  // Green's true perspective position of the channel-`c` image point `distorted` (normalised):
  // lateral colour undone, then the distortion. Empty where Newton fails.
  std::optional<glm::dvec2> undistortChannel(Channel c, glm::dvec2 distorted, glm::dvec2 guess) const;
  // Forward: where the true perspective position lands in channel `c`'s image.
  glm::dvec2 distortChannel(Channel c, glm::dvec2 undistorted) const;
  // Inverse focus distance of channel `c` for a pixel at true perspective position `undistorted`.
  double inverseFocusShift(Channel c, glm::dvec2 undistorted) const;
};

}  // namespace lenslab
