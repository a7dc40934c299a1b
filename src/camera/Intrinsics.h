#pragma once
// A perspective camera's pinhole intrinsics in OpenCV's convention, for vision tools: the camera
// matrix K = [fx 0 cx; 0 fy cy; 0 0 1] of an image `width` × `height` pixels, pixel centres on
// integers with (0, 0) the centre of the top-left pixel and y down. The lecture's viewing model
// gives them directly: the PRP is the pinhole, its distance d to the view plane the focal length,
// so a window w wide spread over W pixels makes fx = d·W / w. For a thin lens focused at z_f that d
// is the image distance z_i scaled onto the plane of focus, which is what a calibration measures.
// The inverse is the OpenCV-intrinsics camera form (io/CameraJson.h).
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "camera/Rotation.h"
#include "camera/ViewSpec.h"

#include <array>

namespace lenslab {

struct OpenCvIntrinsics {
  double fx = 0.0, fy = 0.0;  // pixels
  double cx = 0.0, cy = 0.0;  // pixels, OpenCV's centres-on-integers convention
  int widthPx = 0, heightPx = 0;
};

// Throws InputError for a parallel projection (it has no pinhole).
OpenCvIntrinsics intrinsicsOf(const ViewSpec& view, ImageSize size);

// The extrinsics that go with them: a world point X is at camera point R·X + t, the camera's x
// right (u), y down (−v) and z forward (−n, the optical axis), its origin the PRP. With K from
// intrinsicsOf, (x/z·fx + cx, y/z·fy + cy) is OpenCV's pixel of X: lenslab's pixel minus ½.
struct OpenCvPose {
  RotationRows rows;            // R, row by row
  glm::dvec3 translation{0.0};  // t
};
OpenCvPose poseOf(const ViewSpec& view);

// Where a pinhole stands and looks, in the lecture's terms.
struct PinholePlacement {
  glm::dvec3 eye{0.0};            // the PRP (the pinhole), world
  glm::dvec3 vpn{0.0, 0.0, 1.0};  // toward the viewer: the camera looks along −VPN
  glm::dvec3 vup{0.0, 1.0, 0.0};  // up in the image
};

// The placement of an OpenCV pose: the PRP is the camera centre −Rᵀt; OpenCV's z looks forward, so
// VPN = −(R's third row); its y runs down the image, so VUP = −(R's second row). R must be a
// rotation (det +1): its first row, x to the right, is then VUP × VPN, which the view basis rebuilds.
PinholePlacement placementOf(const OpenCvPose& pose);

// The viewing description of a pinhole with intrinsics `k` at `placement`, its view plane
// `viewPlaneDistance` in front of the PRP: VRP on the optical axis there, PRP (0, 0, d), and the
// window the image's border seen from the PRP, so that pixel (x, y) of OpenCV's convention is
// window point (d·(x − cx)/fx, −d·(y − cy)/fy). Near and far are left for the caller to set.
ViewSpec viewSpecOf(const OpenCvIntrinsics& k, const PinholePlacement& placement, double viewPlaneDistance);

// A pinhole camera from OpenCV's K, distortion and pose alone, with no focus or aperture: a COLMAP
// image's camera. Its view plane is at unit distance (a pinhole images every depth alike, and
// `--focus-distance` moves it like any camera's), near is 1/1000 of that and near and far are
// fitted to the scene (camera/DepthRange.h), and the calibrated size is k's. `source` names it
// in messages. Throws InputError naming `source` when the description is degenerate.
Camera pinholeFromOpenCv(const OpenCvIntrinsics& k, const Distortion& distortion, const OpenCvPose& pose,
                         const std::string& source);

}  // namespace lenslab
