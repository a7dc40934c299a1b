#pragma once
// glTF cameras in the lecture's terms. A glTF camera looks along its node's −Z with +Y up, from the
// node's origin; it has a field of view but no focus, so the caller chooses where the view plane
// (the plane of focus) lies: `focusDistance`, from the camera along its view direction.
#include "camera/ViewSpec.h"

#include <glm/glm.hpp>

namespace lenslab {

// Perspective: window half-height = focusDistance·tan(yfov/2), half-width = aspect × that.
ViewSpec viewSpecFromGltfPerspective(const glm::dmat4& worldFromCamera, double yfovRadians, double aspectRatio,
                                     double znear, double zfar, double focusDistance);

// Orthographic: window [−xmag, xmag] × [−ymag, ymag], DOP = −n (PRP over the window centre).
ViewSpec viewSpecFromGltfOrthographic(const glm::dmat4& worldFromCamera, double xmag, double ymag, double znear,
                                      double zfar, double focusDistance);

}  // namespace lenslab
