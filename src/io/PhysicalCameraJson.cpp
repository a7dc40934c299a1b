// The physical form of a camera file: a photographer's description (io/CameraJson.h).
#include "io/CameraJsonForms.h"

#include "camera/Exposure.h"
#include "core/NumberInput.h"

#include <tuple>

namespace lenslab {

const std::set<std::string> kPhysicalKeys = {
    "eye", "target",    "up", "focal_length_mm", "sensor_mm", "f_number", "focus_distance", "near",
    "far", "shutter_s", "iso"};

CameraFile parsePhysical(const JsonReader& r) {
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
  for (const auto& [key, range, field] :
       {std::tuple{"shutter_s", kShutterSecondsRange, &c.shutterSeconds}, std::tuple{"iso", kIsoRange, &c.iso}})
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

}  // namespace lenslab
