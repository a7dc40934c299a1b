#pragma once
// The lens effects (lens/LensEffects.h) on a camera's image: whether a camera's effects can be
// rendered, the window in normalised coordinates, the planes of focus they add. Which pixel of the
// true perspective image each output pixel shows is the frame's image map's (camera/ImageMap.h):
// the raster path renders the true perspective image (with depth of field) over a window a little
// larger than the camera's (overscan: same centre, same pixel pitch, whole pixels added on each
// side) and carries each view's samples forward to where the lens puts them (ForwardTable), or
// remaps a single view through a table of the inverse positions (RemapTable), both filled here
// (LensMap.cpp) as the map's members. The ray caster casts each output sample's ray through the
// same inverse mapping, exactly, per sample (ThinLensMap::ray).
#include "camera/Camera.h"
#include "camera/ImageMap.h"
#include "camera/ImageSize.h"
#include "lens/LensEffects.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace lenslab {

// Throws InputError naming `where` when the camera's lens effects cannot be rendered: effects on a
// parallel projection, non-finite or out-of-range values, a channel's or the curved surface's plane
// of focus no nearer than `focalLength` (world units; without one, the aperture radius), or a
// distortion that folds over inside the image (see findFoldOver); the message says which field,
// what it is and what to change.
void validateLensEffects(const Camera& camera, const std::string& where,
                         std::optional<double> focalLength = std::nullopt);

// The normalised-coordinate rectangle covered by the camera's window.
struct NormalisedRect {
  glm::dvec2 min, max;
  double cornerRadius() const;  // distance of the farthest corner from the principal point
};
NormalisedRect normalisedWindow(const ViewSpec& view);

// The inverse focus shifts over which a camera's circle of confusion is largest: each colour's
// plane of focus (axial colour), flat and at the window's farthest corner (field curvature).
// A parallel projection has no corners to curve toward (its circle ignores the shift).
std::vector<double> extremeFocusShifts(const Camera& camera);

// Beyond this the samples of a rendered pixel land in the wrong output pixel, and the raster
// converges to a wrong image whatever the number of views (k1 = 1e6 on `rows` at 63 px: 196 px,
// a patchwork of a few samples where the ray caster shows a magnified floor). Measured on `rows` at 63 px, raster against a 1024-spp ray cast:
// 0.4 px (k1 = 100) reaches 36.7 dB at 2048 views and still rises; 2 px (k1 = 1000) stays at 23.6 dB.
constexpr double kMaxForwardLinearisationErrorPx = 0.5;

// The channels with a lens-pass table of their own: red, green and blue with lateral colour, else green.
std::vector<Channel> remappedChannels(const LensEffects& effects);

}  // namespace lenslab
