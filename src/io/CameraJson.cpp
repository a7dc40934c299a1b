#include "io/CameraJson.h"

#include "io/JsonDocument.h"

#include "camera/Exposure.h"
#include "camera/Intrinsics.h"
#include "camera/LensMap.h"
#include "camera/Rotation.h"
#include "core/Error.h"
#include "core/NumberInput.h"
#include "core/Text.h"
#include "core/TextFile.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <tuple>
#include <set>
#include <sstream>
#include <vector>

namespace lenslab {
namespace {

using nlohmann::json;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Camera files nest two levels ("distortion": {...}); far deeper is refused, not recursed into.

const std::set<std::string> kLectureKeys = {"projection", "vrp", "vpn", "vup", "prp", "window", "near", "far",
                                            "aperture_radius", "focus_distance"};
const std::set<std::string> kPhysicalKeys = {"eye", "target", "up", "focal_length_mm", "sensor_mm",
                                             "f_number", "focus_distance", "near", "far",
                                             "shutter_s", "iso"};
// The OpenCV form: intrinsics as "intrinsics" or "K" (+ "width", "height"), the pose as eye/target/up
// or R/t, OpenCV's distCoeffs as "dist" (or "distortion").
const std::set<std::string> kOpenCvFormKeys = {"eye", "target", "up", "R", "t", "intrinsics", "K", "width", "height",
                                               "dist", "focus_distance", "aperture_radius", "near", "far"};
// Keys that only the OpenCV form takes: any of them selects it.
const std::set<std::string> kOpenCvOnlyKeys = {"intrinsics", "K", "R", "t", "dist"};
// Lens effects and the image size, in any form.
const std::set<std::string> kCommonKeys = {"distortion", "chromatic", "field_curvature", "image_size", "aperture", "barrel", "vignetting"};
const std::set<std::string> kBarrelKeys = {"distance_mm", "diameter_mm"};
const std::set<std::string> kApertureKeys = {"blades", "rotation_deg", "roundness", "anamorphic_squeeze"};
const std::set<std::string> kDistortionKeys = {"k1", "k2", "p1", "p2", "k3", "alpha", "beta", "gamma"};
const std::set<std::string> kChromaticKeys = {"lateral_red", "lateral_blue", "focus_distance_red",
                                              "focus_distance_blue", "abbe_number"};
const std::set<std::string> kFieldCurvatureKeys = {"corner_focus_distance"};
const std::set<std::string> kVignettingKeys = {"a1", "a2", "a3"};
const std::set<std::string> kIntrinsicsKeys = {"fx", "fy", "cx", "cy", "width", "height"};

std::string joined(const std::set<std::string>& keys) {
  std::string s;
  for (const std::string& k : keys) s += (s.empty() ? "" : ", ") + k;
  return s;
}

class Reader {
 public:
  Reader(const json& object, std::string where, std::string prefix = "")
      : object_(object), where_(std::move(where)), prefix_(std::move(prefix)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw InputError(cat(where_, ": \"", prefix_, key, "\" ", message));
  }

  // A number's problem (core/NumberInput's words): "<where>: \"key\": 1e+300 is out of range; ...".
  // `what`, when given, says what the key holds: "\"K\" (the focal length in pixels): -500 is ...".
  [[noreturn]] void failNumber(const std::string& key, const std::string& problem, const std::string& what = "") const {
    throw InputError(cat(where_, ": \"", prefix_, key, "\"", what.empty() ? "" : cat(" (", what, ")"), ": ", problem));
  }

  bool has(const std::string& key) const { return object_.contains(key); }

  double number(const std::string& key) const {
    const json& v = object_.at(key);
    if (!v.is_number()) fail(key, cat("must be a number, not ", excerpt(v.dump())));
    // core/NumberInput's finiteness rule (JSON has no nan, but 1e309 reads as infinity).
    if (const auto problem = numberProblem(v.get<double>(), NumberRange{})) failNumber(key, *problem);
    return v.get<double>();
  }

  // A number, or the string "infinity".
  double distance(const std::string& key) const {
    const json& v = object_.at(key);
    if (v.is_string() && v.get<std::string>() == "infinity") return kInfinity;
    if (!v.is_number()) fail(key, cat("must be a number or \"infinity\", not ", excerpt(v.dump())));
    return number(key);
  }

  template <int N>
  glm::vec<N, double> vector(const std::string& key) const {
    const json& v = object_.at(key);
    if (!v.is_array() || v.size() != N) fail(key, cat("must be an array of ", N, " numbers, not ", excerpt(v.dump())));
    glm::vec<N, double> out;
    for (int i = 0; i < N; ++i) {
      if (!v[static_cast<std::size_t>(i)].is_number()) fail(key, cat("must be an array of ", N, " numbers, not ", excerpt(v.dump())));
      out[i] = v[static_cast<std::size_t>(i)].get<double>();
      if (!std::isfinite(out[i])) fail(key, "must hold finite numbers");
    }
    return out;
  }

  // A 3×3 matrix given row by row, [[a, b, c], [d, e, f], [g, h, i]], of finite numbers.
  RotationRows matrix3(const std::string& key, const std::string& shape) const {
    const json& v = object_.at(key);
    const auto bad = [&] { fail(key, cat("must be a 3×3 matrix given row by row, ", shape, ", of finite numbers, not ", excerpt(v.dump()))); };
    if (!v.is_array() || v.size() != 3) bad();
    RotationRows m;
    for (std::size_t i = 0; i < 3; ++i) {
      if (!v[i].is_array() || v[i].size() != 3) bad();
      for (std::size_t c = 0; c < 3; ++c) {
        if (!v[i][c].is_number()) bad();
        m[i][static_cast<int>(c)] = v[i][c].get<double>();
        if (!std::isfinite(m[i][static_cast<int>(c)])) bad();
      }
    }
    return m;
  }

  std::string string(const std::string& key) const {
    const json& v = object_.at(key);
    if (!v.is_string()) fail(key, cat("must be a string, not ", excerpt(v.dump())));
    return v.get<std::string>();
  }

  int integer(const std::string& key) const {
    const json& v = object_.at(key);
    if (!v.is_number_integer()) fail(key, cat("must be a whole number, not ", excerpt(v.dump())));
    // get<int>() wraps what int cannot hold (4294967297 would be read as 1): refused instead.
    const bool fits = v.is_number_unsigned() ? v.get<std::uint64_t>() <= INT_MAX
                                             : v.get<std::int64_t>() >= INT_MIN && v.get<std::int64_t>() <= INT_MAX;
    if (!fits) fail(key, cat("is ", excerpt(v.dump()), "; give a whole number from ", INT_MIN, " to ", INT_MAX));
    return v.get<int>();
  }

  // The object under `key`, read with keys named "key.sub" in messages; unknown keys are errors.
  Reader object(const std::string& key, const std::set<std::string>& allowed) const {
    const json& v = object_.at(key);
    if (!v.is_object()) fail(key, cat("must be an object with keys among ", joined(allowed), ", not ", excerpt(v.dump())));
    for (const auto& item : v.items())
      if (allowed.count(item.key()) == 0)
        throw InputError(cat(where_, ": unknown key \"", key, ".", excerpt(item.key()), "\"; \"", key, "\" takes ", joined(allowed)));
    return Reader(v, where_, key + ".");
  }

  const json& raw(const std::string& key) const { return object_.at(key); }

  void require(const std::string& key, const std::string& form) const {
    if (!has(key)) throw InputError(cat(where_, ": \"", prefix_, key, "\" is missing; the ", form, " form needs it"));
  }

  const std::string& where() const { return where_; }

 private:
  const json& object_;
  std::string where_;
  std::string prefix_;  // "distortion." inside a nested object
};

// "aperture_radius" (world units), 0 when absent: a pinhole.
double apertureRadiusOf(const Reader& r) {
  if (!r.has("aperture_radius")) return 0.0;
  const double aperture = r.number("aperture_radius");
  if (aperture < 0.0) r.fail("aperture_radius", cat("is ", aperture, "; give a radius ≥ 0 in world units (0 = pinhole)"));
  return aperture;
}

CameraFile parseLecture(const Reader& r) {
  for (const char* key : {"vrp", "vpn", "prp", "window"}) r.require(key, "lecture");
  ViewSpec spec;
  if (r.has("projection")) {
    const std::string p = r.string("projection");
    if (p == "perspective") spec.projection = Projection::Perspective;
    else if (p == "parallel") spec.projection = Projection::Parallel;
    else r.fail("projection", cat("is \"", p, "\"; use \"perspective\" or \"parallel\""));
  }
  spec.vrp = r.vector<3>("vrp");
  spec.vpn = r.vector<3>("vpn");
  if (r.has("vup")) spec.vup = r.vector<3>("vup");
  spec.prp = r.vector<3>("prp");
  const glm::dvec4 w = r.vector<4>("window");
  spec.window = {w.x, w.y, w.z, w.w};
  const bool perspective = spec.projection == Projection::Perspective;
  const double defaultNear = perspective ? spec.prp.z * kDefaultNearPerViewPlaneDistance : 0.0;
  spec.nearDistance = r.has("near") ? r.distance("near") : defaultNear;
  if (r.has("far")) spec.farDistance = r.distance("far");
  else if (!perspective) r.require("far", "parallel-projection lecture");
  validate(spec, r.where());
  const double aperture = apertureRadiusOf(r);
  CameraFile file;
  file.camera = cameraFocusedOnViewPlane(spec, aperture, r.where());
  file.camera.nearFromScene = perspective && !r.has("near");
  file.camera.farFromScene = !r.has("far");
  // The view plane is the plane of focus unless focus_distance says otherwise: then the focus goes
  // through refocused(), the same path as --focus-distance (infinity and far focus as 1/z_f).
  if (r.has("focus_distance")) file.camera = refocused(file.camera, r.distance("focus_distance"), r.where() + ": focus_distance");
  // A lens focused at distance d has a focal length below d, and no lens is faster than f/0.5
  // (radius ≤ focal length): its aperture radius is below d.
  if (const double focus = r.has("focus_distance") ? r.distance("focus_distance") : spec.prp.z;
      perspective && aperture > 0.0 && std::isfinite(focus) && !(aperture < focus))
    r.fail("aperture_radius", cat("is ", aperture, " for a lens focused at ", focus,
                                  "; a lens focused there has a focal length below that distance and an aperture radius no larger "
                                  "than its focal length: give a radius below ", focus));
  return file;
}

CameraFile parsePhysical(const Reader& r) {
  r.require("eye", "physical");
  r.require("target", "physical");
  PhysicalCamera c;
  c.eye = r.vector<3>("eye");
  c.target = r.vector<3>("target");
  if (r.has("up")) c.up = r.vector<3>("up");
  if (r.has("focal_length_mm")) c.focalLengthMm = r.number("focal_length_mm");
  if (r.has("sensor_mm")) c.sensorMm = r.vector<2>("sensor_mm");
  if (r.has("f_number")) c.fNumber = r.number("f_number");
  c.focusDistance = r.has("focus_distance") ? r.distance("focus_distance") : glm::length(c.target - c.eye);
  if (r.has("near")) c.nearDistance = r.distance("near");
  if (r.has("far")) c.farDistance = r.distance("far");
  // The exposure's settings (camera/Exposure.h); what they need of the rest is checked where the
  // exposure is resolved, after the command line's options.
  for (const auto& [key, range, field] : {std::tuple{"shutter_s", kShutterSecondsRange, &c.shutterSeconds},
                                          std::tuple{"iso", kIsoRange, &c.iso}})
    if (r.has(key)) {
      const double value = r.number(key);
      if (const auto problem = numberProblem(value, range)) r.failNumber(key, *problem);
      *field = value;
    }
  validate(c, r.where());
  CameraFile file;
  file.form = CameraFile::Form::Physical;
  file.physical = c;
  file.camera = toCamera(c, r.where());
  file.camera.nearFromScene = !r.has("near");
  file.camera.farFromScene = !r.has("far");
  validate(file.camera.view, r.where());
  return file;
}

// Focal lengths in pixels that lenslab draws: beyond 1e9 a field of view across the largest image
// is below a microradian, and the window's size (width / fx) underflows what later arithmetic holds
// (fx = 1e300 overflowed an integer in the fold-over check's message).
constexpr NumberRange kFocalLengthPx{.min = 1e-3, .max = 1e9, .unit = "pixels"};

// fx, fy in kFocalLengthPx and a size of 1 to kMaxImageSidePx a side; `reader` and the keys name
// them in messages.
void checkIntrinsics(const OpenCvIntrinsics& k, const Reader& reader, const std::string& fxKey, const std::string& fyKey,
                     const std::string& widthKey, const std::string& heightKey) {
  if (const auto problem = numberProblem(k.fx, kFocalLengthPx)) reader.failNumber(fxKey, *problem, "the focal length in pixels");
  if (const auto problem = numberProblem(k.fy, kFocalLengthPx)) reader.failNumber(fyKey, *problem, "the focal length in pixels");
  if (k.widthPx < 1 || k.widthPx > kMaxImageSidePx)
    reader.fail(widthKey, cat("is ", k.widthPx, "; use 1 to ", kMaxImageSidePx, " pixels"));
  if (k.heightPx < 1 || k.heightPx > kMaxImageSidePx)
    reader.fail(heightKey, cat("is ", k.heightPx, "; use 1 to ", kMaxImageSidePx, " pixels"));
}

// "intrinsics": {"fx", "fy", "cx", "cy", "width", "height"}.
OpenCvIntrinsics intrinsicsFromObject(const Reader& r) {
  if (r.has("width") || r.has("height"))
    r.fail(r.has("width") ? "width" : "height", "goes inside \"intrinsics\" in this form (beside a \"K\" matrix it stands alone)");
  const Reader o = r.object("intrinsics", kIntrinsicsKeys);
  for (const char* key : {"fx", "fy", "cx", "cy", "width", "height"}) o.require(key, "intrinsics");
  OpenCvIntrinsics k;
  k.fx = o.number("fx"), k.fy = o.number("fy"), k.cx = o.number("cx"), k.cy = o.number("cy");
  k.widthPx = o.integer("width"), k.heightPx = o.integer("height");
  checkIntrinsics(k, o, "fx", "fy", "width", "height");
  return k;
}

// "image_size": [width, height], whole pixels from 1 to kMaxImageSidePx.
ImageSize imageSizeOf(const Reader& r) {
  const glm::dvec2 size = r.vector<2>("image_size");
  if (size != glm::floor(size) || size.x < 1 || size.y < 1 || size.x > kMaxImageSidePx || size.y > kMaxImageSidePx)
    r.fail("image_size", cat("must be [width, height] in whole pixels from 1 to ", kMaxImageSidePx));
  return ImageSize{static_cast<int>(size.x), static_cast<int>(size.y)};
}

// "K": [[fx, 0, cx], [0, fy, cy], [0, 0, 1]], with "width" and "height" (or "image_size") beside it.
// The zeros must be zeros: K[0][1] is the skew, which a window of rectangular pixels cannot hold.
OpenCvIntrinsics intrinsicsFromMatrix(const Reader& r) {
  const RotationRows m = r.matrix3("K", "[[fx, 0, cx], [0, fy, cy], [0, 0, 1]]");
  if (m[0].y != 0.0)
    r.fail("K", cat("has skew K[0][1] = ", m[0].y, "; lenslab's window has rectangular pixels and cannot hold skew: give 0 "
                    "(OpenCV's calibrateCamera never estimates it)"));
  if (m[1].x != 0.0) r.fail("K", cat("has K[1][0] = ", m[1].x, "; a camera matrix has 0 there"));
  if (m[2] != glm::dvec3(0.0, 0.0, 1.0))
    r.fail("K", cat("has the last row [", m[2].x, ", ", m[2].y, ", ", m[2].z, "]; a camera matrix has [0, 0, 1] there"));
  OpenCvIntrinsics k;
  k.fx = m[0].x, k.fy = m[1].y, k.cx = m[0].z, k.cy = m[1].z;
  const bool hasWidthHeight = r.has("width") || r.has("height");
  if (hasWidthHeight && r.has("image_size")) r.fail("image_size", "and \"width\"/\"height\" both give the image size; give one");
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
    throw InputError(cat(r.where(), ": \"K\" needs the image size it was calibrated for: give \"width\" and \"height\" "
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

OpenCvPose poseFromRt(const Reader& r) {
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
    r.fail("R", cat("is a reflection (det R = ", check.determinant, "), not a rotation: OpenCV's camera frame is "
                    "right-handed (x right, y down, z forward); give det R = +1"));
  return pose;
}

// The OpenCV form: intrinsics as "intrinsics" {fx, fy, cx, cy, width, height} or "K"; the pose as
// "eye", "target" (and "up"), or OpenCV's "R" and "t" (a world point X is at R·X + t in the camera
// frame: x right, y down, z forward).
CameraFile parseOpenCv(const Reader& r) {
  if (r.has("intrinsics") && r.has("K")) r.fail("K", "and \"intrinsics\" both give the intrinsics; give one");
  if (!r.has("intrinsics") && !r.has("K"))
    throw InputError(cat(r.where(), ": an OpenCV camera needs its intrinsics: \"K\" ([[fx, 0, cx], [0, fy, cy], [0, 0, 1]] "
                                    "with \"width\" and \"height\") or \"intrinsics\" {fx, fy, cx, cy, width, height}"));
  const bool rt = r.has("R") || r.has("t");
  const bool look = r.has("eye") || r.has("target") || r.has("up");
  if (rt && look)
    r.fail(r.has("R") ? "R" : "t", "and \"eye\"/\"target\"/\"up\" both give the pose; give R and t, or eye and target");
  if (!rt && !look)
    throw InputError(cat(r.where(), ": an OpenCV camera needs its pose: \"R\" and \"t\" (X_cam = R·X_world + t), or "
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

// 1/distance for a focus distance read from the file ("infinity" → 0).
double inverseOf(const Reader& r, const std::string& key) {
  const double distance = r.distance(key);
  if (!(distance > 0.0)) r.fail(key, cat("is ", distance, "; give a distance > 0 or \"infinity\""));
  return std::isinf(distance) ? 0.0 : 1.0 / distance;
}

// OpenCV's distCoeffs as a calibration prints them: [k1, k2, p1, p2] or [k1, k2, p1, p2, k3]; the
// 8-, 12- and 14-element forms too when what lenslab's model lacks is zero (k4, k5, k6 of the rational
// model, s1..s4 of the thin prism, τx, τy of a tilted sensor).
Distortion distCoeffsOf(const Reader& r, const std::string& key) {
  const json& raw = r.raw(key);
  const std::size_t n = raw.size();
  if (n != 4 && n != 5 && n != 8 && n != 12 && n != 14)
    r.fail(key, cat("as an array is OpenCV's distCoeffs [k1, k2, p1, p2] or [k1, k2, p1, p2, k3] (or the 8, 12 or 14 "
                    "of the fuller models), not ", excerpt(raw.dump())));
  std::vector<double> c(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!raw[i].is_number() || !std::isfinite(raw[i].get<double>())) r.fail(key, "must hold finite numbers");
    c[i] = raw[i].get<double>();
  }
  static const char* const kBeyond[] = {"k4", "k5", "k6", "s1", "s2", "s3", "s4", "tauX", "tauY"};
  for (std::size_t i = 5; i < n; ++i)
    if (c[i] != 0.0)
      r.fail(key, cat("has ", kBeyond[i - 5], " = ", c[i], " (element ", i, "); lenslab's lens model is OpenCV's k1, k2, p1, "
                      "p2, k3: the rational, thin-prism and tilt terms must be 0"));
  Distortion d;
  d.k1 = c[0], d.k2 = c[1], d.p1 = c[2], d.p2 = c[3], d.k3 = n > 4 ? c[4] : 0.0;
  return d;
}

// distortion, chromatic, field_curvature and image_size, on a camera already built.
void parseCommon(const Reader& r, CameraFile& file) {
  Camera& camera = file.camera;
  LensEffects& e = camera.effects;
  if (r.has("image_size")) camera.calibratedSize = imageSizeOf(r);
  if (r.has("dist") && r.has("distortion")) r.fail("dist", "and \"distortion\" both give the distortion; give one");
  if (r.has("dist")) {
    if (!r.raw("dist").is_array()) r.fail("dist", cat("is OpenCV's distCoeffs array [k1, k2, p1, p2, k3], not ", r.raw("dist").dump()));
    e.distortion = distCoeffsOf(r, "dist");
  }
  if (r.has("distortion")) {
    Distortion& d = e.distortion;
    const json& raw = r.raw("distortion");
    if (raw.is_array()) {
      d = distCoeffsOf(r, "distortion");
    } else {
      const Reader o = r.object("distortion", kDistortionKeys);
      const auto get = [&](const char* key, double& out) { if (o.has(key)) out = o.number(key); };
      get("k1", d.k1), get("k2", d.k2), get("p1", d.p1), get("p2", d.p2), get("k3", d.k3);
      get("alpha", d.alpha), get("beta", d.beta), get("gamma", d.gamma);
    }
  }
  const double focus = camera.inverseFocusDistance();
  if (r.has("chromatic")) {
    const Reader o = r.object("chromatic", kChromaticKeys);
    if (o.has("lateral_red")) e.chromatic.lateralRed = o.number("lateral_red");
    if (o.has("lateral_blue")) e.chromatic.lateralBlue = o.number("lateral_blue");
    const bool perChannel = o.has("focus_distance_red") || o.has("focus_distance_blue");
    if (o.has("abbe_number")) {
      if (perChannel) o.fail("abbe_number", "and focus_distance_red/blue both set the axial aberration; give one");
      if (!file.physical)
        o.fail("abbe_number", "needs the physical form (its focal_length_mm); in this form give "
                              "focus_distance_red and focus_distance_blue");
      const double abbe = o.number("abbe_number");
      if (!(abbe > 0.0)) o.fail("abbe_number", cat("is ", abbe, "; glasses have Abbe numbers of about 20 to 90"));
      const auto shifts = inverseFocusShiftsFromAbbe(abbe, file.physical->focalLengthMm * kMetresPerMillimetre);
      e.chromatic.inverseFocusShiftRed = shifts[0];
      e.chromatic.inverseFocusShiftBlue = shifts[1];
    }
    if (o.has("focus_distance_red")) e.chromatic.inverseFocusShiftRed = inverseOf(o, "focus_distance_red") - focus;
    if (o.has("focus_distance_blue")) e.chromatic.inverseFocusShiftBlue = inverseOf(o, "focus_distance_blue") - focus;
  }
  if (r.has("field_curvature")) {
    const Reader o = r.object("field_curvature", kFieldCurvatureKeys);
    o.require("corner_focus_distance", "field_curvature");
    if (camera.view.projection != Projection::Perspective)
      r.fail("field_curvature", "needs a perspective projection");
    const double corner = normalisedWindow(camera.view).cornerRadius();
    e.fieldCurvature.inverseFocusPerRadius2 = (inverseOf(o, "corner_focus_distance") - focus) / (corner * corner);
  }
  if (r.has("vignetting")) {
    // Missing keys are 0; validateLensEffects below refuses a gain that reaches 0 inside the image.
    const Reader o = r.object("vignetting", kVignettingKeys);
    Vignetting& v = e.vignetting;
    if (o.has("a1")) v.a1 = o.number("a1");
    if (o.has("a2")) v.a2 = o.number("a2");
    if (o.has("a3")) v.a3 = o.number("a3");
    if (!v.isZero() && camera.view.projection != Projection::Perspective) r.fail("vignetting", "needs a perspective projection");
  }
  if (r.has("aperture")) {
    const Reader o = r.object("aperture", kApertureKeys);
    ApertureShape& a = camera.aperture;
    if (o.has("blades")) a.blades = o.integer("blades");
    if (o.has("rotation_deg")) a.rotationDeg = o.number("rotation_deg");
    if (o.has("roundness")) a.roundness = o.number("roundness");
    if (o.has("anamorphic_squeeze")) a.anamorphicSqueeze = o.number("anamorphic_squeeze");
    if (const std::optional<ApertureProblem> problem = apertureShapeProblem(a)) o.fail(problem->field, problem->message);
  }
  if (r.has("barrel")) {
    const Reader o = r.object("barrel", kBarrelKeys);
    o.require("distance_mm", "barrel");
    o.require("diameter_mm", "barrel");
    const double distance = o.number("distance_mm"), diameter = o.number("diameter_mm");
    if (const std::optional<BarrelProblem> problem = barrelProblem(distance, diameter)) o.fail(problem->field, problem->message);
    if (camera.view.projection != Projection::Perspective) r.fail("barrel", "needs a perspective projection");
    camera.barrel = barrelFromMillimetres(distance, diameter);
  }
  validateLensEffects(camera, r.where(), file.physical ? std::optional(file.physical->focalLengthMm * kMetresPerMillimetre) : std::nullopt);
}

// distortion, chromatic, field_curvature and aperture of `camera` into `j`, as parseCommon reads them.
void writeEffects(const Camera& camera, json& j) {
  if (camera.barrel.present())
    j["barrel"] = {{"distance_mm", camera.barrel.distance / kMetresPerMillimetre},
                   {"diameter_mm", 2.0 * camera.barrel.radius / kMetresPerMillimetre}};
  const ApertureShape& a = camera.aperture;
  if (a != ApertureShape{}) {
    json o = json::object();
    if (a.blades != 0) o["blades"] = a.blades;
    if (a.rotationDeg != 0.0) o["rotation_deg"] = a.rotationDeg;
    if (a.roundness != 0.0) o["roundness"] = a.roundness;
    if (a.anamorphicSqueeze != 1.0) o["anamorphic_squeeze"] = a.anamorphicSqueeze;
    j["aperture"] = o;
  }
  const LensEffects& e = camera.effects;
  // Focus distances for the inverse distances that the effects hold; beyond infinity has no name.
  const auto distanceOf = [&](double inverse, const char* key) -> json {
    if (inverse == 0.0) return "infinity";
    if (inverse < 0.0)
      throw InputError(cat(camera.source, ": ", key, " lies beyond infinity (inverse distance ", inverse,
                           "); it cannot be written as a distance"));
    return 1.0 / inverse;
  };
  const double focus = camera.inverseFocusDistance();
  if (!e.distortion.isZero()) {
    json d = json::object();
    const Distortion& k = e.distortion;
    for (const auto& [key, value] : {std::pair{"k1", k.k1}, {"k2", k.k2}, {"p1", k.p1}, {"p2", k.p2}, {"k3", k.k3},
                                     {"alpha", k.alpha}, {"beta", k.beta}, {"gamma", k.gamma}})
      if (value != 0.0) d[key] = value;
    j["distortion"] = d;
  }
  if (e.chromatic.hasLateral() || e.chromatic.hasAxial()) {
    json c = json::object();
    if (e.chromatic.lateralRed != 0.0) c["lateral_red"] = e.chromatic.lateralRed;
    if (e.chromatic.lateralBlue != 0.0) c["lateral_blue"] = e.chromatic.lateralBlue;
    if (e.chromatic.hasAxial()) {
      c["focus_distance_red"] = distanceOf(focus + e.chromatic.inverseFocusShiftRed, "chromatic.focus_distance_red");
      c["focus_distance_blue"] = distanceOf(focus + e.chromatic.inverseFocusShiftBlue, "chromatic.focus_distance_blue");
    }
    j["chromatic"] = c;
  }
  if (!e.vignetting.isZero()) {
    json v = json::object();
    for (const auto& [key, value] : {std::pair{"a1", e.vignetting.a1}, {"a2", e.vignetting.a2}, {"a3", e.vignetting.a3}})
      if (value != 0.0) v[key] = value;
    j["vignetting"] = v;
  }
  if (!e.fieldCurvature.isZero()) {
    const double corner = normalisedWindow(camera.view).cornerRadius();
    j["field_curvature"] = {{"corner_focus_distance",
                             distanceOf(focus + e.fieldCurvature.inverseFocusPerRadius2 * corner * corner,
                                        "field_curvature.corner_focus_distance")}};
  }
}

}  // namespace

CameraFile parseCameraJson(const std::string& text, const std::string& where) {
  const json root = parseJsonDocument(text, where);
  if (!root.is_object()) throw InputError(cat(where, ": a camera file must hold a JSON object, not ", root.type_name()));

  const Reader reader(root, where);
  const bool openCv = std::any_of(kOpenCvOnlyKeys.begin(), kOpenCvOnlyKeys.end(),
                                  [&](const std::string& key) { return root.contains(key); });
  if (openCv) {
    for (const auto& item : root.items())
      if (kOpenCvFormKeys.count(item.key()) == 0 && kCommonKeys.count(item.key()) == 0)
        throw InputError(cat(where, ": unknown key \"", excerpt(item.key()), "\" in an OpenCV camera; it takes ",
                             joined(kOpenCvFormKeys), " and ", joined(kCommonKeys)));
    CameraFile file = parseOpenCv(reader);
    parseCommon(reader, file);
    return file;
  }
  bool lecture = false;
  bool physical = false;
  for (const auto& [key, value] : root.items()) {
    if (kCommonKeys.count(key) > 0) continue;
    const bool inLecture = kLectureKeys.count(key) > 0;
    const bool inPhysical = kPhysicalKeys.count(key) > 0;
    if (!inLecture && !inPhysical)
      throw InputError(cat(where, ": unknown key \"", excerpt(key), "\"; the lecture form takes ", joined(kLectureKeys),
                           "; the physical form takes ", joined(kPhysicalKeys), "; the OpenCV form (chosen by ",
                           joined(kOpenCvOnlyKeys), ") takes ", joined(kOpenCvFormKeys), "; any form takes ",
                           joined(kCommonKeys)));
    if (inLecture && !inPhysical) lecture = true;
    if (inPhysical && !inLecture) physical = true;
  }
  if (lecture && physical)
    throw InputError(cat(where, ": mixes the lecture form (vrp, vpn, prp, window, ...) with the physical form "
                                "(eye, target, focal_length_mm, ...); use one"));
  if (physical || lecture) {
    CameraFile file = physical ? parsePhysical(reader) : parseLecture(reader);
    parseCommon(reader, file);
    return file;
  }
  throw InputError(cat(where, ": no camera in it; give the lecture form (vrp, vpn, prp, window) or the "
                              "physical form (eye, target, focal_length_mm, ...)"));
}

CameraFile loadCameraJson(const std::filesystem::path& file) {
  return parseCameraJson(readTextFile(file, "camera file"), file.string());
}

std::string toCameraJson(const Camera& camera) {
  const ViewSpec& s = camera.view;
  json j;
  j["projection"] = s.projection == Projection::Perspective ? "perspective" : "parallel";
  j["vrp"] = {s.vrp.x, s.vrp.y, s.vrp.z};
  j["vpn"] = {s.vpn.x, s.vpn.y, s.vpn.z};
  j["vup"] = {s.vup.x, s.vup.y, s.vup.z};
  j["prp"] = {s.prp.x, s.prp.y, s.prp.z};
  j["window"] = {s.window.umin, s.window.vmin, s.window.umax, s.window.vmax};
  j["near"] = s.nearDistance;
  if (camera.apertureRadius > 0.0) j["aperture_radius"] = camera.apertureRadius;
  if (camera.inverseFocusOffPlane) j["focus_distance"] = camera.focusAtInfinity() ? json("infinity") : json(camera.focusDistance());
  if (std::isinf(s.farDistance)) j["far"] = "infinity";
  else j["far"] = s.farDistance;
  if (camera.calibratedSize) j["image_size"] = {camera.calibratedSize->widthPx, camera.calibratedSize->heightPx};
  writeEffects(camera, j);
  return j.dump(2) + "\n";
}

std::string toIntrinsicsCameraJson(const PhysicalCamera& physical, const LensEffects& effects, ImageSize size,
                                   bool writeNear, bool writeFar, const ApertureShape& aperture, const LensBarrel& barrel) {
  Camera camera = toCamera(physical, "the frame's camera");
  camera.effects = effects;
  camera.aperture = aperture;
  camera.barrel = barrel;
  const OpenCvIntrinsics k = intrinsicsOf(camera.view, size);
  json j;
  j["eye"] = {physical.eye.x, physical.eye.y, physical.eye.z};
  j["target"] = {physical.target.x, physical.target.y, physical.target.z};
  j["up"] = {physical.up.x, physical.up.y, physical.up.z};
  j["intrinsics"] = {{"fx", k.fx}, {"fy", k.fy}, {"cx", k.cx}, {"cy", k.cy}, {"width", k.widthPx}, {"height", k.heightPx}};
  j["focus_distance"] = std::isinf(physical.focusDistance) ? json("infinity") : json(physical.focusDistance);
  if (camera.apertureRadius > 0.0) j["aperture_radius"] = camera.apertureRadius;
  if (writeNear) j["near"] = physical.nearDistance;
  if (writeFar) j["far"] = std::isinf(physical.farDistance) ? json("infinity") : json(physical.farDistance);
  writeEffects(camera, j);
  // OpenCV's distCoeffs as an array where the lens is all OpenCV's (the lecture's series is not).
  const Distortion& d = effects.distortion;
  if (!d.isZero() && d.alpha == 0.0 && d.beta == 0.0 && d.gamma == 0.0) j["distortion"] = {d.k1, d.k2, d.p1, d.p2, d.k3};
  return j.dump(2) + "\n";
}

}  // namespace lenslab
