// COLMAP's binary model: files laid out here byte by byte from COLMAP's format (not by the writer
// under test) read as the text reader reads the same model; the writer's bytes read back exactly;
// each way a file can be broken refused naming the file and the record.
#include "io/ColmapBinary.h"

#include "core/Error.h"
#include "io/ColmapExport.h"

#include "../common/refusal.h"
#include "../common/temp_dir_test.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace lenslab {
namespace {

// A file's bytes, little-endian, put together field by field.
struct Bytes {
  std::string data;
  template <class T>
  Bytes& put(T value) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    data.append(raw, sizeof(T));
    return *this;
  }
  Bytes& text(const std::string& s) {
    data += s;
    data += '\0';
    return *this;
  }
};

bool has(const std::string& message, const std::string& part) { return message.find(part) != std::string::npos; }

// Two cameras: a PINHOLE (id 1) and a FOV (id 9, which lenslab reads but does not render).
std::string twoCameras() {
  Bytes b;
  b.put(std::uint64_t{2});
  b.put(std::uint32_t{1}).put(std::int32_t{1}).put(std::uint64_t{640}).put(std::uint64_t{480});
  for (const double p : {500.0, 501.5, 320.25, 239.75}) b.put(p);
  b.put(std::uint32_t{9}).put(std::int32_t{7}).put(std::uint64_t{64}).put(std::uint64_t{48});
  for (const double p : {40.0, 40.0, 32.0, 24.0, 0.9}) b.put(p);  // FOV: fx, fy, cx, cy, omega
  return b.data;
}

// Two images, the first with two POINTS2D (skipped), the second's name holding a space (which the
// binary format can hold).
std::string twoImages() {
  Bytes b;
  b.put(std::uint64_t{2});
  b.put(std::uint32_t{4});
  for (const double v : {1.0, 0.0, 0.0, 0.0, 0.5, -0.25, 3.0}) b.put(v);
  b.put(std::uint32_t{1}).text("left/a.png").put(std::uint64_t{2});
  for (int k = 0; k < 2; ++k) b.put(10.5 * k).put(20.5).put(std::uint64_t{77});
  b.put(std::uint32_t{5});
  for (const double v : {0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 2.0}) b.put(v);
  b.put(std::uint32_t{9}).text("b b.png").put(std::uint64_t{0});
  return b.data;
}

TEST(ColmapBinary, ReadsCamerasAndImagesAsLaidOut) {
  const std::vector<ColmapCamera> c = parseColmapCamerasBinary(twoCameras(), "cameras.bin");
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].id, 1u);
  EXPECT_EQ(c[0].model, "PINHOLE");
  EXPECT_EQ(c[0].widthPx, 640);
  EXPECT_EQ(c[0].heightPx, 480);
  EXPECT_EQ(c[0].params, (std::vector<double>{500.0, 501.5, 320.25, 239.75}));
  EXPECT_EQ(c[1].model, "FOV");
  EXPECT_EQ(c[1].params.size(), 5u);
  EXPECT_EQ(c[1].record, 2);
  // The same camera from the text reader gives the same lens.
  const ColmapCamera text = parseColmapCameras("1 PINHOLE 640 480 500 501.5 320.25 239.75\n", "cameras.txt")[0];
  EXPECT_EQ(lensOf(text, "t").intrinsics.fx, lensOf(c[0], "b").intrinsics.fx);
  EXPECT_EQ(lensOf(text, "t").intrinsics.cy, lensOf(c[0], "b").intrinsics.cy);
  EXPECT_TRUE(has(test::refusalOf([&] { lensOf(c[1], "cameras.bin"); }), "cameras.bin: record 2: camera 9 is FOV"));

  const std::vector<ColmapImage> i = parseColmapImagesBinary(twoImages(), "images.bin");
  ASSERT_EQ(i.size(), 2u);
  EXPECT_EQ(i[0].id, 4u);
  EXPECT_EQ(i[0].name, "left/a.png");
  EXPECT_EQ(i[0].translation, glm::dvec3(0.5, -0.25, 3.0));
  EXPECT_EQ(i[0].cameraId, 1u);
  EXPECT_EQ(i[1].name, "b b.png");
  EXPECT_EQ(i[1].rotation.x, 1.0);
  EXPECT_EQ(i[1].cameraId, 9u);
}

TEST(ColmapBinary, TheWritersRecordsReadBackExactly) {
  ColmapCamera camera;
  camera.id = 3;
  camera.model = "FULL_OPENCV";
  camera.widthPx = 1920;
  camera.heightPx = 1080;
  camera.params = {1500.1, 1499.9, 962.3, 541.7, -0.3, 0.1, 1e-3, -2e-3, 0.01, 0.05, 0.002, 1e-4};
  const std::string cameras = colmapCountField(1) + colmapCameraRecord(camera);
  const ColmapCamera back = parseColmapCamerasBinary(cameras, "c.bin").at(0);
  EXPECT_EQ(back.id, 3u);
  EXPECT_EQ(back.model, "FULL_OPENCV");
  EXPECT_EQ(back.params, camera.params);
  ColmapImage image;
  image.id = 12;
  image.rotation = glm::dquat(0.5, 0.5, -0.5, 0.5);
  image.translation = {1.0 / 3.0, -2.0, 1e-9};
  image.cameraId = 3;
  image.name = "frames/frame_0011.png";
  const ColmapImage read = parseColmapImagesBinary(colmapCountField(1) + colmapImageRecord(image), "i.bin").at(0);
  EXPECT_EQ(read.rotation, image.rotation);
  EXPECT_EQ(read.translation, image.translation);
  EXPECT_EQ(read.name, image.name);
  EXPECT_EQ(colmapPoints3DBinary(), std::string(8, '\0'));
  EXPECT_EQ(colmapModelId("THIN_PRISM_FISHEYE")->id, 10);
  EXPECT_FALSE(colmapModelId("NOT_A_MODEL").has_value());
}

TEST(ColmapBinary, BrokenFilesAreRefusedNamingTheFileAndTheRecord) {
  const auto camerasError = [](const std::string& bytes) {
    return test::refusalOf([&] { parseColmapCamerasBinary(bytes, "sparse/cameras.bin"); });
  };
  const std::string good = twoCameras();
  EXPECT_TRUE(has(camerasError(good.substr(0, good.size() - 1)),
                  "sparse/cameras.bin: camera record 2: the file ends inside a parameter"));
  EXPECT_TRUE(has(camerasError(good + "x"), "1 bytes follow the last record"));
  const std::string huge = Bytes().put(std::uint64_t{1} << 60).data;
  EXPECT_TRUE(
      has(camerasError(huge), "the number of cameras is 1152921504606846976, but the 0 bytes left hold at most 0"))
      << camerasError(huge);
  std::string badModel = good;
  const std::int32_t twelve = 12;
  std::memcpy(&badModel[12], &twelve, 4);
  EXPECT_TRUE(has(camerasError(badModel), "camera record 1: camera 1 has MODEL_ID 12, which COLMAP does not define"));
  std::string twice = good;
  const std::uint32_t one = 1;
  std::memcpy(&twice[8 + 56], &one, 4);
  EXPECT_TRUE(has(camerasError(twice), "CAMERA_ID 1 is given again (first in record 1)"));
  std::string zeroWide = good;
  std::memset(&zeroWide[16], 0, 8);
  EXPECT_TRUE(has(camerasError(zeroWide), "camera 1 is 0x480 pixels"));

  const auto imagesError = [](const std::string& bytes) {
    return test::refusalOf([&] { parseColmapImagesBinary(bytes, "images.bin"); });
  };
  std::string longQuaternion = twoImages();
  const double two = 2.0;
  std::memcpy(&longQuaternion[12], &two, 8);  // QW of the first image
  EXPECT_TRUE(has(imagesError(longQuaternion), "image record 1: image 4's quaternion QW QX QY QZ has length"));
  const std::string images = twoImages();
  std::string unterminated = images.substr(0, 82);  // up to the name's 0 byte
  unterminated[0] = 1;                              // one image: its name runs to the end of the file
  EXPECT_TRUE(has(imagesError(unterminated), "image record 1: NAME has no terminating 0 byte"))
      << imagesError(unterminated);
  std::string manyPoints = images;
  const std::uint64_t lots = std::uint64_t{1} << 40;
  std::memcpy(&manyPoints[8 + 4 + 56 + 4 + 11], &lots, 8);
  EXPECT_TRUE(has(imagesError(manyPoints), "the number of POINTS2D is 1099511627776"));
}

class ColmapBinaryFolder : public test::TempDirTest {};

TEST_F(ColmapBinaryFolder, RenderCamerasComeFromTheBinaryModel) {
  std::ofstream(dir_ / "cameras.bin", std::ios::binary) << twoCameras();
  std::ofstream(dir_ / "images.bin", std::ios::binary) << twoImages();
  const ColmapModel model = readColmapModel(dir_);
  EXPECT_EQ(model.images.size(), 2u);
  const Camera camera = colmapImageCamera(model, "left/a.png");
  EXPECT_EQ(camera.calibratedSize->widthPx, 640);
  // Image "b b.png" uses the FOV camera, refused when asked for, naming its record.
  EXPECT_TRUE(
      has(test::refusalOf([&] { colmapImageCamera(model, "b b.png"); }), "cameras.bin: record 2: camera 9 is FOV"));
}

}  // namespace
}  // namespace lenslab
