#pragma once
// COLMAP's sparse model in its binary format (cameras.bin, images.bin, points3D.bin), as COLMAP's
// reconstruction reader and writer lay it out: little-endian, no padding.
//   cameras.bin   uint64 count; per camera: uint32 CAMERA_ID, int32 MODEL_ID, uint64 WIDTH,
//                 uint64 HEIGHT, double PARAMS[the model's count]
//   images.bin    uint64 count; per image: uint32 IMAGE_ID, double QW QX QY QZ, double TX TY TZ,
//                 uint32 CAMERA_ID, NAME as bytes ending in a 0 byte, uint64 POINTS2D count, then
//                 per point: double X, double Y, uint64 POINT3D_ID
//   points3D.bin  uint64 count; per point: uint64 ID, double XYZ[3], uint8 RGB[3], double ERROR,
//                 uint64 track length, then per element: uint32 IMAGE_ID, uint32 POINT2D_IDX
// Model ids are COLMAP's (src/colmap/sensor/models.h): 0 SIMPLE_PINHOLE … 11
// RAD_TAN_THIN_PRISM_FISHEYE. The conventions of the values are io/ColmapModel.h's; the records
// become the same ColmapCamera and ColmapImage the text reader gives, with each message naming the
// file and the record ("sparse/cameras.bin: camera record 3: ...").
#include "io/ColmapModel.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lenslab {

// A binary model's file is read whole: images.bin holds every image's 2D points, hundreds of
// megabytes for a large reconstruction.
constexpr std::uintmax_t kMaxColmapBinaryBytes = std::uintmax_t{2} << 30;

// COLMAP's id of a model name, and the number of parameters the model takes; empty for a name
// COLMAP does not define.
struct ColmapModelId {
  int id;
  std::size_t parameterCount;
};
std::optional<ColmapModelId> colmapModelId(const std::string& name);

// Each throws InputError naming the file and the record: a file that ends inside a record, a
// count the file cannot hold, a model id COLMAP does not define, a size or id out of range, a
// quaternion off unit length (as the text reader), an ID or NAME given twice, bytes after the last
// record.
std::vector<ColmapCamera> parseColmapCamerasBinary(std::string_view bytes, const std::string& file);
std::vector<ColmapImage> parseColmapImagesBinary(std::string_view bytes, const std::string& file);

// The files' bytes. A camera whose model COLMAP does not define is a logic error (lenslab writes
// only the models colmapCameraOf picks).
std::string colmapCameraRecord(const ColmapCamera& camera);
std::string colmapImageRecord(const ColmapImage& image);  // with no POINTS2D
std::string colmapCountField(std::uint64_t count);        // a file's leading count
std::string colmapPoints3DBinary();                       // no points

}  // namespace lenslab
