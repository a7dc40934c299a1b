#pragma once
// A perspective camera's pinhole intrinsics in OpenCV's convention, for vision tools: the camera
// matrix K = [fx 0 cx; 0 fy cy; 0 0 1] of an image `width` × `height` pixels, pixel centres on
// integers with (0, 0) the centre of the top-left pixel and y down. The lecture's viewing model
// gives them directly: the PRP is the pinhole, its distance d to the view plane the focal length,
// so a window w wide spread over W pixels makes fx = d·W / w. For a thin lens focused at z_f that d
// is the image distance z_i scaled onto the plane of focus, which is what a calibration measures.
// The inverse is the OpenCV-intrinsics camera form (io/CameraJson.h).
#include "camera/ImageSize.h"
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
  std::array<glm::dvec3, 3> rows;  // R, row by row
  glm::dvec3 translation{0.0};     // t
};
OpenCvPose poseOf(const ViewSpec& view);

}  // namespace lenslab
