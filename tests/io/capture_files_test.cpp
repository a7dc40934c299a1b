// What `lenslab capture` names, splits and writes: frame patterns, ranges and shards, per-frame
// seeds, the frame's camera file (OpenCV intrinsics that `render --camera` reads back), the EXR's
// Z channel, and a manifest that processes append to at once.
#include "camera/Intrinsics.h"
#include "camera/PhysicalCamera.h"
#include "camera/Projection.h"
#include "core/Error.h"
#include "io/CameraJson.h"
#include "io/CameraPathJson.h"
#include "io/FrameSequence.h"
#include "io/ImageFile.h"
#include "io/JsonLines.h"

#include "../common/temp_dir_test.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <limits>
#include <set>
#include <thread>

namespace lenslab {
namespace {

TEST(FrameSequence, PatternsTakeOneIntegerConversion) {
  EXPECT_EQ(formatFramePath("out/frame_%04d.exr", 7), "out/frame_0007.exr");
  EXPECT_EQ(formatFramePath("f%d.png", 12345), "f12345.png");
  EXPECT_EQ(formatFramePath("f%3d.png", 5), "f  5.png");
  EXPECT_EQ(formatFramePath("100%%_%02d.png", 3), "100%_03.png");
  EXPECT_EQ(formatFramePath("f_%02d.png", 123), "f_123.png");  // wider than the field: all digits
  for (const char* bad : {"frame.png", "f_%d_%d.png", "f_%s.png", "f_%04x.png", "f_%.png", "f_%", "f_%40d.png"})
    EXPECT_THROW(checkFramePattern(bad, "--out"), InputError) << bad;
}

TEST(FrameSequence, RangesAreInclusiveAndInsideThePath) {
  const FrameRange all = parseFrameRange("0:72", 73);
  EXPECT_EQ(all.first, 0);
  EXPECT_EQ(all.last, 72);
  EXPECT_EQ(parseFrameRange("5:", 73).last, 72);
  EXPECT_EQ(parseFrameRange(":5", 73).first, 0);
  EXPECT_EQ(parseFrameRange("9", 73).first, 9);
  EXPECT_EQ(parseFrameRange("9", 73).last, 9);
  for (const char* bad : {"5:2", "0:73", "73", "-1:3", ":", "a:b", "1:2:3:4", ""}) {
    try {
      parseFrameRange(bad, 73);
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("0:72"), std::string::npos) << e.what();  // names what is valid
    }
  }
}

TEST(FrameSequence, AStepTakesEverySteppedFrameUpToTheEnd) {
  const auto frames = [](const char* text, Shard shard = {}) { return shardFrames(parseFrameRange(text, 73), shard); };
  EXPECT_EQ(frames("0:72:12"), (std::vector<int>{0, 12, 24, 36, 48, 60, 72}));
  EXPECT_EQ(frames("5:30:10"), (std::vector<int>{5, 15, 25}));  // the end need not be a frame taken
  EXPECT_EQ(frames("::24"), (std::vector<int>{0, 24, 48, 72}));
  EXPECT_EQ(frames("60::5"), (std::vector<int>{60, 65, 70}));
  EXPECT_EQ(frames(":30:15"), (std::vector<int>{0, 15, 30}));
  EXPECT_EQ(frames("3:3:7"), (std::vector<int>{3}));
  EXPECT_EQ(frames("0:72:1"), frames("0:72"));
  // Shards split the stepped frames, interleaved: together they are the whole list, once.
  std::vector<int> all;
  for (int i = 0; i < 3; ++i) {
    const std::vector<int> part = frames("0:72:12", {i, 3});
    all.insert(all.end(), part.begin(), part.end());
  }
  std::sort(all.begin(), all.end());
  EXPECT_EQ(all, frames("0:72:12"));
  EXPECT_EQ(frames("0:72:12", {1, 3}), (std::vector<int>{12, 48}));
  // A step that is not a whole number of frames from 1 up gets its own message.
  for (const char* bad : {"0:72:0", "0:72:-2", "0:72:x", "0:72:1.5", "0:72:", "::"}) {
    try {
      parseFrameRange(bad, 73);
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(
          std::string(e.what()).find("the step after the second colon must be a whole number of frames, 1 or more"),
          std::string::npos)
          << e.what();
    }
  }
}

TEST(FrameSequence, ShardsPartitionTheRangeInterleaved) {
  const FrameRange range{3, 20};
  std::multiset<int> seen;
  for (int i = 0; i < 4; ++i)
    for (const int f : shardFrames(range, {i, 4})) {
      EXPECT_EQ((f - range.first) % 4, i);
      seen.insert(f);
    }
  EXPECT_EQ(seen.size(), 18u);
  for (int f = 3; f <= 20; ++f) EXPECT_EQ(seen.count(f), 1u) << f;
  EXPECT_TRUE(shardFrames({0, 1}, {5, 8}).empty());  // more shards than frames: the rest do nothing
  EXPECT_EQ(parseShard("2/5").index, 2);
  EXPECT_EQ(parseShard("2/5").count, 5);
  for (const char* bad : {"5/5", "1", "-1/3", "1/0", "a/b", "1/2/3"}) EXPECT_THROW(parseShard(bad), InputError) << bad;
}

TEST(FrameSequence, APathNamesTheFrameWhoseFileItIs) {
  EXPECT_EQ(frameNamedBy("out/frame_%04d.png", "out/frame_0012.png"), 12);
  EXPECT_EQ(frameNamedBy("out/frame_%04d.png", "./out/../out/frame_0012.png"), 12);  // the same file
  EXPECT_EQ(frameNamedBy("out/frame_%04d.png", std::filesystem::absolute("out/frame_0000.png")), 0);
  EXPECT_EQ(frameNamedBy("out/%d/image.exr", "out/7/image.exr"), 7);
  EXPECT_EQ(frameNamedBy("out/f%5d.png", "out/f   42.png"), 42);
  EXPECT_EQ(frameNamedBy("out/100%%_%d.png", "out/100%_3.png"), 3);
  // Another spelling of the number is another file; so are other names.
  EXPECT_FALSE(frameNamedBy("out/frame_%04d.png", "out/frame_12.png"));
  EXPECT_FALSE(frameNamedBy("out/frame_%d.png", "out/frame_0012.png"));
  EXPECT_FALSE(frameNamedBy("out/frame_%04d.png", "out/frame_00a2.png"));
  EXPECT_FALSE(frameNamedBy("out/frame_%04d.png", "out/frame_.png"));
  EXPECT_FALSE(frameNamedBy("out/frame_%04d.png", "other/frame_0012.png"));
  EXPECT_FALSE(frameNamedBy("out/frame_%04d.png", "out/frame_0012.png.bak"));
  // In the range, step included.
  EXPECT_TRUE(inRange(FrameRange{4, 20, 4}, 12));
  EXPECT_FALSE(inRange(FrameRange{4, 20, 4}, 14));
  EXPECT_FALSE(inRange(FrameRange{4, 20, 4}, 24));
  EXPECT_FALSE(inRange(FrameRange{4, 20, 4}, 0));
}

TEST(FrameSequence, SeedsDependOnSeedAndFrameOnly) {
  std::set<std::uint32_t> seeds;
  for (int f = 0; f < 10000; ++f) seeds.insert(frameSeed(1, f));
  EXPECT_EQ(seeds.size(), 10000u);
  EXPECT_EQ(frameSeed(7, 42), frameSeed(7, 42));
  EXPECT_NE(frameSeed(7, 42), frameSeed(8, 42));
  EXPECT_EQ(frameCameraPath("out/frame_0001.exr"), std::filesystem::path("out/frame_0001.camera.json"));
}

PhysicalCamera aLens() {
  PhysicalCamera c;
  c.eye = {0.3, 1.2, 4.0};
  c.target = {0.0, 0.5, -2.0};
  c.focalLengthMm = 50.0;
  c.sensorMm = {36.0, 24.0};
  c.fNumber = 2.8;
  c.focusDistance = 3.0;
  return c;
}

TEST(FrameCameraFile, IntrinsicsOfTheLecturesWindow) {
  // 50 mm on a 36 mm sensor focused at 3 m: z_i = 50·3000/2950 mm, so fx = z_i / 36 mm × 960 px.
  const PhysicalCamera c = aLens();
  const OpenCvIntrinsics k = intrinsicsOf(toViewSpec(c), {960, 640});
  const double imageDistanceMm = 50.0 * 3000.0 / (3000.0 - 50.0);
  EXPECT_NEAR(k.fx, imageDistanceMm / 36.0 * 960.0, 1e-9);
  EXPECT_NEAR(k.fy, imageDistanceMm / 24.0 * 640.0, 1e-9);
  EXPECT_NEAR(k.cx, 479.5, 1e-9);
  EXPECT_NEAR(k.cy, 319.5, 1e-9);
}

// OpenCV's projection x = K (R X + t), written out here, against lenslab's own projection of the
// same point, for a physical camera and for a lecture camera whose PRP is off the window's centre.
TEST(FrameCameraFile, PoseAndIntrinsicsProjectAsLenslabDoes) {
  ViewSpec offAxis;
  offAxis.vrp = {1.0, 2.0, -3.0};
  offAxis.vpn = glm::normalize(glm::dvec3(0.2, 0.1, 1.0));
  offAxis.prp = {0.3, -0.2, 2.0};
  offAxis.window = {-1.0, -0.6, 0.8, 0.7};
  for (const ViewSpec& view : {toViewSpec(aLens()), offAxis}) {
    const ImageSize size{640, 480};
    const OpenCvIntrinsics k = intrinsicsOf(view, size);
    const OpenCvPose pose = poseOf(view);
    const ViewBasis b = viewBasis(view);
    const glm::dvec3 prp = prpWorld(view);
    for (const glm::dvec3 offset :
         {glm::dvec3(0.1, 0.2, -3.0), glm::dvec3(-0.5, 0.3, -1.0), glm::dvec3(0.7, -0.4, -6.0)}) {
      const glm::dvec3 world = prp + offset.x * b.u + offset.y * b.v + offset.z * b.n;
      const glm::dvec3 cam(glm::dot(pose.rows[0], world) + pose.translation.x,
                           glm::dot(pose.rows[1], world) + pose.translation.y,
                           glm::dot(pose.rows[2], world) + pose.translation.z);
      ASSERT_GT(cam.z, 0.0);
      const glm::dvec2 opencv(k.fx * cam.x / cam.z + k.cx, k.fy * cam.y / cam.z + k.cy);
      const glm::dvec2 lenslab =
          pixelFromWindow(view.window, projectToWindow(view, world), size.widthPx, size.heightPx);
      EXPECT_NEAR(opencv.x + 0.5, lenslab.x, 1e-9);
      EXPECT_NEAR(opencv.y + 0.5, lenslab.y, 1e-9);
    }
  }
}

TEST(FrameCameraFile, ReadsBackAsTheSameCamera) {
  PhysicalCamera c = aLens();
  Lens lens;
  lens.effects.distortion.k1 = -0.1;
  lens.effects.distortion.p2 = 0.001;
  const Camera expected = toCamera(c, "expected");
  const std::string text = toIntrinsicsCameraJson(c, lens, {960, 640}, false, false);
  const nlohmann::json j = nlohmann::json::parse(text);
  EXPECT_EQ(j["distortion"], nlohmann::json({-0.1, 0.0, 0.0, 0.001, 0.0}));  // OpenCV's distCoeffs
  EXPECT_FALSE(j.contains("near"));
  const CameraFile file = parseCameraJson(text, "frame");
  const Camera& got = file.camera;
  EXPECT_TRUE(got.nearFromScene);
  EXPECT_NEAR(got.lens.apertureRadius, expected.lens.apertureRadius, 1e-15);
  EXPECT_NEAR(got.focusDistance(), 3.0, 1e-12);
  EXPECT_EQ(got.lens.effects.distortion.k1, -0.1);
  ASSERT_TRUE(got.calibratedSize);
  EXPECT_EQ(got.calibratedSize->widthPx, 960);
  // The same rays: the window's corners seen from the PRP point the same way.
  const ViewSpec& a = expected.view;
  const ViewSpec& b = got.view;
  for (const glm::dvec2 corner : {glm::dvec2(a.window.umin, a.window.vmin), glm::dvec2(a.window.umax, a.window.vmax)}) {
    const glm::dvec2 slopeA = (corner - glm::dvec2(a.prp)) / a.prp.z;
    const glm::dvec2 cornerB = corner == glm::dvec2(a.window.umin, a.window.vmin)
                                   ? glm::dvec2(b.window.umin, b.window.vmin)
                                   : glm::dvec2(b.window.umax, b.window.vmax);
    const glm::dvec2 slopeB = (cornerB - glm::dvec2(b.prp)) / b.prp.z;
    EXPECT_NEAR(slopeA.x, slopeB.x, 1e-12);
    EXPECT_NEAR(slopeA.y, slopeB.y, 1e-12);
  }
  EXPECT_NEAR(glm::length(prpWorld(a) - prpWorld(b)), 0.0, 1e-12);
  // Near and far are written when the path gave them.
  c.nearDistance = 0.2;
  c.farDistance = std::numeric_limits<double>::infinity();
  const nlohmann::json given = nlohmann::json::parse(toIntrinsicsCameraJson(c, {}, {960, 640}, true, true));
  EXPECT_EQ(given["near"], 0.2);
  EXPECT_EQ(given["far"], "infinity");
}

TEST(FrameCameraFile, APathGivingNearOrFarKeepsIt) {
  const std::string key0 = R"({"time": 0, "eye": [0, 1, 3], "target": [0, 0.5, -2])";
  const std::string key1 = R"({"time": 1, "eye": [0, 1, 4], "target": [0, 0.5, -2])";
  const CameraPath open = parseCameraPath(R"({"fps": 24, "keys": [)" + key0 + "}, " + key1 + "}]}", "p");
  EXPECT_TRUE(open.nearFromScene);
  EXPECT_TRUE(open.farFromScene);
  const CameraPath given =
      parseCameraPath(R"({"fps": 24, "keys": [)" + key0 + R"(, "near": 0.1}, )" + key1 + "}]}", "p");
  EXPECT_FALSE(given.nearFromScene);
  EXPECT_TRUE(given.farFromScene);
}

class CaptureFiles : public test::TempDirTest {};

TEST_F(CaptureFiles, DepthIsTheExrsZChannelWithInfinityKept) {
  Image image(3, 2);
  for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = 0.1f * static_cast<float>(i);
  const std::vector<float> depth = {1.0f, 2.5f, std::numeric_limits<float>::infinity(), 1e6f, 0.001f, 7.0f};
  const auto file = dir_ / "f.exr";
  OutputSet outputs;
  writeImage(outputs, file, image, &depth);
  outputs.commit();
  EXPECT_EQ(readDepthChannel(file), depth);  // bit for bit, +inf included
  const Image back = readImage(file);
  EXPECT_EQ(back.rgba, image.rgba);  // RGBA unchanged by the fifth channel
  OutputSet png;
  EXPECT_THROW(writeImage(png, dir_ / "f.png", image, &depth), InputError);
  const auto plain = dir_ / "plain.exr";
  writeImage(plain, image);
  EXPECT_THROW(readDepthChannel(plain), InputError);
}

TEST_F(CaptureFiles, ProcessesAppendingAtOnceLeaveWholeLines) {
  // Threads stand in for shard processes: each call opens its own descriptor, as a process does.
  const auto manifest = dir_ / "manifest.jsonl";
  constexpr int kWriters = 8, kLines = 200;
  std::vector<std::thread> writers;
  for (int w = 0; w < kWriters; ++w)
    writers.emplace_back([&, w] {
      for (int i = 0; i < kLines; ++i)
        appendLine(manifest, nlohmann::json{{"writer", w}, {"line", i}, {"padding", std::string(300, 'x')}}.dump());
    });
  for (std::thread& t : writers) t.join();
  std::ifstream in(manifest);
  std::set<std::pair<int, int>> seen;
  std::string line;
  while (std::getline(in, line)) {
    const nlohmann::json j = nlohmann::json::parse(line);  // throws on a torn line
    seen.insert({j["writer"].get<int>(), j["line"].get<int>()});
  }
  EXPECT_EQ(seen.size(), static_cast<std::size_t>(kWriters * kLines));
  EXPECT_THROW(appendLine(dir_ / "missing" / "m.jsonl", "{}"), InputError);
}

}  // namespace
}  // namespace lenslab
