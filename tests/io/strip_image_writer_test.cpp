// The strip writer's files equal writeImage's, pixel for pixel, and appear whole or not at all.
#include "core/Error.h"
#include "io/ImageFile.h"
#include "io/StripImageWriter.h"

#include "../common/temp_dir_test.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <random>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

class StripImageWriterTest : public test::TempDirTest {};

// Values past [0, 1] and negative ones too: PNG clamps them, EXR keeps them.
Image noise(int width, int height) {
  Image image(width, height);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> value(-0.2f, 1.3f);
  for (float& v : image.rgba) v = value(rng);
  return image;
}

Image block(const Image& image, int x0, int y0, int x1, int y1) {
  Image out(x1 - x0, y1 - y0);
  for (int y = y0; y < y1; ++y)
    std::memcpy(&out.rgba[out.offset(0, y - y0)], &image.rgba[image.offset(x0, y)],
                static_cast<std::size_t>(x1 - x0) * 4 * sizeof(float));
  return out;
}

// In tiles of 7 x 5 (the last column and row smaller), strip by strip.
void writeInTiles(const fs::path& path, const Image& image) {
  OutputSet outputs;
  StripImageWriter writer(outputs, path, {image.width, image.height});
  for (int y0 = 0; y0 < image.height; y0 += 5)
    for (int x0 = 0; x0 < image.width; x0 += 7)
      writer.add(x0, y0, block(image, x0, y0, std::min(x0 + 7, image.width), std::min(y0 + 5, image.height)));
  writer.finish();
  EXPECT_FALSE(fs::exists(path)) << "before the set is committed";
  outputs.commit();
}

TEST_F(StripImageWriterTest, WritesWhatWriteImageWrites) {
  const Image image = noise(31, 17);
  for (const char* ext : {".png", ".exr"}) {
    writeImage(dir_ / (std::string("whole") + ext), image);
    writeInTiles(dir_ / (std::string("tiled") + ext), image);
    const Image whole = readImage(dir_ / (std::string("whole") + ext));
    const Image tiled = readImage(dir_ / (std::string("tiled") + ext));
    ASSERT_EQ(tiled.width, whole.width);
    ASSERT_EQ(tiled.height, whole.height);
    EXPECT_EQ(tiled.rgba, whole.rgba) << ext;
  }
}

TEST_F(StripImageWriterTest, LeavesNoFileWhenNotFinished) {
  const Image image = noise(16, 10);
  {
    OutputSet outputs;
    StripImageWriter writer(outputs, dir_ / "partial.png", {16, 10});
    writer.add(0, 0, block(image, 0, 0, 16, 5));
    EXPECT_THROW(writer.finish(), std::logic_error);  // rows 5 to 10 never came
  }
  EXPECT_FALSE(fs::exists(dir_ / "partial.png"));
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(StripImageWriterTest, RefusesBlocksOutOfOrder) {
  const Image image = noise(16, 10);
  OutputSet outputs;
  StripImageWriter writer(outputs, dir_ / "order.exr", {16, 10});
  EXPECT_THROW(writer.add(0, 5, block(image, 0, 5, 16, 10)), std::logic_error);  // not the first strip
  writer.add(0, 0, block(image, 0, 0, 8, 5));
  EXPECT_THROW(writer.add(8, 0, block(image, 8, 0, 16, 4)), std::logic_error);  // not the strip's rows
}

TEST_F(StripImageWriterTest, RefusesAnUnsupportedExtension) {
  OutputSet outputs;
  EXPECT_THROW(StripImageWriter(outputs, dir_ / "image.tif", {4, 4}), InputError);
}

}  // namespace
}  // namespace lenslab
