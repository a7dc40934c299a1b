#include "plan/CameraOptions.h"

#include "camera/AutoFraming.h"
#include "camera/GltfCamera.h"
#include "camera/LensMap.h"
#include "core/Error.h"
#include "core/ParseNumber.h"
#include "core/Text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace lenslab {
namespace {

constexpr double kDefaultSensorHeightMm = 24.0;  // full frame's, for glTF cameras (which have none)

std::string vectorText(const glm::dvec3& v) { return cat(v.x, ",", v.y, ",", v.z); }

double parseNumber(const std::string& text, bool& ok) {
  const std::optional<double> value = parseFiniteNumber(text);
  ok = value.has_value();
  return value.value_or(0.0);
}

// The physical rows of the composition table, on a description whose focus is on its target when
// `focusOnTarget` (then a new eye or target keeps it there).
PhysicalCamera applyTo(PhysicalCamera p, const CameraOptions& o) {
  const double toTarget = glm::length(p.target - p.eye);
  const bool focusOnTarget = std::abs(p.focusDistance - toTarget) <= 1e-9 * toTarget;
  if (!o.sensor.empty()) p.sensorMm = parseSensorMm(o.sensor);
  if (o.focalLengthMm) p.focalLengthMm = *o.focalLengthMm;
  if (!o.fNumber.empty()) p.fNumber = parseFNumber(o.fNumber);
  if (o.eye) p.eye = *o.eye;
  if (o.target) p.target = *o.target;
  if (o.changesPose() && focusOnTarget) p.focusDistance = glm::length(p.target - p.eye);
  return p;
}

// The physical description converted, keeping what the base camera had beyond it (lens effects,
// calibrated image size, near/far left to the scene), and its view checked as a camera file's is.
SelectedCamera physicalCamera(const PhysicalCamera& p, const Camera& like, const std::string& source) {
  SelectedCamera out = toSelectedCamera(p, like, source);
  validate(out.camera.view, source);
  return out;
}

// The aspect ratio a glTF camera is drawn at: its own, else the image's (--width / --height), else
// 3:2 (full frame's, as for its sensor).
double gltfAspect(const SceneCamera& c, double imageAspect) {
  if (c.aspectRatio > 0.0) return c.aspectRatio;
  return imageAspect > 0.0 ? imageAspect : 1.5;
}

// A node transform looking from `eye` at `target` with +Y up (glTF cameras look along −Z, +Y up).
glm::dmat4 lookingAt(const glm::dvec3& eye, const glm::dvec3& target, const std::string& where) {
  const glm::dvec3 forward = target - eye;
  if (!(glm::length(forward) > 0.0))
    throw InputError(cat(where, ": --eye and --target are the same point; the view direction is undefined"));
  const glm::dvec3 back = -glm::normalize(forward);
  const glm::dvec3 side = glm::cross(glm::dvec3(0.0, 1.0, 0.0), back);
  if (!(glm::length(side) > 1e-9))
    throw InputError(
        cat(where, ": the view from --eye to --target is vertical, so +Y cannot be up; move one of them sideways"));
  const glm::dvec3 x = glm::normalize(side);
  glm::dmat4 m(1.0);
  m[0] = glm::dvec4(x, 0.0);
  m[1] = glm::dvec4(glm::cross(back, x), 0.0);
  m[2] = glm::dvec4(back, 0.0);
  m[3] = glm::dvec4(eye, 1.0);
  return m;
}

// A glTF camera as lenslab draws it without options: its own field of view, the view plane at the
// base's focus distance.
SelectedCamera gltfView(const BaseCamera& base, const SceneCamera& c, double focus, double imageAspect,
                        const std::string& source) {
  const double aspect = gltfAspect(c, imageAspect);
  const ViewSpec view =
      c.perspective ? viewSpecFromGltfPerspective(c.worldFromCamera, c.yfovRadians, aspect, c.znear, c.zfar, focus)
                    : viewSpecFromGltfOrthographic(c.worldFromCamera, c.xmag, c.ymag, c.znear, c.zfar, focus);
  SelectedCamera selected;
  selected.camera = cameraFocusedOnViewPlane(view, 0.0, source);
  selected.camera.farFromScene = std::isinf(c.zfar);  // glTF: an absent zfar is an infinite projection
  validate(selected.camera.view, cat(base.name, ": ", source));
  return selected;
}

// A glTF perspective camera as a physical description: sensor from --sensor, else 24 mm high at
// the camera's aspect ratio; the focal length that gives its yfov on that sensor at its focus
// distance z_f, so that the view is the one the file shows: image distance z_i = h / (2·tan(yfov/2)),
// f = z_i·z_f / (z_i + z_f). For a subject far beyond the lens this is h / (2·tan(yfov/2)), what
// exporters such as Blender's write; for a close-up the difference matters (ToyCar's first camera,
// 4 cm from a 7 cm car, would otherwise see 2.6 times less of it).
PhysicalCamera gltfAsPhysical(const BaseCamera& base, const CameraOptions& o, double imageAspect) {
  const SceneCamera& c = base.gltf;
  const double aspect = gltfAspect(c, imageAspect);
  PhysicalCamera p;
  p.sensorMm =
      o.sensor.empty() ? glm::dvec2(kDefaultSensorHeightMm * aspect, kDefaultSensorHeightMm) : parseSensorMm(o.sensor);
  const double imageDistance = p.sensorMm.y * kMetresPerMillimetre / (2.0 * std::tan(0.5 * c.yfovRadians));
  const double focus = base.gltfFocusDistance;
  p.focalLengthMm = imageDistance * focus / (imageDistance + focus) / kMetresPerMillimetre;
  p.eye = glm::dvec3(c.worldFromCamera[3]);
  const glm::dvec3 forward = -glm::normalize(glm::dvec3(c.worldFromCamera[2]));
  p.up = o.changesPose() ? glm::dvec3(0.0, 1.0, 0.0) : glm::normalize(glm::dvec3(c.worldFromCamera[1]));
  p.focusDistance = base.gltfFocusDistance;
  p.target = p.eye + base.gltfFocusDistance * forward;
  p.nearDistance = c.znear;
  p.farDistance = c.zfar;
  // --eye alone keeps the view's direction; the rest is the physical rows.
  if (o.eye && !o.target) p.target = *o.eye + (p.target - p.eye);
  CameraOptions lens = o;
  lens.sensor.clear();  // already applied (it also chose the focal length)
  return applyTo(p, lens);
}

[[noreturn]] void refuse(const std::string& option, const std::string& why) {
  throw InputError(cat(option, ": ", why));
}

SelectedCamera composeFramed(const BaseCamera& base, const CameraOptions& o) {
  const PhysicalCamera defaults;  // 35 mm on full frame
  const double focalMm = o.focalLengthMm.value_or(defaults.focalLengthMm);
  const glm::dvec2 sensorMm = o.sensor.empty() ? defaults.sensorMm : parseSensorMm(o.sensor);
  const std::string where = cat(base.name, " with ", o.describe());
  const BoundingSphere& s = base.subject;
  SelectedCamera framed;
  if (o.eye) {
    PhysicalCamera p;
    p.eye = *o.eye;
    p.target = o.target.value_or(s.center);
    p.focalLengthMm = focalMm;
    p.sensorMm = sensorMm;
    p.focusDistance = glm::length(p.target - p.eye);
    validate(p, where);
    framed = physicalCamera(p, Camera{},
                            cat("--eye ", vectorText(p.eye), ", --target ", vectorText(p.target), ", ", focalMm,
                                " mm on ", sensorMm.x, "x", sensorMm.y, " mm, focused on the target"));
  } else {
    framed = frameSphere(o.target.value_or(s.center), s.radius, focalMm, sensorMm);
  }
  // Either way near and far are placeholders: fit them to the scene (the one place that says so).
  framed.camera.nearFromScene = framed.camera.farFromScene = true;
  if (o.fNumber.empty()) return framed;
  const double n = parseFNumber(o.fNumber);
  if (!framed.physical) {
    if (std::isinf(n)) return framed;
    refuse(cat("--f-number ", o.fNumber), framed.camera.source);
  }
  PhysicalCamera p = *framed.physical;
  p.fNumber = n;
  validate(p, where);
  return physicalCamera(p, framed.camera, framed.camera.source + cat(", f/", o.fNumber));
}

SelectedCamera composeViewingDescription(const BaseCamera& base, const CameraOptions& o) {
  const bool lecture = base.form == CameraForm::Lecture;
  const std::string form = lecture ? "the lecture form" : "the OpenCV-intrinsics form";
  if (o.changesPose())
    refuse(o.eye ? "--eye" : "--target",
           cat(base.name, " is in ", form, ", which places the camera by ",
               lecture ? "VRP, VPN and PRP: edit those" : "its own eye and target: edit them",
               ", or give the camera in the physical form (eye, target, focal_length_mm)"));
  const std::string fieldOfView = lecture ? "its window and PRP" : "its fx and fy";
  if (!o.sensor.empty())
    refuse(cat("--sensor ", o.sensor),
           cat(base.name, " is in ", form, ", whose field of view is ", fieldOfView,
               " (it has no sensor): give the camera in the physical form to choose a sensor"));
  if (o.focalLengthMm && o.fNumber.empty())
    refuse(cat("--focal-length ", *o.focalLengthMm),
           cat(base.name, " is in ", form, ", whose field of view is ", fieldOfView,
               ": a focal length alone changes nothing (with --f-number it gives the aperture radius f/2N)"));
  if (o.fNumber.empty()) return base.selected;
  const double n = parseFNumber(o.fNumber);
  SelectedCamera out = base.selected;
  if (std::isinf(n)) {
    out.camera.lens.apertureRadius = 0.0;
    out.camera.source += ", a pinhole (--f-number infinity)";
    return out;
  }
  if (!o.focalLengthMm)
    refuse(cat("--f-number ", o.fNumber),
           cat(base.name, " is in ", form,
               ", which has no focal length: give --focal-length too, or aperture_radius in the file"));
  out.camera.lens.apertureRadius = *o.focalLengthMm * kMetresPerMillimetre / (2.0 * n);
  out.camera.source +=
      cat(", aperture radius ", out.camera.lens.apertureRadius, " (", *o.focalLengthMm, " mm at f/", o.fNumber, ")");
  return out;
}

}  // namespace

std::string CameraOptions::describe() const {
  std::string text;
  const auto add = [&](const std::string& part) { text += (text.empty() ? "" : " ") + part; };
  if (focalLengthMm) add(cat("--focal-length ", *focalLengthMm));
  if (!fNumber.empty()) add("--f-number " + fNumber);
  if (!sensor.empty()) add("--sensor " + sensor);
  if (eye) add("--eye " + vectorText(*eye));
  if (target) add("--target " + vectorText(*target));
  return text;
}

const std::vector<NamedSensor>& namedSensors() {
  static const std::vector<NamedSensor> sensors = {
      {"full-frame", {36.0, 24.0}},
      {"aps-c", {23.6, 15.6}, "Nikon's and Sony's; Canon's is --sensor 22.3x14.9"},
      {"micro-four-thirds", {17.3, 13.0}},
      {"1-inch", {13.2, 8.8}}};
  return sensors;
}

std::string namedSensorList() {
  std::string list;
  for (const NamedSensor& s : namedSensors()) {
    const std::string note = *s.note ? cat(", ", s.note) : "";
    list += cat(list.empty() ? "" : ", ", s.name, " (", s.sizeMm.x, "x", s.sizeMm.y, note, ")");
  }
  return list;
}

glm::dvec2 parseSensorMm(const std::string& text) {
  for (const NamedSensor& s : namedSensors())
    if (text == s.name) return s.sizeMm;
  const auto x = text.find_first_of("xX");
  if (x != std::string::npos) {
    bool okWidth = false, okHeight = false;
    const double w = parseNumber(text.substr(0, x), okWidth), h = parseNumber(text.substr(x + 1), okHeight);
    if (okWidth && okHeight && w > 0.0 && h > 0.0 && w <= 1e4 && h <= 1e4) return {w, h};
  }
  throw InputError(
      cat("--sensor ", text, ": give WIDTHxHEIGHT in millimetres (e.g. 36x24), or one of ", namedSensorList()));
}

double parseFNumber(const std::string& text) {
  if (text == "infinity" || text == "pinhole") return std::numeric_limits<double>::infinity();
  bool ok = false;
  const double n = parseNumber(text, ok);
  if (ok && n > 0.0) return n;
  throw InputError(
      cat("--f-number ", text, ": give a positive number (e.g. 2.8), or infinity (a pinhole: no aperture)"));
}

BaseCamera gltfBaseCamera(const Scene& scene, std::size_t index) {
  BaseCamera base;
  const SceneCamera& c = scene.cameras[index];
  base.gltf = c;
  base.gltfIndex = index;
  base.form = c.perspective ? CameraForm::GltfPerspective : CameraForm::GltfOrthographic;
  base.name = cat(scene.source, ": glTF camera ", sceneCameraLabel(scene, index));
  // glTF cameras have no focus; put the view plane (the plane of focus) at the depth of the
  // scene's centre, no nearer than twice znear.
  const glm::dvec3 eye(c.worldFromCamera[3]);
  const glm::dvec3 forward = glm::normalize(-glm::dvec3(c.worldFromCamera[2]));
  double focus = scene.bounds.empty() ? 1.0 : glm::dot(scene.bounds.center() - eye, forward);
  focus = std::max(focus, 2.0 * c.znear);
  base.gltfFocusDistance = focus > 0.0 ? focus : 1.0;
  return base;
}

BaseCamera framingBaseCamera(const Scene& scene) {
  BaseCamera base;
  base.form = CameraForm::AutomaticFraming;
  base.name = "automatic framing";
  base.subject = boundingSphere(scene);
  if (base.subject.empty()) base.subject = {glm::dvec3(0.0), 1.0};
  return base;
}

PhysicalCamera gltfPhysicalCamera(const BaseCamera& base, const CameraOptions& options, double imageAspect) {
  const PhysicalCamera p = gltfAsPhysical(base, options, imageAspect);
  validate(p,
           options.changesLens() || options.changesPose() ? cat(base.name, " with ", options.describe()) : base.name);
  return p;
}

PhysicalCamera withCameraOptions(PhysicalCamera camera, const CameraOptions& options, const std::string& where) {
  PhysicalCamera p = applyTo(camera, options);
  validate(p, cat(where, " with ", options.describe()));
  return p;
}

namespace {

SelectedCamera composeForm(const BaseCamera& base, const CameraOptions& o, double imageAspect) {
  const std::string given = o.describe();
  const std::string with = " with " + given;
  const std::string& gltfName = base.gltf.nodeName.empty() ? base.gltf.name : base.gltf.nodeName;
  const std::string gltfSource = cat("glTF camera ", base.gltfIndex, gltfName.empty() ? "" : cat(" (", gltfName, ")"));
  switch (base.form) {
    case CameraForm::AutomaticFraming: return composeFramed(base, o);
    case CameraForm::Lecture:
    case CameraForm::Intrinsics: return composeViewingDescription(base, o);
    case CameraForm::Physical: {
      if (!o.changesLens() && !o.changesPose()) return base.selected;
      const PhysicalCamera p = withCameraOptions(*base.selected.physical, o, base.name);
      return physicalCamera(p, base.selected.camera, cat(base.selected.camera.source, ", ", given));
    }
    case CameraForm::GltfPerspective: {
      if (!o.changesLens() && !o.changesPose())
        return gltfView(base, base.gltf, base.gltfFocusDistance, imageAspect, gltfSource);
      const PhysicalCamera p = gltfPhysicalCamera(base, o, imageAspect);
      Camera like;
      like.farFromScene = std::isinf(base.gltf.zfar);
      return physicalCamera(
          p, like,
          cat(gltfSource, " as ", p.focalLengthMm, " mm on ", p.sensorMm.x, "x", p.sensorMm.y, " mm, ", given));
    }
    case CameraForm::GltfOrthographic: {
      const std::string why = cat(base.name, " is orthographic, which has no lens");
      if (!o.sensor.empty()) refuse(cat("--sensor ", o.sensor), why);
      if (o.focalLengthMm) refuse(cat("--focal-length ", *o.focalLengthMm), why);
      if (!o.fNumber.empty() && !std::isinf(parseFNumber(o.fNumber)))
        refuse(cat("--f-number ", o.fNumber), why + " (--f-number infinity, a pinhole, is all it takes)");
      if (!o.changesPose()) return gltfView(base, base.gltf, base.gltfFocusDistance, imageAspect, gltfSource);
      SceneCamera moved = base.gltf;
      const glm::dvec3 eye = o.eye.value_or(glm::dvec3(base.gltf.worldFromCamera[3]));
      const glm::dvec3 forward = -glm::normalize(glm::dvec3(base.gltf.worldFromCamera[2]));
      const glm::dvec3 target = o.target.value_or(eye + base.gltfFocusDistance * forward);
      moved.worldFromCamera = lookingAt(eye, target, base.name + with);
      return gltfView(base, moved, glm::length(target - eye), imageAspect, cat(gltfSource, ", ", given));
    }
  }
  return base.selected;
}

}  // namespace

SelectedCamera composeCamera(const BaseCamera& base, const CameraOptions& o, double imageAspect) {
  SelectedCamera out = composeForm(base, o, imageAspect);
  // A new focal length, aperture or sensor can move the file's lens effects out of what the lens
  // can do (a channel's plane of focus inside a longer focal length, a fold inside a wider view).
  if (o.changesLens() || o.changesPose())
    validateLensEffects(out.camera, cat(base.name, " with ", o.describe()),
                        out.physical      ? std::optional(out.physical->focalLengthMm * kMetresPerMillimetre)
                        : o.focalLengthMm ? std::optional(*o.focalLengthMm * kMetresPerMillimetre)
                                          : std::nullopt);
  return out;
}

std::vector<std::string> focusWarnings(const Camera& camera, const LensOptions& lens) {
  std::vector<std::string> warnings;
  if (!camera.lens.isPinhole()) return warnings;
  const std::string why =
      "the camera has no aperture (a pinhole), so focus changes nothing; give --f-number N (or f_number / "
      "aperture_radius in the camera file) for depth of field";
  if (!lens.focusDistance.empty()) warnings.push_back(cat("--focus-distance ", lens.focusDistance, ": ", why));
  if (lens.focusAt) warnings.push_back(cat("--focus-at ", lens.focusAt->x, ",", lens.focusAt->y, ": ", why));
  const std::string shapeWhy =
      "the camera has no aperture (a pinhole), so nothing is blurred into the aperture's shape; give "
      "--f-number N (or f_number / aperture_radius in the camera file) for depth of field";
  if (lens.blades) warnings.push_back(cat("--blades ", *lens.blades, ": ", shapeWhy));
  if (lens.squeeze) warnings.push_back(cat("--squeeze ", *lens.squeeze, ": ", shapeWhy));
  return warnings;
}

}  // namespace lenslab
