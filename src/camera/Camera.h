#pragma once
// Everything the renderers need to know about the camera: the lecture's viewing description and
// the thin lens. Where it came from is kept for messages and --stats.
//
// The view plane is the plane of focus (../shared/ARCHITECTURE.md). A thin lens is the same camera
// with the PRP moved to a point of the aperture disk, in the PRP's plane (parallel to the view
// plane), while the window stays where it is: every point of the view plane then lands on the same
// pixel from every aperture point, and any other point spreads over its circle of confusion.
#include "camera/ImageSize.h"
#include "camera/ViewSpec.h"
#include "lens/Lens.h"

#include <glm/glm.hpp>

#include <optional>

#include <string>

namespace lenslab {

struct Camera {
  ViewSpec view;
  // The aperture's radius (0: a pinhole) and shape, the barrel and the lens effects (perspective
  // only; lens/LensEffects.h), as one value (lens/Lens.h).
  Lens lens;
  // The plane of focus is the view plane, except where no well-conditioned view plane can hold
  // it: at infinity focus, and at a finite focus far beyond the view plane (a view plane at 1e300
  // has a window of 1e300 and no precision left). There the focus is carried as an inverse
  // distance 1/z_f (0 at infinity) and the window travels by 1 − d/z_f of each lens offset (see
  // viewThroughLens), so a huge focus distance tends to infinity focus smoothly.
  std::optional<double> inverseFocusOffPlane;
  std::string source;  // "assets/rows/camera.json", "glTF camera 0 (Main)", ...
  // The camera's file left near / far open: withDepthRangeFitted (camera/DepthRange.h) fits them
  // to the scene before rendering, so that the depth buffer's precision lands where the scene is.
  bool nearFromScene = false;
  bool farFromScene = false;
  // The image size the camera was calibrated for (OpenCV intrinsics), the default render size.
  std::optional<ImageSize> calibratedSize;

  // 1/z_f, from the PRP along −n: 1/PRP.n on the view plane, 0 at infinity focus.
  double inverseFocusDistance() const { return inverseFocusOffPlane ? *inverseFocusOffPlane : 1.0 / view.prp.z; }
  bool focusAtInfinity() const { return inverseFocusDistance() == 0.0; }
  // z_f, +infinity at infinity focus.
  double focusDistance() const;
};

// The image size for a camera: a calibrated camera's own size (scaled to a given width or height),
// else resolveImageSize from the window (with `defaultWidthPx` when no side is given).
ImageSize resolveImageSize(const Camera& camera, std::optional<int> widthPx, std::optional<int> heightPx,
                           int defaultWidthPx = kDefaultWidthPx);

// The warning for `size` (resolveImageSize's answer to the sides given) when it stretches the
// camera's pixels: out of square, or for a calibrated camera out of its calibrated shape
// (pixelShapeWarning in camera/ImageSize.h); empty when they keep their shape.
std::string pixelShapeWarning(const Camera& camera, std::optional<int> widthPx, std::optional<int> heightPx,
                              ImageSize size);

// A camera whose plane of focus is its view plane.
Camera cameraFocusedOnViewPlane(const ViewSpec& view, double apertureRadius, std::string source);

// The view from one point of the aperture: the PRP moved by lensOffset (u, v; world units) in its
// plane, the window kept on the plane of focus, and the window also shifted by pixelOffset
// (window units) for sub-pixel jitter. For focus at inverse distance φ and view plane at d = PRP.n
// the window moves by lensOffset·(1 − d·φ): not at all when the view plane is the plane of focus,
// with the PRP when focus is at infinity. `inverseFocusShift` is added to φ: how one colour
// channel (axial chromatic aberration) or one part of the image (field curvature) is focused.
ViewSpec viewThroughLens(const Camera& camera, glm::dvec2 lensOffset, glm::dvec2 pixelOffset,
                         double inverseFocusShift = 0.0);

// Diameter, in window units on the view plane, of the circle of confusion of a point at `depth`
// (world units from the PRP along −n): every aperture point sees it through a different window
// point. Perspective: 2R·d·|1/z_f − 1/z| with d = PRP.n (2R·|z − z_f|/z when the view plane is the
// plane of focus). Parallel: the DOP tilts by the lens offset over PRP.n, so 2R·|z − PRP.n|/PRP.n.
// `inverseFocusShift` as for viewThroughLens. A shaped aperture (blades, squeeze): the diameter of
// the circle about the blur that holds it, from the shape's farthest point (apertureReach).
double cocDiameterOnWindow(const Camera& camera, double depth, double inverseFocusShift = 0.0);

// How far beyond the current view plane refocused() still moves the view plane; beyond this the
// focus is carried as 1/z_f with the view plane left where it is (as at infinity).
constexpr double kMaxViewPlaneMove = 1e3;

// Where a camera puts its view plane for focus at `focusDistance` (+infinity allowed): on the
// plane of focus up to kMaxViewPlaneMove × `nearDistance` (the current view plane, or the target),
// else at `nearDistance`, the focus then carried as 1/z_f. The one rule for refocusing and for
// the physical and intrinsics forms.
double viewPlaneDistanceFor(double focusDistance, double nearDistance);

// Moves the plane of focus to `distance` (world units along −n from the PRP; +infinity allowed for
// perspective). Up to kMaxViewPlaneMove × PRP.n the view plane moves to the plane of focus and the
// window scales about the principal point (the field of view is kept); further out the view plane
// stays and the focus is held as 1/z_f. Throws InputError naming `where` for a distance ≤ 0, or a
// parallel projection focused at infinity.
Camera refocused(const Camera& camera, double distance, const std::string& where);

}  // namespace lenslab
