#pragma once
// The three forms of a camera file (io/CameraJson.h), one file each: the lecture form
// (LectureCameraJson.cpp), the physical form (PhysicalCameraJson.cpp) and OpenCV's calibration
// (OpenCvCameraJson.cpp). Each builds the camera from its own keys; the lens-effect keys, common to
// all three, are read after it through the effect modules (CameraJson.cpp, parseCommon).
#include "io/CameraJson.h"
#include "io/JsonReader.h"

#include <set>
#include <string>

namespace lenslab {

extern const std::set<std::string> kLectureKeys;
extern const std::set<std::string> kPhysicalKeys;
// The OpenCV form: intrinsics as "intrinsics" or "K" (+ "width", "height"), the pose as eye/target/up
// or R/t, OpenCV's distCoeffs as "dist" (or "distortion").
extern const std::set<std::string> kOpenCvFormKeys;
// Keys that only the OpenCV form takes: any of them selects it.
extern const std::set<std::string> kOpenCvOnlyKeys;

CameraFile parseLecture(const JsonReader& r);
CameraFile parsePhysical(const JsonReader& r);
CameraFile parseOpenCv(const JsonReader& r);

// "aperture_radius" (world units), 0 when absent: a pinhole (the lecture and OpenCV forms).
double apertureRadiusOf(const JsonReader& r);
// "image_size": [width, height], whole pixels from 1 to kMaxImageSidePx (any form).
ImageSize imageSizeOf(const JsonReader& r);

}  // namespace lenslab
