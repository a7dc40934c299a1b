#pragma once
// The camera's lens as one value: how large its aperture is, its shape, the barrel in front of it
// and the effects of a real lens on the image. A camera holds one (camera/Camera.h); the lens
// effects' modules read, write, interpolate and plan it (lens/effects/LensEffectModule.h); a
// camera path's key carries one beside its physical description (camera/CameraPath.h).
//
// The focus is not here: the lecture's thin lens keeps the plane of focus on the view plane, so the
// view carries it (Camera::inverseFocusDistance).
#include "lens/ApertureShape.h"
#include "lens/LensBarrel.h"
#include "lens/LensEffects.h"

#include <glm/glm.hpp>

namespace lenslab {

struct Lens {
  double apertureRadius = 0.0;  // world units; 0 = pinhole
  ApertureShape aperture;       // round unless the camera has blades or a squeeze (lens/ApertureShape.h)
  LensBarrel barrel;    // the barrel's opening in front of the aperture: cat's-eye vignetting (lens/LensBarrel.h)
  LensEffects effects;  // distortion, chromatic aberration, field curvature, vignetting (lens/LensEffects.h)

  bool isPinhole() const { return !(apertureRadius > 0.0); }
  // Whether the barrel clips the aperture anywhere: a pinhole has no aperture to clip.
  bool hasBarrel() const { return barrel.present() && !isPinhole(); }
  // The lens offset (u, v; world units) of an aperture sample's point on the unit disk: the
  // aperture's shape applied, scaled by the radius. Both renderers place the PRP through this.
  glm::dvec2 lensOffset(glm::dvec2 unitDisk) const {
    return apertureRadius * (aperture.isRound() ? unitDisk : apertureFromDisk(unitDisk, aperture));
  }
};

}  // namespace lenslab
