#pragma once
// A real lens as the image commands take it (--lens FILE): the prescription placed where the
// camera's lens centre is, looking along its axis, with the camera's sensor (a physical camera's,
// else 36 mm wide at the window's aspect), f-number (the design's full opening where the camera
// has none) and focus distance; and the real-time thin lens fitted to it (lens/LensFit.h).
#include "camera/Camera.h"
#include "camera/PhysicalCamera.h"
#include "lens/LensCamera.h"
#include "lens/LensFit.h"
#include "lens/LensPrescription.h"
#include "plan/CameraOptions.h"
#include "scene/Scene.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace lenslab {

struct LensRequest {
  std::shared_ptr<const LensPrescription> lens;
  LensCameraSettings settings;
  LensCameraPose pose;
};

// Refuses, in one line naming --lens and the file, a camera that cannot take a prescription: a
// parallel projection, lens effects or a barrel of its own (the lens has its own), a shaped
// aperture, a window shifted off the axis.
LensRequest lensRequestFor(const std::string& file, const SelectedCamera& selected, const Camera& camera);

// The camera options for --lens `file` where automatic framing places the camera (no camera
// file, no glTF or COLMAP camera): the prescription's own focal length, so that the subject is
// framed in the field the lens renders (not the default 35 mm's). Unchanged otherwise, and where
// --focal-length is given.
CameraOptions framingForLens(CameraOptions options, const std::string& file, const Scene& scene, bool cameraFile);

LensCamera lensCameraFor(const LensRequest& request);
FittedLens fitFor(const LensRequest& request);

// The fit's worst error (LensFitError::worstUm) in pixels of an image `widthPx` wide; infinite
// where no thin lens fits.
double fitErrorPx(const FittedLens& fit, const LensRequest& request, int widthPx);

// The thin-lens camera fitted to the lens, at `camera`'s pose (camera/LensFitCamera.h): what the
// frame's real-lens map (camera/ImageMap.h, RealLensMap) holds as its real-time form, fitted().
Camera fittedCameraFor(const LensRequest& request, const FittedLens& fit, const Camera& camera,
                       const std::string& file);

// Why the fitted lens's focus distance is not the one asked for: the film is placed where the
// lens's first-order (paraxial) image of the asked plane lies, and the traced rays through the
// whole stop are sharpest on the axis elsewhere (spherical aberration moves best focus); the thin
// lens is fitted to where the real lens is sharpest. Empty when the two agree within 0.5 %
// (of the inverse distances, so that infinity compares too). For --stats' "lens".
struct FocusExplanation {
  double askedDistance = 0.0;  // world units from the entrance pupil; +infinity allowed
  std::string note;
};
FocusExplanation focusExplanation(const LensRequest& request, const FittedLens& fit);

// The fitted camera with each of its effects left out in turn, named ("distortion", "barrel",
// ...): what each effect of the fit is worth against the exact lens (sweep --lens). Effects the
// fit left at zero are not listed.
std::vector<std::pair<std::string, Camera>> fittedCameraAblations(const Camera& fitted);

}  // namespace lenslab
