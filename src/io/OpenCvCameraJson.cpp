// The OpenCV form of a camera file: a calibrated camera, K (or "intrinsics"), R and t (or eye and
// target) and distCoeffs (io/CameraJson.h).
#include "io/CameraJsonForms.h"

#include "camera/Intrinsics.h"
#include "camera/Rotation.h"
#include "core/Error.h"
#include "core/NumberInput.h"
#include "core/Text.h"

#include <cmath>

namespace lenslab {

// The OpenCV form: intrinsics as "intrinsics" or "K" (+ "width", "height"), the pose as eye/target/up
// or R/t, OpenCV's distCoeffs as "dist" (or "distortion").
const std::set<std::string> kOpenCvFormKeys = {
    "eye",  "target", "up", "R", "t", "intrinsics", "K", "width", "height", "dist", "focus_distance", "aperture_radius",
    "near", "far"};
// Keys that only the OpenCV form takes: any of them selects it.
const std::set<std::string> kOpenCvOnlyKeys = {"intrinsics", "K", "R", "t", "dist"};

namespace {

const std::set<std::string> kIntrinsicsKeys = {"fx", "fy", "cx", "cy", "width", "height"};

// Focal lengths in pixels that lenslab draws: beyond 1e9 a field of view across the largest image
// is below a microradian, and the window's size (width / fx) underflows what later arithmetic holds
// (fx = 1e300 overflowed an integer in the fold-over check's message).
constexpr NumberRange kFocalLengthPx{.min = 1e-3, .max = 1e9, .unit = "pixels"};

// fx, fy in kFocalLengthPx and a size of 1 to kMaxImageSidePx a side; `reader` and the keys name
// them in messages.
void checkIntrinsics(const OpenCvIntrinsics& k, const JsonReader& reader, const std::string& fxKey,
                     const std::string& fyKey, const std::string& widthKey, const std::string& heightKey) {
  if (const auto problem = numberProblem(k.fx, kFocalLengthPx))
    reader.failNumber(fxKey, *problem, "the focal length in pixels");
  if (const auto problem = numberProblem(k.fy, kFocalLengthPx))
    reader.failNumber(fyKey, *problem, "the focal length in pixels");
  if (k.widthPx < 1 || k.widthPx > kMaxImageSidePx)
    reader.fail(widthKey, cat("is ", k.widthPx, "; use 1 to ", kMaxImageSidePx, " pixels"));
  if (k.heightPx < 1 || k.heightPx > kMaxImageSidePx)
    reader.fail(heightKey, cat("is ", k.heightPx, "; use 1 to ", kMaxImageSidePx, " pixels"));
}

// "intrinsics": {"fx", "fy", "cx", "cy", "width", "height"}.
OpenCvIntrinsics intrinsicsFromObject(const JsonReader& r) {
  if (r.has("width") || r.has("height"))
    r.fail(r.has("width") ? "width" : "height",
           "goes inside \"intrinsics\" in this form (beside a \"K\" matrix it stands alone)");
  const JsonReader o = r.child("intrinsics", kIntrinsicsKeys);
  for (const char* key : {"fx", "fy", "cx", "cy", "width", "height"}) o.require(key, "intrinsics");
  OpenCvIntrinsics k;
  k.fx = o.number("fx"), k.fy = o.number("fy"), k.cx = o.number("cx"), k.cy = o.number("cy");
  k.widthPx = o.integer("width"), k.heightPx = o.integer("height");
  checkIntrinsics(k, o, "fx", "fy", "width", "height");
  return k;
}

}  // namespace

// "image_size": [width, height], whole pixels from 1 to kMaxImageSidePx.
ImageSize imageSizeOf(const JsonReader& r) {
  const glm::dvec2 size = r.vector<2>("image_size");
  if (size != glm::floor(size) || size.x < 1 || size.y < 1 || size.x > kMaxImageSidePx || size.y > kMaxImageSidePx)
    r.fail("image_size", cat("must be [width, height] in whole pixels from 1 to ", kMaxImageSidePx));
  return ImageSize{static_cast<int>(size.x), static_cast<int>(size.y)};
}

namespace {

// "K": [[fx, 0, cx], [0, fy, cy], [0, 0, 1]], with "width" and "height" (or "image_size") beside it.
// The zeros must be zeros: K[0][1] is the skew, which a window of rectangular pixels cannot hold.
OpenCvIntrinsics intrinsicsFromMatrix(const JsonReader& r) {
  const RotationRows m = r.matrix3("K", "[[fx, 0, cx], [0, fy, cy], [0, 0, 1]]");
  if (m[0].y != 0.0)
    r.fail("K", cat("has skew K[0][1] = ", m[0].y,
                    "; lenslab's window has rectangular pixels and cannot hold skew: give 0 "
                    "(OpenCV's calibrateCamera never estimates it)"));
  if (m[1].x != 0.0) r.fail("K", cat("has K[1][0] = ", m[1].x, "; a camera matrix has 0 there"));
  if (m[2] != glm::dvec3(0.0, 0.0, 1.0))
    r.fail("K",
           cat("has the last row [", m[2].x, ", ", m[2].y, ", ", m[2].z, "]; a camera matrix has [0, 0, 1] there"));
  OpenCvIntrinsics k;
  k.fx = m[0].x, k.fy = m[1].y, k.cx = m[0].z, k.cy = m[1].z;
  const bool hasWidthHeight = r.has("width") || r.has("height");
  if (hasWidthHeight && r.has("image_size"))
    r.fail("image_size", "and \"width\"/\"height\" both give the image size; give one");
  if (hasWidthHeight) {
    r.require("width", "OpenCV \"K\"");
    r.require("height", "OpenCV \"K\"");
    k.widthPx = r.integer("width"), k.heightPx = r.integer("height");
    checkIntrinsics(k, r, "K", "K", "width", "height");
  } else if (r.has("image_size")) {
    const ImageSize size = imageSizeOf(r);
    k.widthPx = size.widthPx, k.heightPx = size.heightPx;
    checkIntrinsics(k, r, "K", "K", "image_size", "image_size");
  } else {
    throw InputError(cat(r.where(),
                         ": \"K\" needs the image size it was calibrated for: give \"width\" and \"height\" "
                         "(pixels), or \"image_size\": [width, height]"));
  }
  return k;
}

// R must be a rotation to this tolerance on every entry of R·Rᵀ − I: a matrix printed to 7
// significant digits (float precision, or OpenCV's and numpy's short formats) is off by about
// 1e-7 and passes; the view basis then rebuilds an exact rotation from its last two rows, moving
// the optical axis by at most ~1e-6 rad (0.001 px at a focal length of 1000 px). A matrix scaled,
// sheared or typed with four digits is refused rather than silently straightened.
constexpr double kRotationTolerance = 1e-6;

OpenCvPose poseFromRt(const JsonReader& r) {
  r.require("R", "OpenCV pose (R, t)");
  r.require("t", "OpenCV pose (R, t)");
  OpenCvPose pose;
  pose.rows = r.matrix3("R", "[[r00, r01, r02], [r10, r11, r12], [r20, r21, r22]]");
  pose.translation = r.vector<3>("t");
  const RotationCheck check = checkRotation(pose.rows);
  if (!(check.orthonormalityError <= kRotationTolerance))
    r.fail("R", cat("is not a rotation: R·Rᵀ differs from the identity by ", check.orthonormalityError, " (at most ",
                    kRotationTolerance, " is accepted); give R with at least 7 significant digits"));
  if (!(check.determinant > 0.0))
    r.fail("R", cat("is a reflection (det R = ", check.determinant,
                    "), not a rotation: OpenCV's camera frame is "
                    "right-handed (x right, y down, z forward); give det R = +1"));
  return pose;
}

// The OpenCV form: intrinsics as "intrinsics" {fx, fy, cx, cy, width, height} or "K"; the pose as
// "eye", "target" (and "up"), or OpenCV's "R" and "t" (a world point X is at R·X + t in the camera

}  // namespace

// frame: x right, y down, z forward).
CameraFile parseOpenCv(const JsonReader& r) {
  if (r.has("intrinsics") && r.has("K")) r.fail("K", "and \"intrinsics\" both give the intrinsics; give one");
  if (!r.has("intrinsics") && !r.has("K"))
    throw InputError(cat(r.where(),
                         ": an OpenCV camera needs its intrinsics: \"K\" ([[fx, 0, cx], [0, fy, cy], [0, 0, 1]] "
                         "with \"width\" and \"height\") or \"intrinsics\" {fx, fy, cx, cy, width, height}"));
  const bool rt = r.has("R") || r.has("t");
  const bool look = r.has("eye") || r.has("target") || r.has("up");
  if (rt && look)
    r.fail(r.has("R") ? "R" : "t", "and \"eye\"/\"target\"/\"up\" both give the pose; give R and t, or eye and target");
  if (!rt && !look)
    throw InputError(cat(r.where(),
                         ": an OpenCV camera needs its pose: \"R\" and \"t\" (X_cam = R·X_world + t), or "
                         "\"eye\" and \"target\""));
  const OpenCvIntrinsics k = r.has("K") ? intrinsicsFromMatrix(r) : intrinsicsFromObject(r);

  PinholePlacement placement;
  double focus = 0.0, d = 0.0, defaultNear = 0.0;
  if (look) {
    r.require("eye", "OpenCV intrinsics");
    r.require("target", "OpenCV intrinsics");
    placement.eye = r.vector<3>("eye");
    const glm::dvec3 target = r.vector<3>("target");
    placement.vup = r.has("up") ? r.vector<3>("up") : glm::dvec3(0.0, 1.0, 0.0);
    const double toTarget = glm::length(target - placement.eye);
    if (!(toTarget > 0.0)) r.fail("target", "must differ from \"eye\"");
    placement.vpn = placement.eye - target;  // viewSpecOf normalises it
    focus = r.has("focus_distance") ? r.distance("focus_distance") : toTarget;
    if (!(focus > 0.0)) r.fail("focus_distance", cat("is ", focus, "; give a distance > 0 or \"infinity\""));
    // As for the physical form: the view plane is the plane of focus, unless focus lies beyond
    // kMaxViewPlaneMove × |target − eye| (or at infinity): then it is held as 1/z_f.
    d = viewPlaneDistanceFor(focus, toTarget);
    defaultNear = 0.05;
  } else {
    placement = placementOf(poseFromRt(r));
    // No target to focus on: a pinhole's view plane at unit distance, unless focus_distance says
    // where (a plane of focus further than kMaxViewPlaneMove units is held as 1/z_f).
    if (r.has("focus_distance")) {
      focus = r.distance("focus_distance");
      if (!(focus > 0.0)) r.fail("focus_distance", cat("is ", focus, "; give a distance > 0 or \"infinity\""));
    } else if (apertureRadiusOf(r) > 0.0) {
      r.fail("aperture_radius", "needs \"focus_distance\" beside \"R\" and \"t\" (there is no target to focus on)");
    } else {
      focus = 1.0;
    }
    d = viewPlaneDistanceFor(focus, 1.0);
    defaultNear = d * kDefaultNearPerViewPlaneDistance;  // this camera's scale is not known
  }
  ViewSpec spec = viewSpecOf(k, placement, d);
  spec.nearDistance = r.has("near") ? r.distance("near") : defaultNear;
  if (r.has("far")) spec.farDistance = r.distance("far");
  validate(spec, r.where());
  CameraFile file;
  file.form = CameraFile::Form::Intrinsics;
  file.camera = cameraFocusedOnViewPlane(spec, apertureRadiusOf(r), r.where());
  if (d != focus) file.camera.inverseFocusOffPlane = 1.0 / focus;
  file.camera.nearFromScene = !r.has("near");
  file.camera.farFromScene = !r.has("far");
  file.camera.calibratedSize = ImageSize{k.widthPx, k.heightPx};
  return file;
}

}  // namespace lenslab
