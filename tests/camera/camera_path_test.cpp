// Camera paths (camera/CameraPath.h, io/CameraPathJson.h): keys hit exactly, a rack focus moves
// one way in 1/z, f-numbers in stops, up stays orthonormal, frame counts, and bad paths refused in
// one line naming the key.
#include "../common/refusal.h"
#include "camera/CameraPath.h"
#include "core/Error.h"
#include "io/CameraPathJson.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace lenslab {
namespace {

PhysicalCamera lens(glm::dvec3 eye, glm::dvec3 target, double focus, double fNumber, double focalMm = 35.0) {
  PhysicalCamera c;
  c.eye = eye;
  c.target = target;
  c.focusDistance = focus;
  c.fNumber = fNumber;
  c.focalLengthMm = focalMm;
  return c;
}

CameraPath threeKeys(PathInterpolation mode) {
  CameraPath p;
  p.fps = 24.0;
  p.interpolation = mode;
  p.keys = {{0.0, lens({0, 1, 5}, {0, 0.5, 0}, 1.0, 1.4, 35.0), {}},
            {1.0, lens({2, 1.5, 4}, {0.2, 0.5, -1}, 4.0, 2.8, 50.0), {}},
            {2.5, lens({3, 1, 1}, {0, 0.5, -3}, 20.0, 8.0, 85.0), {}}};
  p.keys[1].camera.up = glm::normalize(glm::dvec3(0.2, 1.0, 0.0));
  validate(p, "test");
  return p;
}

TEST(CameraPath, FrameCountIsBoundedWhereverItComesFrom) {
  EXPECT_EQ(frameCountFor(3.0, 24.0, "path"), 73);
  EXPECT_EQ(frameCountFor(0.0, 24.0, "path"), 1);
  // A glTF animation's last key at 1e9 s at 24 fps would wrap an int frame number.
  try {
    frameCountFor(1e9, 24.0, "scene.glb over the animation at --fps 24");
    FAIL() << "2.4e10 frames accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("scene.glb over the animation at --fps 24: 2.4e+10 frames"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("at most 10^7"), std::string::npos) << e.what();
  }
}

TEST(CameraPath, KeysAreHitExactly) {
  for (PathInterpolation mode : {PathInterpolation::Smooth, PathInterpolation::Linear}) {
    const CameraPath p = threeKeys(mode);
    for (const PathKey& k : p.keys) {
      const PhysicalCamera c = cameraAt(p, k.timeSeconds).camera;
      EXPECT_NEAR(glm::length(c.eye - k.camera.eye), 0.0, 1e-12);
      EXPECT_NEAR(glm::length(c.target - k.camera.target), 0.0, 1e-12);
      EXPECT_NEAR(c.focusDistance, k.camera.focusDistance, 1e-9 * k.camera.focusDistance);
      EXPECT_NEAR(c.fNumber, k.camera.fNumber, 1e-12);
      EXPECT_NEAR(c.focalLengthMm, k.camera.focalLengthMm, 1e-12);
    }
  }
}

TEST(CameraPath, ARackFocusMovesOneWayInInverseDistance) {
  for (PathInterpolation mode : {PathInterpolation::Smooth, PathInterpolation::Linear}) {
    const CameraPath p = threeKeys(mode);  // focus 1 → 4 → 20: 1/z falls all the way
    double previous = 2.0;
    for (int i = 0; i <= 250; ++i) {
      const double inverse = 1.0 / cameraAt(p, i * 0.01).camera.focusDistance;
      EXPECT_LE(inverse, previous + 1e-12) << "t = " << i * 0.01;
      previous = inverse;
    }
  }
  // Linear: even in 1/z, so halfway from 1 m to 4 m is 1/z = 0.625 (1.6 m), not 2.5 m.
  EXPECT_NEAR(cameraAt(threeKeys(PathInterpolation::Linear), 0.5).camera.focusDistance, 1.6, 1e-12);
}

TEST(CameraPath, FNumbersMoveInStops) {
  // f/1.4 → f/2.8 is one stop: halfway is half a stop, 1.4·√2.
  EXPECT_NEAR(cameraAt(threeKeys(PathInterpolation::Linear), 0.5).camera.fNumber, 1.4 * std::sqrt(2.0), 1e-12);
  // Smooth: between the keys' f-numbers, never beyond them.
  for (int i = 0; i <= 100; ++i) {
    const double f = cameraAt(threeKeys(PathInterpolation::Smooth), i * 0.025).camera.fNumber;
    EXPECT_GE(f, 1.4 - 1e-12);
    EXPECT_LE(f, 8.0 + 1e-12);
  }
}

TEST(CameraPath, UpStaysOrthonormalToTheViewDirection) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  CameraPath p;
  p.fps = 30.0;
  for (int k = 0; k < 6; ++k) {
    PathKey key{k * 0.5, lens({u(rng) * 3, 1 + u(rng), 5 + u(rng)}, {u(rng), 0.5, u(rng)}, 3.0, 2.0), {}};
    key.camera.up = glm::normalize(glm::dvec3(0.3 * u(rng), 1.0, 0.3 * u(rng)));
    p.keys.push_back(key);
  }
  validate(p, "test");
  for (int i = 0; i <= 250; ++i) {
    const PhysicalCamera c = cameraAt(p, i * 0.01).camera;
    EXPECT_NEAR(glm::length(c.up), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(c.up, glm::normalize(c.target - c.eye)), 0.0, 1e-12);
  }
}

// Keys that are each valid can interpolate to a camera that is not; the whole path is refused when
// read, naming the frame, before capture draws any.
std::string refusal(const CameraPath& path) {
  return test::refusalOf([&] { validate(path, "path.json"); });
}

TEST(CameraPath, AnEyeThroughItsTargetIsRefusedBeforeTheFirstFrame) {
  CameraPath p;
  p.fps = 4.0;
  p.interpolation = PathInterpolation::Linear;
  p.keys = {{0.0, lens({0, 0, 5}, {0, 0, 0}, 3.0, 2.8), {}}, {1.0, lens({0, 0, -5}, {0, 0, 0}, 3.0, 2.8), {}}};
  const std::string message = refusal(p);
  EXPECT_NE(message.find("path.json: frame 2 (t = 0.5 s): eye meets target"), std::string::npos) << message;
}

TEST(CameraPath, UpsThatCancelAreRefusedNamingTheFrame) {
  CameraPath p;
  p.fps = 4.0;
  p.interpolation = PathInterpolation::Linear;
  p.keys = {{0.0, lens({0, 0, 5}, {0, 0, 0}, 3.0, 2.8), {}}, {1.0, lens({0, 0, 5}, {0, 0, 0}, 3.0, 2.8), {}}};
  p.keys[1].camera.up = {0, -1, 0};
  const std::string message = refusal(p);
  EXPECT_NE(message.find("path.json: frame 2 (t = 0.5 s): up is parallel to the view direction"), std::string::npos)
      << message;
}

TEST(CameraPath, CentripetalCatmullRomPassesItsPointsAndKeepsALineStraight) {
  const glm::dvec3 p0(0, 0, 0), p1(1, 0, 0), p2(2, 0, 0), p3(3, 0, 0);
  for (double u : {0.0, 0.25, 0.5, 1.0})
    EXPECT_NEAR(glm::length(centripetalCatmullRom(p0, p1, p2, p3, u) - glm::dvec3(1 + u, 0, 0)), 0.0, 1e-12);
  const glm::dvec3 q0(0, 0, 0), q1(1, 0, 0), q2(1, 1, 0), q3(0, 5, 0);
  EXPECT_NEAR(glm::length(centripetalCatmullRom(q0, q1, q2, q3, 0.0) - q1), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(centripetalCatmullRom(q0, q1, q2, q3, 1.0) - q2), 0.0, 1e-12);
}

TEST(CameraPath, MonotoneCubicDoesNotOvershoot) {
  const std::vector<double> x{0, 1, 2, 3}, y{0, 0, 1, 1};
  for (int i = 0; i <= 300; ++i) {
    const double v = monotoneCubic(x, y, i * 0.01);
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 1.0);
  }
  EXPECT_EQ(monotoneCubic(x, y, 2.0), 1.0);
}

TEST(CameraPath, FrameCountFollowsTheLastKeyOrIsGiven) {
  CameraPath p = threeKeys(PathInterpolation::Smooth);  // last key at 2.5 s, 24 fps
  EXPECT_EQ(p.frameCount(), 61);
  EXPECT_DOUBLE_EQ(p.frameTimeSeconds(60), 2.5);
  p.frames = 10;
  EXPECT_EQ(p.frameCount(), 10);
}

const char* kKey0 = R"({"time": 0, "eye": [0, 1, 5], "target": [0, 0.5, 0], "f_number": 2, "focus_distance": 3})";
const char* kKey1 = R"({"time": 1, "eye": [1, 1, 5], "target": [0, 0.5, 0], "f_number": 4, "focus_distance": 6})";

std::string refusal(const std::string& text) {
  return test::refusalOf([&] { parseCameraPath(text, "path.json"); });
}

TEST(CameraPathJson, ReadsAPathWithEffects) {
  const CameraPath p =
      parseCameraPath(std::string(R"({"fps": 12, "interpolation": "linear", "keys": [)") + kKey0 + "," +
                          R"({"time": 2, "eye": [1, 1, 5], "target": [0, 0.5, 0], "f_number": 4, "focus_distance": 6,
                                               "distortion": {"k1": -0.1}}]})",
                      "path.json");
  ASSERT_EQ(p.keys.size(), 2u);
  EXPECT_EQ(p.frameCount(), 25);
  EXPECT_EQ(p.interpolation, PathInterpolation::Linear);
  EXPECT_NEAR(cameraAt(p, 1.0).lens.effects.distortion.k1, -0.05, 1e-12);
}

TEST(CameraPathJson, BadPathsAreRefusedNamingTheKey) {
  const std::string two = std::string(kKey0) + "," + kKey1;
  EXPECT_NE(refusal(R"({"fps": 24, "keys": []})").find("keys: give at least one key"), std::string::npos);
  EXPECT_NE(refusal(R"({"keys": [)" + two + "]}").find("fps: required"), std::string::npos);
  EXPECT_NE(refusal(R"({"fps": -1, "keys": [)" + two + "]}").find("fps -1"), std::string::npos);
  EXPECT_NE(refusal(R"({"fps": 24, "keys": [)" + std::string(kKey1) + "," + kKey0 + "]}")
                .find("keys[1].time 0 must be later than keys[0].time 1"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"fps": 24, "keys": [)" + std::string(kKey0) + "," + kKey0 + "]}").find("keys[1].time"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"fps": 24, "speed": 2, "keys": [)" + two + "]}").find("unknown key \"speed\""),
            std::string::npos);
  EXPECT_NE(refusal(R"({"fps": 24, "keys": [{"time": 0, "eye": [0, 1, 5], "target": [0, 0, 0], "fov": 40}]})")
                .find("keys[0]: unknown key \"fov\""),
            std::string::npos);
  // A lecture-form key mixed with a physical one (keys of one kind only: camera/ViewPath.h).
  EXPECT_NE(
      refusal(
          R"({"fps": 24, "keys": [{"time": 0, "vrp": [0, 0, 0], "vpn": [0, 0, 1], "prp": [0, 0, 2], "window": [-1, -1, 1, 1]}, )"
          R"({"time": 1, "eye": [0, 1, 5], "target": [0, 0, 0]}]})")
          .find("keys[1]: is in the physical form where keys[0] is not"),
      std::string::npos);
  EXPECT_NE(refusal(R"({"fps": 24, "keys": [{"eye": [0, 1, 5], "target": [0, 0, 0]}]})").find("keys[0].time: required"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"fps": 24, "interpolation": "cubic", "keys": [)" + two + "]}").find("interpolation \"cubic\""),
            std::string::npos);
  EXPECT_NE(refusal(R"({"fps": 24, "keys": [{"time": 0, "eye": [0, 1, 5], "target": [0, 0, 0]}, )" +
                    std::string(kKey1) + "]}")
                .find("keys[1].f_number"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"fps": 24, "frames": 0, "keys": [)" + two + "]}").find("frames 0"), std::string::npos);
  EXPECT_NE(refusal("[1, 2]").find("must hold a JSON object"), std::string::npos);
}

TEST(CameraPathAssets, TheRackFocusPullsFromTheNearBoxToTheFarOneAtF14) {
  const CameraPath p = loadCameraPath(std::string(LENSLAB_UNIT_ASSET_DIR) + "/rows/rack-focus.json");
  EXPECT_EQ(p.frameCount(), 73);
  EXPECT_DOUBLE_EQ(cameraAt(p, 0.0).camera.focusDistance, 2.0);
  EXPECT_NEAR(cameraAt(p, 3.0).camera.focusDistance, 16.0, 1e-9);
  double previous = 0.0;
  for (int frame = 0; frame < p.frameCount(); ++frame) {
    const PhysicalCamera c = cameraAt(p, p.frameTimeSeconds(frame)).camera;
    EXPECT_GE(c.focusDistance, previous - 1e-12) << "frame " << frame;
    EXPECT_DOUBLE_EQ(c.fNumber, 1.4);
    previous = c.focusDistance;
  }
}

TEST(CameraPathAssets, TheDollyZoomKeepsFocalLengthOverDistance) {
  const CameraPath p = loadCameraPath(std::string(LENSLAB_UNIT_ASSET_DIR) + "/rows/dolly-zoom.json");
  EXPECT_EQ(p.frameCount(), 97);
  for (int frame = 0; frame < p.frameCount(); ++frame) {
    const PhysicalCamera c = cameraAt(p, p.frameTimeSeconds(frame)).camera;
    const double distance = glm::length(c.target - c.eye);
    // The subject's size on the sensor goes as f / d: constant, so the 4 m box keeps its size.
    EXPECT_NEAR(c.focalLengthMm / distance, 8.75, 1e-9) << "frame " << frame;
    // Focus, even in 1/z between keys a metre apart, stays within 1.5 % of the subject.
    EXPECT_NEAR(c.focusDistance / distance, 1.0, 0.015) << "frame " << frame;
  }
  EXPECT_NEAR(cameraAt(p, 0.0).camera.focalLengthMm, 35.0, 1e-12);
  EXPECT_NEAR(cameraAt(p, 4.0).camera.focalLengthMm, 70.0, 1e-12);
}

// A path file's JSON is read as a camera file's is: the parser's own text ("[json.exception...]")
// cut to what it says, and a key given twice refused.
TEST(CameraPath, BadJsonIsOneLineInTheInputsWords) {
  const auto message = [](const std::string& text) {
    return test::refusalOf([&] { parseCameraPath(text, "path.json"); });
  };
  const std::string overflow = message(R"({"fps": 1e309, "keys": []})");
  EXPECT_NE(overflow.find("path.json: not valid JSON: number overflow"), std::string::npos) << overflow;
  EXPECT_EQ(overflow.find("json.exception"), std::string::npos) << overflow;
  const std::string truncated = message(R"({"fps": )");
  EXPECT_EQ(truncated.find("json.exception"), std::string::npos) << truncated;
  EXPECT_NE(message(R"({"fps": 24, "fps": 25, "keys": []})").find("the key \"fps\" is given twice"), std::string::npos);
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

TEST(CameraPathJson, APathHoldsOneApertureShape) {
  const std::string shaped0 =
      R"({"time": 0, "eye": [0, 1, 5], "target": [0, 0.5, 0], "f_number": 2, "aperture": {"blades": 6}})";
  const std::string shaped1 =
      R"({"time": 1, "eye": [1, 1, 5], "target": [0, 0.5, 0], "f_number": 4, "aperture": {"blades": 6}})";
  const CameraPath p = parseCameraPath(R"({"fps": 4, "keys": [)" + shaped0 + "," + shaped1 + "]}", "path.json");
  EXPECT_EQ(cameraAt(p, 0.5).lens.aperture.blades, 6);
  EXPECT_EQ(cameraAt(p, 1.0).lens.aperture.blades, 6);
  const std::string message =
      test::refusalOf([&] { parseCameraPath(R"({"fps": 4, "keys": [)" + shaped0 + "," + kKey1 + "]}", "path.json"); });
  EXPECT_NE(message.find("keys[1]: \"aperture\" is circle where the first key's is 6 blades"), std::string::npos)
      << message;
}

}  // namespace
}  // namespace lenslab
