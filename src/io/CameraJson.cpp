#include "io/CameraJson.h"

#include "camera/LensMap.h"
#include "camera/Projection.h"
#include "core/Error.h"
#include "core/NumberInput.h"
#include "core/Text.h"
#include "core/TextFile.h"
#include "io/CameraJsonForms.h"
#include "io/JsonDocument.h"
#include "lens/effects/LensEffectRegistry.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace lenslab {
namespace {

using nlohmann::json;

// What the lens-effect modules need of the camera the form built.
LensFrame lensFrameOf(const CameraFile& file, const std::string& where) {
  LensFrame frame;
  frame.where = where;
  frame.inverseFocus = file.camera.inverseFocusDistance();
  frame.cornerRadius = normalisedWindow(file.camera.view).cornerRadius();
  frame.perspective = file.camera.view.projection == Projection::Perspective;
  if (file.physical) frame.focalLength = file.physical->focalLengthMm * kMetresPerMillimetre;
  return frame;
}

// The keys any form takes: the image size, and each lens effect's (lens/effects/).
std::set<std::string> commonKeys() {
  std::set<std::string> keys = lensEffectKeys();
  keys.insert("image_size");
  return keys;
}

// image_size and every lens effect's key, on a camera already built.
void parseCommon(const JsonReader& r, CameraFile& file) {
  Camera& camera = file.camera;
  if (r.has("image_size")) camera.calibratedSize = imageSizeOf(r);
  const LensFrame frame = lensFrameOf(file, r.where());
  for (const LensEffectModule* module : lensEffectModules()) module->read(r, frame, camera.lens);
  validateLensEffects(camera, r.where(), frame.focalLength);
}

}  // namespace

CameraFile parseCameraJson(const std::string& text, const std::string& where) {
  const json root = parseJsonDocument(text, where);
  if (!root.is_object())
    throw InputError(cat(where, ": a camera file must hold a JSON object, not ", root.type_name()));

  const JsonReader reader(root, where);
  const std::set<std::string> common = commonKeys();
  const bool openCv = std::any_of(kOpenCvOnlyKeys.begin(), kOpenCvOnlyKeys.end(),
                                  [&](const std::string& key) { return root.contains(key); });
  if (openCv) {
    for (const auto& item : root.items())
      if (kOpenCvFormKeys.count(item.key()) == 0 && common.count(item.key()) == 0)
        throw InputError(cat(where, ": unknown key \"", excerpt(item.key()), "\" in an OpenCV camera; it takes ",
                             joinedKeys(kOpenCvFormKeys), " and ", joinedKeys(common)));
    CameraFile file = parseOpenCv(reader);
    parseCommon(reader, file);
    return file;
  }
  bool lecture = false;
  bool physical = false;
  for (const auto& [key, value] : root.items()) {
    if (common.count(key) > 0) continue;
    const bool inLecture = kLectureKeys.count(key) > 0;
    const bool inPhysical = kPhysicalKeys.count(key) > 0;
    if (!inLecture && !inPhysical)
      throw InputError(cat(where, ": unknown key \"", excerpt(key), "\"; the lecture form takes ",
                           joinedKeys(kLectureKeys), "; the physical form takes ", joinedKeys(kPhysicalKeys),
                           "; the OpenCV form (chosen by ", joinedKeys(kOpenCvOnlyKeys), ") takes ",
                           joinedKeys(kOpenCvFormKeys), "; any form takes ", joinedKeys(common)));
    if (inLecture && !inPhysical) lecture = true;
    if (inPhysical && !inLecture) physical = true;
  }
  if (lecture && physical)
    throw InputError(cat(where,
                         ": mixes the lecture form (vrp, vpn, prp, window, ...) with the physical form "
                         "(eye, target, focal_length_mm, ...); use one"));
  if (physical || lecture) {
    CameraFile file = physical ? parsePhysical(reader) : parseLecture(reader);
    parseCommon(reader, file);
    return file;
  }
  throw InputError(cat(where,
                       ": no camera in it; give the lecture form (vrp, vpn, prp, window) or the "
                       "physical form (eye, target, focal_length_mm, ...)"));
}

CameraFile loadCameraJson(const std::filesystem::path& file) {
  return parseCameraJson(readTextFile(file, "camera file"), file.string());
}

}  // namespace lenslab
