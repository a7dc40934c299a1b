#pragma once
// Camera files (JSON), in one of three forms: lecture, physical, OpenCV intrinsics.
//
// Lecture form — the viewing description itself:
//   {"projection": "perspective" | "parallel",      default "perspective"
//    "vrp": [x, y, z], "vpn": [x, y, z],            required (world)
//    "vup": [x, y, z],                              default [0, 1, 0]
//    "prp": [u, v, n],                              required (view-reference coordinates)
//    "window": [umin, vmin, umax, vmax],            required (on the view plane)
//    "near": d, "far": d | "infinity",              defaults: near = prp.n / 1000 (perspective)
//                                                   or 0 (parallel); far = infinity
//                                                   (perspective; required for parallel)
//    "aperture_radius": r,                          default 0 (a pinhole); the view plane is the
//                                                   plane of focus
//    "focus_distance": d | "infinity"}              default: the view plane is the plane of focus;
//                                                   else as --focus-distance (refocused())
// Physical form — a photographer's description (world units are metres):
//   {"eye": [x, y, z], "target": [x, y, z],         required
//    "up": [x, y, z],                               default [0, 1, 0]
//    "focal_length_mm": 35, "sensor_mm": [36, 24],  defaults
//    "f_number": 2.8,                               default: none (a pinhole)
//    "focus_distance": d | "infinity",              default |target − eye|
//    "near": 0.05, "far": d | "infinity",           defaults
//    "shutter_s": 0.01, "iso": 100}                 default: none (no physical exposure; iso
//                                                   alone is refused); camera/Exposure.h
// OpenCV form — a calibrated pinhole (chosen by any of intrinsics, K, R, t, dist):
//   intrinsics: {"intrinsics": {"fx", "fy", "cx", "cy", "width", "height"}}, or
//               {"K": [[fx, 0, cx], [0, fy, cy], [0, 0, 1]], "width": W, "height": H} (or
//               "image_size"); pixels in OpenCV's convention (pixel centres on integers)
//   pose:       {"eye", "target", "up"} as in the physical form, or OpenCV's {"R": 3×3 row by row,
//               "t": [x, y, z]}: X_cam = R·X_world + t, x right, y down, z forward
//   "dist": [k1, k2, p1, p2(, k3)] (or "distortion"), "focus_distance", "aperture_radius",
//   "near", "far". With R and t and no focus_distance the camera is a pinhole whose view plane is
//   at unit distance (near defaults to 1/1000 of it); an aperture needs a focus_distance.
// Unknown keys, wrong types and mixed forms are errors naming the file and the key.
#include "camera/Camera.h"
#include "camera/PhysicalCamera.h"

#include <filesystem>
#include <optional>
#include <string>

namespace lenslab {

struct CameraFile {
  enum class Form { Lecture, Physical, Intrinsics };
  Form form = Form::Lecture;  // which of the three forms the file is in
  Camera camera;
  std::optional<PhysicalCamera> physical;  // when given in the physical form
};

CameraFile parseCameraJson(const std::string& text, const std::string& where);
CameraFile loadCameraJson(const std::filesystem::path& file);

// The lecture form of `camera` as JSON text (what `view` will save and `render` loads back).
std::string toCameraJson(const Camera& camera);

// A physical camera with `lens`'s effects, aperture shape and barrel (its radius is the camera's
// f/2N), as seen on an image of `size`, in the OpenCV-intrinsics form (K, distCoeffs as an array
// when the lens is all OpenCV's, plus focus_distance and aperture_radius): one file both
// `lenslab render --camera` and vision tools read. `capture` writes one per frame. near / far are
// written only when asked; left out, the renderer fits them to the scene. A shaped aperture is
// written as "aperture", a barrel as "barrel".
std::string toIntrinsicsCameraJson(const PhysicalCamera& camera, const Lens& lens, ImageSize size, bool writeNear,
                                   bool writeFar);

// Any perspective camera with its lens, as seen on an image of `size`, in the OpenCV form with
// OpenCV's pose: K, R, t, distCoeffs (where the lens is all OpenCV's), focus_distance,
// aperture_radius, the other lens effects, aperture shape and barrel; near / far only when asked.
// Read back, it is the same camera (to rounding): what `capture` writes for a frame whose camera
// has no physical description (a calibrated camera, a lecture-form view). Throws InputError for a
// parallel projection.
std::string toOpenCvCameraJson(const Camera& camera, ImageSize size, bool writeNear, bool writeFar);

}  // namespace lenslab
