// The AOVs as a user names them (--aov) and as an EXR holds them: the names parsed, unknown ones
// refused naming the valid ones, each AOV's channels named and ordered, and every channel written
// and read back bit for bit (the instance's integers, +inf depth), the colour unchanged; a PNG
// refuses them.
#include "../common/temp_dir_test.h"
#include "core/Aovs.h"
#include "core/Error.h"
#include "io/AovChannels.h"
#include "io/ImageFile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

namespace lenslab {
namespace {

TEST(AovNames, ParsesEachNameAndRefusesAnUnknownOneNamingTheValidOnes) {
  const AovSelection s = parseAovs({"instance", "depth", "depth"});
  EXPECT_TRUE(s.depth && s.instance);
  EXPECT_FALSE(s.normal || s.albedo);
  EXPECT_EQ(s.names(), (std::vector<std::string>{"depth", "instance"}));
  EXPECT_EQ(aovList(s), "depth,instance");
  EXPECT_FALSE(parseAovs({}).any());
  try {
    parseAovs({"depth", "normals"});
    FAIL() << "normals was taken";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("--aov normals"), std::string::npos) << message;
    EXPECT_NE(message.find("depth, normal, albedo, instance, flow"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(AovNames, ChannelsFollowOpenExrNamesInTheSelectionsOrder) {
  EXPECT_EQ(aovChannelNames(parseAovs(aovNames())),
            (std::vector<std::string>{"Z", "N.X", "N.Y", "N.Z", "albedo.R", "albedo.G", "albedo.B", "instance",
                                      "flow.X", "flow.Y"}));
  EXPECT_EQ(aovChannelNames(parseAovs({"albedo"})), (std::vector<std::string>{"albedo.R", "albedo.G", "albedo.B"}));
}

class AovFiles : public test::TempDirTest {};

TEST_F(AovFiles, EveryChannelRoundTripsBitForBitBesideTheUnchangedColour) {
  Image image(3, 2);
  for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = 0.1f * static_cast<float>(i);
  const float inf = std::numeric_limits<float>::infinity();
  AovImages aovs;
  aovs.widthPx = 3;
  aovs.heightPx = 2;
  aovs.depth = {1.0f, 2.5f, inf, 1e6f, 0.001f, 7.0f};
  aovs.normal = {0, 0, 1, 0.6f, 0, 0.8f, 0, 0, 0, -0.28f, 0.96f, 0, 0, 1, 0, 1, 0, 0};
  aovs.albedo = {0.2f, 0.45f, 0.7f, 1, 1, 1, 0, 0, 0, 0.5f, 0.25f, 0.125f, 0, 0, 0, 3e-3f, 2e-2f, 1e-1f};
  // glTF node indices up to 2^24, the last integer before float skips odd ones.
  aovs.instance = {0.0f, 1.0f, kNoSurfaceInstance, 16777216.0f, 16777215.0f, 42.0f};
  const auto file = dir_ / "f.exr";
  OutputSet outputs;
  writeImage(outputs, file, image, aovChannels(aovs));
  outputs.commit();
  const std::vector<std::string> names = channelNames(file);
  for (const char* n : {"R", "G", "B", "A", "Z", "N.X", "N.Y", "N.Z", "albedo.R", "albedo.G", "albedo.B", "instance"})
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
  EXPECT_EQ(names.size(), 12u);
  EXPECT_EQ(readChannel(file, "Z"), aovs.depth);
  EXPECT_EQ(readDepthChannel(file), aovs.depth);
  EXPECT_EQ(readChannel(file, "instance"), aovs.instance);
  const char* axes[] = {"N.X", "N.Y", "N.Z"};
  const char* colours[] = {"albedo.R", "albedo.G", "albedo.B"};
  for (std::size_t k = 0; k < 3; ++k) {
    const std::vector<float> n = readChannel(file, axes[k]), a = readChannel(file, colours[k]);
    for (std::size_t i = 0; i < 6; ++i) {
      EXPECT_EQ(n[i], aovs.normal[3 * i + k]) << axes[k] << " " << i;
      EXPECT_EQ(a[i], aovs.albedo[3 * i + k]) << colours[k] << " " << i;
    }
  }
  EXPECT_EQ(readImage(file).rgba, image.rgba);
  EXPECT_THROW(readChannel(file, "N.W"), InputError);
  OutputSet png;
  EXPECT_THROW(writeImage(png, dir_ / "f.png", image, aovChannels(aovs)), InputError);
}

}  // namespace
}  // namespace lenslab
