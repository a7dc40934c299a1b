#pragma once
// The AOVs (core/Aovs.h) in the forms vision pipelines read, one file an AOV beside the image
// (`--aov-format`): NumPy's .npy (numpy.load, OpenCV's cv2 via numpy, PyTorch) or 16-bit PNG
// (cv2.imread(..., cv2.IMREAD_UNCHANGED), the depth format of TUM RGB-D and ScanNet), or EXR
// channels (inside the image when it is an EXR, else an EXR of their own). The normals in GL's
// camera convention (x right, y up, z toward the viewer) or OpenCV's (x right, y down, z forward).
//
// File by file, for an image IMAGE.png or IMAGE.exr:
//   exr    IMAGE.exr's channels (io/AovChannels.h); beside a PNG, IMAGE.aov.exr holds them alone
//   npy    IMAGE.depth.npy     float32 (H, W), world units (metres), +inf where nothing is hit
//          IMAGE.normal.npy    float32 (H, W, 3), unit; 0 where nothing is hit
//          IMAGE.albedo.npy    float32 (H, W, 3), linear
//          IMAGE.instance.npy  int32 (H, W): the instance id (instances.json), 0 where nothing is hit
//          IMAGE.flow.npy      float32 (H, W, 2): pixels to the next frame (x right, y down), NaN unknown
//   png16  IMAGE.depth.png     uint16 millimetres, 0 where nothing is hit; beyond 65.535 m held
//                              at 65535 (and warned of)
//          IMAGE.normal.png    uint16 RGB, (n + 1) / 2 · 65535
//          IMAGE.albedo.png    uint16 RGB, linear (not sRGB) × 65535, clamped to [0, 1]
//          IMAGE.instance.png  uint16 instance id, 0 where nothing is hit (ids up to 65535)
//          IMAGE.flow.png      KITTI's flow PNG: uint16 RGB, u·64 + 2¹⁵, v·64 + 2¹⁵, 1 where known
// The instance id of a surface is its glTF node index + 1 (the EXR channel keeps the node index,
// −1 where nothing is hit).
#include "core/Aovs.h"
#include "io/AtomicFile.h"
#include "io/ImageFile.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace lenslab {

enum class AovFormat { Exr, Npy, Png16 };
enum class NormalConvention { Gl, OpenCv };

struct AovOutput {
  AovSelection selection;
  AovFormat format = AovFormat::Exr;
  NormalConvention normals = NormalConvention::Gl;
};

// "exr", "npy", "png16"; "gl", "opencv".
AovFormat parseAovFormat(const std::string& text);
NormalConvention parseNormalConvention(const std::string& text);

// The files the AOVs go to beside `image` (none when they are channels of an EXR image).
std::vector<std::filesystem::path> aovFilePaths(const AovOutput& output, const std::filesystem::path& image);

// The normals of `images` turned into `convention` (GL's is how they are computed).
void applyNormalConvention(AovImages& images, NormalConvention convention);

// The AOV files of `images` beside `image`, into `outputs` (they appear with the image); the
// channels the image itself takes (exr format and an EXR image), else none. `warnings` gets a
// line for each value a file could not hold. Throws InputError for an instance id past 65535 in
// a 16-bit PNG.
std::vector<ImageChannel> writeAovFiles(OutputSet& outputs, const std::filesystem::path& image, AovImages images,
                                        const AovOutput& output, std::vector<std::string>& warnings);

// A .npy file (format 1.0) of little-endian values: float32 ('<f4') or int32 ('<i4'), `shape`
// C-ordered.
std::string encodeNpy(const std::vector<float>& values, const std::vector<std::size_t>& shape);
std::string encodeNpy(const std::vector<std::int32_t>& values, const std::vector<std::size_t>& shape);

// A 16-bit PNG of `channels` (1 or 3) values a pixel, rows from the top.
std::string encodePng16(const std::filesystem::path& name, const std::vector<std::uint16_t>& values, int width,
                        int height, int channels);

}  // namespace lenslab
