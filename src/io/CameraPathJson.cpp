#include "io/CameraPathJson.h"

#include "io/JsonDocument.h"

#include "core/Error.h"
#include "core/NumberInput.h"
#include "core/Text.h"
#include "io/CameraJson.h"
#include "core/TextFile.h"

#include <nlohmann/json.hpp>

namespace lenslab {

using json = nlohmann::json;

CameraPath parseCameraPath(const std::string& text, const std::string& where) {
  const json root = parseJsonDocument(text, where);
  if (!root.is_object())
    throw InputError(cat(where, ": a camera path must hold a JSON object, not ", root.type_name()));
  for (const auto& item : root.items())
    if (item.key() != "fps" && item.key() != "keys" && item.key() != "frames" && item.key() != "interpolation")
      throw InputError(cat(where, ": unknown key \"", excerpt(item.key()),
                           "\"; a camera path takes fps, keys, frames, interpolation"));

  CameraPath path;
  if (!root.contains("fps")) throw InputError(cat(where, ": fps: required (frames per second, e.g. 24)"));
  if (!root["fps"].is_number()) throw InputError(cat(where, ": fps: give a number of frames per second"));
  path.fps = root["fps"].get<double>();
  if (root.contains("frames")) {
    if (!root["frames"].is_number_integer()) throw InputError(cat(where, ": frames: give a whole number of frames"));
    const long long frames = root["frames"].get<long long>();
    if (frames < 1 || frames > 10'000'000) throw InputError(cat(where, ": frames ", frames, ": give 1 to 10^7"));
    path.frames = static_cast<int>(frames);
  }
  if (root.contains("interpolation")) {
    const json& mode = root["interpolation"];
    if (mode == "smooth")
      path.interpolation = PathInterpolation::Smooth;
    else if (mode == "linear")
      path.interpolation = PathInterpolation::Linear;
    else
      throw InputError(cat(where, ": interpolation ", excerpt(mode.dump()), ": use \"smooth\" or \"linear\""));
  }
  if (!root.contains("keys") || !root["keys"].is_array())
    throw InputError(
        cat(where, ": keys: give an array of keys, each {\"time\": seconds, <a camera in any form of a camera file>}"));
  const json& keys = root["keys"];
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const std::string name = cat(where, ": keys[", i, "]");
    if (!keys[i].is_object())
      throw InputError(cat(name, ": give an object {\"time\": seconds, <a camera in any form of a camera file>}"));
    json camera = keys[i];
    if (!camera.contains("time") || !camera["time"].is_number())
      throw InputError(cat(name, ".time: required, in seconds"));
    PathKey key;
    key.timeSeconds = camera["time"].get<double>();
    camera.erase("time");
    const CameraFile file = parseCameraJson(camera.dump(), name);
    if (camera.contains("near")) path.nearFromScene = false;
    if (camera.contains("far")) path.farFromScene = false;
    const bool physical = file.physical.has_value();
    if (i > 0 && physical != path.viewKeys.empty())
      throw InputError(cat(name, ": is in the ", physical ? "physical" : "lecture or OpenCV",
                           " form where keys[0] is not; give every key in the physical form (a photographer's "
                           "focal length and sensor), or every key in the lecture or OpenCV form (a calibrated K)"));
    if (!physical) {
      path.viewKeys.push_back({key.timeSeconds, file.camera});
      continue;
    }
    key.camera = *file.physical;
    key.lens = file.camera.lens;
    // The iris and the lens's squeeze do not change along a shot: one shape for every key.
    if (!path.keys.empty() && key.lens.aperture != path.keys.front().lens.aperture)
      throw InputError(cat(name, ": \"aperture\" is ", describeAperture(key.lens.aperture),
                           " where the first key's is ", describeAperture(path.keys.front().lens.aperture),
                           "; every key of a path takes the same aperture shape"));
    if (!path.keys.empty() && key.lens.barrel != path.keys.front().lens.barrel)
      throw InputError(
          cat(name, ": \"barrel\" differs from the first key's; every key of a path takes the same lens barrel"));
    if (!path.keys.empty() && key.lens.effects.distortion.fisheye != path.keys.front().lens.effects.distortion.fisheye)
      throw InputError(cat(name,
                           ": \"distortion.model\" differs from the first key's; every key of a path takes one "
                           "distortion model (fisheye or opencv), whose coefficients are interpolated"));
    path.keys.push_back(key);
  }
  validate(path, where);
  return path;
}

CameraPath loadCameraPath(const std::filesystem::path& file) {
  return parseCameraPath(readTextFile(file, "camera path"), file.string());
}

}  // namespace lenslab
