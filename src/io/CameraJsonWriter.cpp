// Camera files written: the lecture form of any camera, and the OpenCV-intrinsics form of a
// physical one (io/CameraJson.h). The lens-effect keys are each module's (lens/effects/).
#include "io/CameraJson.h"

#include "camera/Intrinsics.h"
#include "camera/LensMap.h"
#include "lens/effects/LensEffectRegistry.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace lenslab {
namespace {

using nlohmann::json;

// The KeyWriter the lens-effect modules write through, on one JSON object.
class JsonKeyWriter final : public KeyWriter {
 public:
  explicit JsonKeyWriter(json& object) : object_(object) {}
  void number(const std::string& key, double value) override { object_[key] = value; }
  void integer(const std::string& key, int value) override { object_[key] = value; }
  void distance(const std::string& key, double value) override {
    object_[key] = std::isinf(value) ? json("infinity") : json(value);
  }
  void string(const std::string& key, const std::string& value) override { object_[key] = value; }
  KeyWriter& object(const std::string& key) override {
    object_[key] = json::object();
    children_.push_back(std::make_unique<JsonKeyWriter>(object_[key]));
    return *children_.back();
  }

 private:
  json& object_;
  std::vector<std::unique_ptr<JsonKeyWriter>> children_;
};

// Every lens effect of `camera` into `j`, as parseCommon reads them.
void writeEffects(const Camera& camera, json& j) {
  LensFrame frame;
  frame.where = camera.source;
  frame.inverseFocus = camera.inverseFocusDistance();
  frame.cornerRadius = normalisedWindow(camera.view).cornerRadius();
  frame.perspective = camera.view.projection == Projection::Perspective;
  JsonKeyWriter writer(j);
  for (const LensEffectModule* module : lensEffectModules()) module->write(camera.lens, frame, writer);
}

}  // namespace

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
  if (camera.lens.apertureRadius > 0.0) j["aperture_radius"] = camera.lens.apertureRadius;
  if (camera.inverseFocusOffPlane)
    j["focus_distance"] = camera.focusAtInfinity() ? json("infinity") : json(camera.focusDistance());
  if (std::isinf(s.farDistance))
    j["far"] = "infinity";
  else
    j["far"] = s.farDistance;
  if (camera.calibratedSize) j["image_size"] = {camera.calibratedSize->widthPx, camera.calibratedSize->heightPx};
  writeEffects(camera, j);
  return j.dump(2) + "\n";
}

std::string toIntrinsicsCameraJson(const PhysicalCamera& physical, const Lens& lens, ImageSize size, bool writeNear,
                                   bool writeFar) {
  const Camera camera = toCamera(physical, lens, "the frame's camera");
  const OpenCvIntrinsics k = intrinsicsOf(camera.view, size);
  json j;
  j["eye"] = {physical.eye.x, physical.eye.y, physical.eye.z};
  j["target"] = {physical.target.x, physical.target.y, physical.target.z};
  j["up"] = {physical.up.x, physical.up.y, physical.up.z};
  j["intrinsics"] = {{"fx", k.fx}, {"fy", k.fy},         {"cx", k.cx},
                     {"cy", k.cy}, {"width", k.widthPx}, {"height", k.heightPx}};
  j["focus_distance"] = std::isinf(physical.focusDistance) ? json("infinity") : json(physical.focusDistance);
  if (camera.lens.apertureRadius > 0.0) j["aperture_radius"] = camera.lens.apertureRadius;
  if (writeNear) j["near"] = physical.nearDistance;
  if (writeFar) j["far"] = std::isinf(physical.farDistance) ? json("infinity") : json(physical.farDistance);
  writeEffects(camera, j);
  // OpenCV's distCoeffs as an array where the lens is all OpenCV's (the lecture's series is not).
  const Distortion& d = camera.lens.effects.distortion;
  if (!d.isZero() && d.isOpenCv()) j["distortion"] = d.distCoeffs();
  return j.dump(2) + "\n";
}

std::string toOpenCvCameraJson(const Camera& camera, ImageSize size, bool writeNear, bool writeFar) {
  const OpenCvIntrinsics k = intrinsicsOf(camera.view, size);
  const OpenCvPose pose = poseOf(camera.view);
  json j;
  j["K"] = {{k.fx, 0.0, k.cx}, {0.0, k.fy, k.cy}, {0.0, 0.0, 1.0}};
  j["width"] = k.widthPx;
  j["height"] = k.heightPx;
  j["R"] = json::array();
  for (const glm::dvec3& row : pose.rows) j["R"].push_back({row.x, row.y, row.z});
  j["t"] = {pose.translation.x, pose.translation.y, pose.translation.z};
  j["focus_distance"] = camera.focusAtInfinity() ? json("infinity") : json(camera.focusDistance());
  if (camera.lens.apertureRadius > 0.0) j["aperture_radius"] = camera.lens.apertureRadius;
  if (writeNear) j["near"] = camera.view.nearDistance;
  if (writeFar) j["far"] = std::isinf(camera.view.farDistance) ? json("infinity") : json(camera.view.farDistance);
  writeEffects(camera, j);
  const Distortion& d = camera.lens.effects.distortion;
  if (!d.isZero() && d.isOpenCv()) j["distortion"] = d.distCoeffs();
  return j.dump(2) + "\n";
}

}  // namespace lenslab
