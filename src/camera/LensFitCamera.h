#pragma once
// The rasterizer's camera for a real lens fitted by lens/LensFit: the lecture's thin lens placed at
// the lens's entrance pupil (the PRP, where every chief ray aims from the scene), with the fit's
// pupil, focus, distortion, colour, field curvature and barrel, and the window the sensor spans
// through the fitted focal length F (normalised image coordinate = film position / F).
#include "camera/Camera.h"
#include "lens/LensFit.h"

#include <glm/glm.hpp>

#include <string>

namespace lenslab {

// `like`'s pose (VRP, VPN, VUP, the PRP's place across the view plane), everything else from the
// fit. `worldPerMm`: the scene's units per millimetre (metres: 1e-3). The fit must be usable.
Camera cameraForFittedLens(const Camera& like, const FittedLens& fit, glm::dvec2 sensorMm, double worldPerMm,
                           std::string source);

}  // namespace lenslab
