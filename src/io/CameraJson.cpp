#include "io/CameraJson.h"

#include "core/Error.h"
#include "core/Text.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace lenslab {
namespace {

using nlohmann::json;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

const std::set<std::string> kLectureKeys = {"projection", "vrp", "vpn", "vup", "prp", "window", "near", "far",
                                            "aperture_radius"};
const std::set<std::string> kPhysicalKeys = {"eye", "target", "up", "focal_length_mm", "sensor_mm",
                                             "f_number", "focus_distance", "near", "far"};

std::string joined(const std::set<std::string>& keys) {
  std::string s;
  for (const std::string& k : keys) s += (s.empty() ? "" : ", ") + k;
  return s;
}

class Reader {
 public:
  Reader(const json& object, std::string where) : object_(object), where_(std::move(where)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw InputError(cat(where_, ": \"", key, "\" ", message));
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
    if (v.is_string() && (v.get<std::string>() == "infinity" || v.get<std::string>() == "inf")) return kInfinity;
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

  void require(const std::string& key, const std::string& form) const {
    if (!has(key)) throw InputError(cat(where_, ": \"", key, "\" is missing; the ", form, " form needs it"));
  }

  const std::string& where() const { return where_; }

 private:
  const json& object_;
  std::string where_;
};

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
  double aperture = 0.0;
  if (r.has("aperture_radius")) {
    aperture = r.number("aperture_radius");
    if (aperture < 0.0) r.fail("aperture_radius", cat("is ", aperture, "; give a radius ≥ 0 in world units (0 = pinhole)"));
  }
  CameraFile file;
  file.camera = cameraFocusedOnViewPlane(spec, aperture, r.where());
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
  file.physical = c;
  file.camera = toCamera(c, r.where());
  validate(file.camera.view, r.where());
  return file;
}

}  // namespace

CameraFile parseCameraJson(const std::string& text, const std::string& where) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    std::string what = e.what();
    if (const auto p = what.find("parse error"); p != std::string::npos) what = what.substr(p);
    throw InputError(cat(where, ": not valid JSON: ", what));
  }
  if (!root.is_object()) throw InputError(cat(where, ": a camera file must hold a JSON object, not ", root.type_name()));

  bool lecture = false;
  bool physical = false;
  for (const auto& [key, value] : root.items()) {
    const bool inLecture = kLectureKeys.count(key) > 0;
    const bool inPhysical = kPhysicalKeys.count(key) > 0;
    if (!inLecture && !inPhysical)
      throw InputError(cat(where, ": unknown key \"", key, "\"; the lecture form takes ", joined(kLectureKeys),
                           "; the physical form takes ", joined(kPhysicalKeys)));
    if (inLecture && !inPhysical) lecture = true;
    if (inPhysical && !inLecture) physical = true;
  }
  if (lecture && physical)
    throw InputError(cat(where, ": mixes the lecture form (vrp, vpn, prp, window, ...) with the physical form "
                                "(eye, target, focal_length_mm, ...); use one"));
  const Reader reader(root, where);
  if (physical) return parsePhysical(reader);
  if (lecture) return parseLecture(reader);
  throw InputError(cat(where, ": no camera in it; give the lecture form (vrp, vpn, prp, window) or the "
                              "physical form (eye, target, focal_length_mm, ...)"));
}

CameraFile loadCameraJson(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(cat(file.string(), ": cannot read the camera file (does it exist?)"));
  std::ostringstream text;
  text << in.rdbuf();
  return parseCameraJson(text.str(), file.string());
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
  if (std::isinf(s.farDistance)) j["far"] = "infinity";
  else j["far"] = s.farDistance;
  return j.dump(2) + "\n";
}

}  // namespace lenslab
