#include "io/CameraJson.h"

#include "camera/Intrinsics.h"
#include "camera/LensMap.h"
#include "core/Error.h"
#include "core/Text.h"
#include "io/TextFile.h"

#include <nlohmann/json.hpp>

#include <climits>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace lenslab {
namespace {

using nlohmann::json;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Camera files nest two levels ("distortion": {...}); far deeper is refused, not recursed into.
constexpr int kMaxJsonDepth = 64;

const std::set<std::string> kLectureKeys = {"projection", "vrp", "vpn", "vup", "prp", "window", "near", "far",
                                            "aperture_radius", "focus_distance"};
const std::set<std::string> kPhysicalKeys = {"eye", "target", "up", "focal_length_mm", "sensor_mm",
                                             "f_number", "focus_distance", "near", "far"};
const std::set<std::string> kIntrinsicsFormKeys = {"eye", "target", "up", "intrinsics", "focus_distance",
                                                   "aperture_radius", "near", "far"};
// Lens effects and the image size, in any form.
const std::set<std::string> kCommonKeys = {"distortion", "chromatic", "field_curvature", "image_size"};
const std::set<std::string> kDistortionKeys = {"k1", "k2", "p1", "p2", "k3", "alpha", "beta", "gamma"};
const std::set<std::string> kChromaticKeys = {"lateral_red", "lateral_blue", "focus_distance_red",
                                              "focus_distance_blue", "abbe_number"};
const std::set<std::string> kFieldCurvatureKeys = {"corner_focus_distance"};
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

  bool has(const std::string& key) const { return object_.contains(key); }

  double number(const std::string& key) const {
    const json& v = object_.at(key);
    if (!v.is_number()) fail(key, cat("must be a number, not ", v.dump()));
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(key, "must be finite");
    return d;
  }

  // A number, or the string "infinity".
  double distance(const std::string& key) const {
    const json& v = object_.at(key);
    if (v.is_string() && v.get<std::string>() == "infinity") return kInfinity;
    if (!v.is_number()) fail(key, cat("must be a number or \"infinity\", not ", v.dump()));
    return number(key);
  }

  template <int N>
  glm::vec<N, double> vector(const std::string& key) const {
    const json& v = object_.at(key);
    if (!v.is_array() || v.size() != N) fail(key, cat("must be an array of ", N, " numbers, not ", v.dump()));
    glm::vec<N, double> out;
    for (int i = 0; i < N; ++i) {
      if (!v[static_cast<std::size_t>(i)].is_number()) fail(key, cat("must be an array of ", N, " numbers, not ", v.dump()));
      out[i] = v[static_cast<std::size_t>(i)].get<double>();
      if (!std::isfinite(out[i])) fail(key, "must hold finite numbers");
    }
    return out;
  }

  std::string string(const std::string& key) const {
    const json& v = object_.at(key);
    if (!v.is_string()) fail(key, cat("must be a string, not ", v.dump()));
    return v.get<std::string>();
  }

  int integer(const std::string& key) const {
    const json& v = object_.at(key);
    if (!v.is_number_integer()) fail(key, cat("must be a whole number, not ", v.dump()));
    // get<int>() wraps what int cannot hold (4294967297 would be read as 1): refused instead.
    const bool fits = v.is_number_unsigned() ? v.get<std::uint64_t>() <= INT_MAX
                                             : v.get<std::int64_t>() >= INT_MIN && v.get<std::int64_t>() <= INT_MAX;
    if (!fits) fail(key, cat("is ", v.dump(), "; give a whole number from ", INT_MIN, " to ", INT_MAX));
    return v.get<int>();
  }

  // The object under `key`, read with keys named "key.sub" in messages; unknown keys are errors.
  Reader object(const std::string& key, const std::set<std::string>& allowed) const {
    const json& v = object_.at(key);
    if (!v.is_object()) fail(key, cat("must be an object with keys among ", joined(allowed), ", not ", v.dump()));
    for (const auto& item : v.items())
      if (allowed.count(item.key()) == 0)
        throw InputError(cat(where_, ": unknown key \"", key, ".", item.key(), "\"; \"", key, "\" takes ", joined(allowed)));
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
  spec.nearDistance = r.has("near") ? r.distance("near") : (perspective ? spec.prp.z * 1e-3 : 0.0);
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

CameraFile parseIntrinsics(const Reader& r) {
  for (const char* key : {"eye", "target", "intrinsics"}) r.require(key, "OpenCV intrinsics");
  const glm::dvec3 eye = r.vector<3>("eye");
  const glm::dvec3 target = r.vector<3>("target");
  const glm::dvec3 up = r.has("up") ? r.vector<3>("up") : glm::dvec3(0.0, 1.0, 0.0);
  const Reader k = r.object("intrinsics", kIntrinsicsKeys);
  for (const char* key : {"fx", "fy", "cx", "cy", "width", "height"}) k.require(key, "intrinsics");
  const double fx = k.number("fx"), fy = k.number("fy"), cx = k.number("cx"), cy = k.number("cy");
  if (!(fx > 0.0)) k.fail("fx", cat("is ", fx, "; give the focal length in pixels (> 0)"));
  if (!(fy > 0.0)) k.fail("fy", cat("is ", fy, "; give the focal length in pixels (> 0)"));
  const int width = k.integer("width"), height = k.integer("height");
  if (width < 1 || width > kMaxImageSidePx) k.fail("width", cat("is ", width, "; use 1 to ", kMaxImageSidePx, " pixels"));
  if (height < 1 || height > kMaxImageSidePx) k.fail("height", cat("is ", height, "; use 1 to ", kMaxImageSidePx, " pixels"));
  const double toTarget = glm::length(target - eye);
  if (!(toTarget > 0.0)) r.fail("target", "must differ from \"eye\"");
  const double focus = r.has("focus_distance") ? r.distance("focus_distance") : toTarget;
  if (!(focus > 0.0)) r.fail("focus_distance", cat("is ", focus, "; give a distance > 0 or \"infinity\""));

  // The view plane is the plane of focus (at |target − eye| when focus is at infinity), its VRP the
  // foot of the PRP, so the principal point is (0, 0) of the window. OpenCV puts pixel centres on
  // integers with (0, 0) the centre of the top-left pixel; lenslab puts them at i + 0.5 with (0, 0)
  // the top-left corner: lenslab x = OpenCV x + 0.5. OpenCV's y runs down, the window's v up.
  // As for the physical form: a focus beyond kMaxViewPlaneMove × |target − eye| is held as 1/z_f.
  const double d = viewPlaneDistanceFor(focus, toTarget);
  ViewSpec spec;
  spec.vpn = glm::normalize(eye - target);
  spec.vup = up;
  spec.vrp = eye - d * spec.vpn;
  spec.prp = {0.0, 0.0, d};
  spec.window = {d * (-0.5 - cx) / fx, -d * (height - 0.5 - cy) / fy, d * (width - 0.5 - cx) / fx, d * (0.5 + cy) / fy};
  spec.nearDistance = r.has("near") ? r.distance("near") : 0.05;
  if (r.has("far")) spec.farDistance = r.distance("far");
  validate(spec, r.where());
  const double aperture = apertureRadiusOf(r);
  CameraFile file;
  file.form = CameraFile::Form::Intrinsics;
  file.camera = cameraFocusedOnViewPlane(spec, aperture, r.where());
  if (d != focus) file.camera.inverseFocusOffPlane = 1.0 / focus;
  file.camera.nearFromScene = !r.has("near");
  file.camera.farFromScene = !r.has("far");
  file.camera.calibratedSize = ImageSize{width, height};
  return file;
}

// 1/distance for a focus distance read from the file ("infinity" → 0).
double inverseOf(const Reader& r, const std::string& key) {
  const double distance = r.distance(key);
  if (!(distance > 0.0)) r.fail(key, cat("is ", distance, "; give a distance > 0 or \"infinity\""));
  return std::isinf(distance) ? 0.0 : 1.0 / distance;
}

// distortion, chromatic, field_curvature and image_size, on a camera already built.
void parseCommon(const Reader& r, CameraFile& file) {
  Camera& camera = file.camera;
  LensEffects& e = camera.effects;
  if (r.has("image_size")) {
    const glm::dvec2 size = r.vector<2>("image_size");
    if (size.x < 1 || size.y < 1 || size.x > kMaxImageSidePx || size.y > kMaxImageSidePx || size != glm::floor(size))
      r.fail("image_size", cat("must be [width, height] in whole pixels from 1 to ", kMaxImageSidePx));
    camera.calibratedSize = ImageSize{static_cast<int>(size.x), static_cast<int>(size.y)};
  }
  if (r.has("distortion")) {
    Distortion& d = e.distortion;
    const json& raw = r.raw("distortion");
    if (raw.is_array()) {
      // OpenCV's distCoeffs as printed by a calibration: [k1, k2, p1, p2] or [k1, k2, p1, p2, k3].
      if (raw.size() != 4 && raw.size() != 5)
        r.fail("distortion", cat("as an array is OpenCV's [k1, k2, p1, p2] or [k1, k2, p1, p2, k3], not ", raw.dump()));
      double c[5] = {0, 0, 0, 0, 0};
      for (std::size_t i = 0; i < raw.size(); ++i) {
        if (!raw[i].is_number() || !std::isfinite(raw[i].get<double>())) r.fail("distortion", "must hold finite numbers");
        c[i] = raw[i].get<double>();
      }
      d.k1 = c[0], d.k2 = c[1], d.p1 = c[2], d.p2 = c[3], d.k3 = c[4];
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
  validateLensEffects(camera, r.where());
}

// distortion, chromatic and field_curvature of `camera` into `j`, as parseCommon reads them.
void writeEffects(const Camera& camera, json& j) {
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
  if (!e.fieldCurvature.isZero()) {
    const double corner = normalisedWindow(camera.view).cornerRadius();
    j["field_curvature"] = {{"corner_focus_distance",
                             distanceOf(focus + e.fieldCurvature.inverseFocusPerRadius2 * corner * corner,
                                        "field_curvature.corner_focus_distance")}};
  }
}

}  // namespace

CameraFile parseCameraJson(const std::string& text, const std::string& where) {
  json root;
  try {
    // Nesting is bounded while parsing: the messages below quote values with dump(), which
    // recurses once per level (a value nested a million deep overflowed the stack).
    root = json::parse(text, [&](int depth, json::parse_event_t, json&) {
      if (depth > kMaxJsonDepth) throw InputError(cat(where, ": the JSON nests deeper than ", kMaxJsonDepth, " levels"));
      return true;
    });
  } catch (const json::exception& e) {  // parse_error, and out_of_range for a number beyond double's range
    std::string what = e.what();
    if (const auto p = what.find("parse error"); p != std::string::npos) what = what.substr(p);
    else if (const auto end = what.find("] "); what.starts_with("[json.exception") && end != std::string::npos) what.erase(0, end + 2);
    throw InputError(cat(where, ": not valid JSON: ", what));
  }
  if (!root.is_object()) throw InputError(cat(where, ": a camera file must hold a JSON object, not ", root.type_name()));

  const Reader reader(root, where);
  if (root.contains("intrinsics")) {
    for (const auto& item : root.items())
      if (kIntrinsicsFormKeys.count(item.key()) == 0 && kCommonKeys.count(item.key()) == 0)
        throw InputError(cat(where, ": unknown key \"", item.key(), "\" in an OpenCV-intrinsics camera; it takes ",
                             joined(kIntrinsicsFormKeys), " and ", joined(kCommonKeys)));
    CameraFile file = parseIntrinsics(reader);
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
      throw InputError(cat(where, ": unknown key \"", key, "\"; the lecture form takes ", joined(kLectureKeys),
                           "; the physical form takes ", joined(kPhysicalKeys), "; any form takes ",
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
                                   bool writeNear, bool writeFar) {
  Camera camera = toCamera(physical, "the frame's camera");
  camera.effects = effects;
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
