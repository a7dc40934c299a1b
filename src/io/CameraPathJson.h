#pragma once
// Camera path files (JSON) for headless capture (camera/CameraPath.h):
//   {"fps": 24,                                  required: frames per second
//    "keys": [{"time": 0.0, <a camera in any form of a camera file, lens effects allowed>}, …],
//    "frames": N,                                optional: else floor(last time × fps) + 1
//    "interpolation": "smooth" | "linear"}       default "smooth"
// Every key in the physical form (interpolated as camera/CameraPath.h says), or every key in the
// lecture or OpenCV form (as a pinhole's pose and K: camera/ViewPath.h).
// Each key is read as a camera file is (io/CameraJson.h), so its errors name the key
// ("path.json: keys[2]: unknown key \"fov\" …"); the path's own errors name the path's key.
#include "camera/CameraPath.h"

#include <filesystem>
#include <string>

namespace lenslab {

CameraPath parseCameraPath(const std::string& text, const std::string& where);
CameraPath loadCameraPath(const std::filesystem::path& file);

}  // namespace lenslab
