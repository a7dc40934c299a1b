#include "core/Error.h"
#include "io/ImageCompare.h"
#include "io/ImageFile.h"

#include "../common/temp_dir_test.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

class ImageFileTest : public test::TempDirTest {};

Image ramp() {
  Image image(16, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x)
      image.set(x, y, {static_cast<float>(x) / 15.0f, static_cast<float>(y) / 7.0f, 0.25f, 1.0f});
  return image;
}

// EXR carries coverage in alpha; PNG is RGB only (its colour is already over the background, so
// an alpha channel would make a viewer composite it twice).
TEST_F(ImageFileTest, ExrKeepsCoverageInAlphaAndPngHasNoAlpha) {
  Image image = ramp();
  image.set(2, 1, {0.5f, 0.5f, 0.5f, 0.25f});
  writeImage(dir_ / "a.exr", image);
  writeImage(dir_ / "a.png", image);
  EXPECT_EQ(readImage(dir_ / "a.exr").at(2, 1).a, 0.25f);
  EXPECT_EQ(readImage(dir_ / "a.png").at(2, 1).a, 1.0f);
}

TEST_F(ImageFileTest, ExrKeepsLinearValuesExactly) {
  Image image = ramp();
  image.set(3, 3, {4.5f, -0.25f, 1e-6f, 1.0f});  // HDR and negative values survive in EXR
  writeImage(dir_ / "a.exr", image);
  const Image back = readImage(dir_ / "a.exr");
  EXPECT_EQ(compareImages(image, back, 0.0).maxAbs, 0.0);
  EXPECT_EQ(fileCount(), 1u) << "no temporary file left behind";
}

TEST_F(ImageFileTest, PngIsSrgbEncodedAndDecodesBackWithinQuantisation) {
  const Image image = ramp();
  writeImage(dir_ / "a.png", image);
  const Image back = readImage(dir_ / "a.png");
  const ImageDifference d = compareImages(displayEncoded(image), displayEncoded(back), 0.0);
  EXPECT_EQ(d.maxAbs, 0.0) << "8-bit values round-trip exactly";
  // sRGB 128/255 is 0.2158 in linear light (IEC 61966-2-1), and linear 0.5 is sRGB 188.
  EXPECT_NEAR(linearFromSrgb(128.0f / 255.0f), 0.2158f, 1e-4f);
  Image grey(1, 1);
  grey.set(0, 0, {0.5f, 0.2158f, 0.0f, 1.0f});
  EXPECT_NEAR(displayEncoded(grey).rgba[0] * 255.0f, 188.0f, 1e-3f);
  EXPECT_NEAR(displayEncoded(grey).rgba[1] * 255.0f, 128.0f, 1e-3f);
}

TEST_F(ImageFileTest, RefusesUnknownExtensionsBeforeWriting) {
  EXPECT_THROW(writeImage(dir_ / "a.jpg", ramp()), InputError);
  EXPECT_THROW(checkImageExtension("out.tif"), InputError);
  EXPECT_NO_THROW(checkImageExtension("OUT.PNG"));
  EXPECT_EQ(fileCount(), 0u);
}

TEST_F(ImageFileTest, MissingFolderIsAClearErrorAndWritesNothing) {
  try {
    writeImage(dir_ / "no-such-folder" / "a.png", ramp());
    FAIL() << "wrote into a missing folder";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
  }
  EXPECT_EQ(fileCount(), 0u);
}

TEST(ImageCompare, PsnrAndFractionOver) {
  Image a(10, 10), b(10, 10);
  b.set(0, 0, {0.5f, 0.0f, 0.0f, 0.0f});
  const ImageDifference d = compareImages(a, b, 0.1);
  EXPECT_FLOAT_EQ(static_cast<float>(d.maxAbs), 0.5f);
  EXPECT_DOUBLE_EQ(d.fractionOver, 0.01);
  // mse = 0.25 / 300
  EXPECT_NEAR(d.psnrDb, 10.0 * std::log10(300.0 / 0.25), 1e-9);
  EXPECT_TRUE(std::isinf(compareImages(a, a, 0.0).psnrDb));
  EXPECT_THROW(compareImages(a, Image(5, 5), 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace lenslab
