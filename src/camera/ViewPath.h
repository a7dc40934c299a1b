#pragma once
// A camera path whose keys are in the lecture or OpenCV form (camera/CameraPath.h): a calibrated
// camera that moves. Each key is read as a pinhole: where it stands, how it is turned, its
// intrinsics K and its lens. Between two keys:
//   position    as the physical keys' eye: centripetal Catmull–Rom ("smooth") or linear
//   rotation    spherical linear interpolation (slerp) of the keys' unit quaternions, the short
//               way round, in both modes
//   K           fx, fy, cx, cy linearly, at the keys' image size (every key gives the same size,
//               or none: a lecture key's window is read as K on a nominal 1000 × 1000 image)
//   focus       in inverse distance 1/z_f, as for the physical keys (monotone cubic or linear)
//   lens        each effect as its module interpolates it (distortion coefficients linearly),
//               the aperture radius linearly
//   near, far   linearly; an infinite far stays infinite
// A K, distortion or lens that the two keys share is held exactly (a + (b − a)·u is a when b is a):
// a calibrated camera keeps its calibration on every frame.
#include "camera/Camera.h"
#include "camera/CameraPath.h"
#include "camera/ImageSize.h"

#include <string_view>

namespace lenslab {

// The image size every key's K is read at: the keys' calibrated size, or the nominal 1000 × 1000.
constexpr ImageSize kNominalViewKeySize{1000, 1000};

// Throws InputError naming `where` and the key for a key that no pinhole path can hold: a parallel
// projection, a calibrated size unlike the first key's, an aperture shape or barrel unlike it.
void validateViewKeys(const std::vector<ViewPathKey>& keys, std::string_view where);

// The camera at `timeSeconds` of a path that holds view keys; `source` names it in messages.
// Throws InputError when the interpolated view is degenerate.
Camera viewCameraAt(const CameraPath& path, double timeSeconds, const std::string& source);

// Every frame's view built once before the first is drawn (the lens is checked as each frame's
// camera file is read back).
void validateViewFrames(const CameraPath& path, std::string_view where);

}  // namespace lenslab
