#pragma once
// COLMAP's sparse model in its text format (cameras.txt and images.txt; the binary format is
// io/ColmapBinary.h) read and turned into lenslab cameras (writing them is io/ColmapExport.h). COLMAP's conventions (its "Output Format"
// page and src/colmap/sensor/models.h), stated once here:
//   - An image's pose is world → camera: X_cam = R(q)·X_world + t, q = (QW, QX, QY, QZ) a unit
//     quaternion in the Hamilton convention (Eigen's), w first; the camera centre is −Rᵀt. The
//     camera frame is OpenCV's: x right, y down, z forward (the optical axis).
//   - Pixel coordinates put the image's top-left corner at (0, 0), so the centre of the top-left
//     pixel is (0.5, 0.5): lenslab's convention exactly. OpenCV puts that centre at (0, 0), so a
//     COLMAP principal point is OpenCV's plus 0.5.
//   - Lines starting with '#' are comments and blank lines are skipped; but each image takes two
//     lines, its pose line and then its POINTS2D line (X Y POINT3D_ID triples, possibly empty),
//     and the second is read as such whatever it holds, as COLMAP does.
//   - Fields are separated by spaces, so a NAME cannot hold one (COLMAP reads it up to the first).
// The distortion models COLMAP shares with OpenCV act on normalised coordinates (x/z, y/z) exactly
// as lenslab's Distortion does (lens/LensEffects.h), so those cameras are rendered exactly.
#include "camera/Camera.h"
#include "camera/Intrinsics.h"
#include "camera/Rotation.h"
#include "lens/LensEffects.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace lenslab {

// One line of cameras.txt: CAMERA_ID MODEL WIDTH HEIGHT PARAMS[].
struct ColmapCamera {
  std::uint32_t id = 0;
  std::string model;  // "PINHOLE", "OPENCV", ...
  int widthPx = 0;
  int heightPx = 0;
  std::vector<double> params;  // in the model's order, e.g. fx, fy, cx, cy for PINHOLE
  int line = 0;                // where it was read; 0 for one made here
  int record = 0;              // or its record in cameras.bin, from 1
};

// The pose line of an image in images.txt: IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME.
struct ColmapImage {
  std::uint32_t id = 0;
  glm::dquat rotation;          // unit length (normalised when read)
  glm::dvec3 translation{0.0};  // t
  std::uint32_t cameraId = 0;
  std::string name;  // relative to the image folder
  int line = 0;
  int record = 0;  // or its record in images.bin, from 1
};

struct ColmapModel {
  std::vector<ColmapCamera> cameras;
  std::vector<ColmapImage> images;
  std::string camerasFile = "cameras.txt";  // as messages name them
  std::string imagesFile = "images.txt";
};

// The camera models lenslab renders, for messages: SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL,
// OPENCV, FULL_OPENCV and the fisheyes OPENCV_FISHEYE, SIMPLE_RADIAL_FISHEYE and RADIAL_FISHEYE
// (lens/effects/Distortion.h's fisheye model).
extern const char* const kColmapModelsRendered;

// A quaternion may be off unit length by this much and is normalised: COLMAP writes 17 digits,
// other tools six or more (an error of ~1e-6). Further off, it is refused: the line is not what
// it claims to be (a column missing or swapped, another format).
constexpr double kQuaternionLengthTolerance = 1e-3;

// Each throws InputError "FILE:LINE: ..." naming the field and what would be valid. Cameras of
// models lenslab does not render are kept (other images may use them) and refused by lensOf.
std::vector<ColmapCamera> parseColmapCameras(const std::string& text, const std::string& file);
std::vector<ColmapImage> parseColmapImages(const std::string& text, const std::string& file);
// DIR's model, as COLMAP reads one: cameras.bin and images.bin where both are there, else
// cameras.txt and images.txt (points3D is not read); every image's CAMERA_ID must be in the
// cameras file.
ColmapModel readColmapModel(const std::filesystem::path& dir);

// A camera's intrinsics (in OpenCV's pixel convention: cx = COLMAP's cx − 0.5) and distortion.
// Throws InputError naming the file, the line and the models rendered for any other model.
struct OpenCvLens {
  OpenCvIntrinsics intrinsics;
  Distortion distortion;
};
OpenCvLens lensOf(const ColmapCamera& camera, const std::string& file);

// An image's pose, R from its quaternion.
OpenCvPose poseOf(const ColmapImage& image);

// The camera that took image `name`: its camera's intrinsics and distortion at its pose, a pinhole
// (pinholeFromOpenCv) whose default size is the camera's WIDTH × HEIGHT. Throws InputError for
// a name not in the model, listing some that are.
Camera colmapImageCamera(const ColmapModel& model, const std::string& name);
// The camera that took `image`, one of the model's.
Camera colmapImageCamera(const ColmapModel& model, const ColmapImage& image);

}  // namespace lenslab
