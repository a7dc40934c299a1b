#include "camera/Projection.h"
#include "core/Error.h"
#include "io/CameraJson.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lenslab {
namespace {

// Expects the text to be refused with a one-line message naming the file and containing `fragment`.
void expectRefused(const std::string& text, const std::string& fragment) {
  try {
    parseCameraJson(text, "cam.json");
    FAIL() << "accepted: " << text;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("cam.json: ", 0), 0u) << message;
    EXPECT_NE(message.find(fragment), std::string::npos) << "expected '" << fragment << "' in: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(CameraJson, ReadsTheLectureForm) {
  const CameraFile f = parseCameraJson(R"({"projection": "perspective", "vrp": [0, 0, -5],
      "vpn": [0, 0, 1], "vup": [0, 1, 0], "prp": [0.5, 0, 5], "window": [-2, -1, 2, 1],
      "near": 0.1, "far": "infinity"})",
                                       "cam.json");
  const ViewSpec& s = f.camera.view;
  EXPECT_EQ(s.projection, Projection::Perspective);
  EXPECT_EQ(s.vrp, glm::dvec3(0, 0, -5));
  EXPECT_EQ(s.prp, glm::dvec3(0.5, 0, 5));
  EXPECT_DOUBLE_EQ(s.window.umax, 2.0);
  EXPECT_DOUBLE_EQ(s.nearDistance, 0.1);
  EXPECT_TRUE(std::isinf(s.farDistance));
  EXPECT_FALSE(f.physical.has_value());
  EXPECT_EQ(f.camera.lens.apertureRadius, 0.0);
}

TEST(CameraJson, ReadsTheParallelLectureForm) {
  const CameraFile f = parseCameraJson(R"({"projection": "parallel", "vrp": [0, 0, 0],
      "vpn": [0, 0, 1], "prp": [0, 0, 5], "window": [-2, -1, 2, 1], "far": 20})",
                                       "cam.json");
  EXPECT_EQ(f.camera.view.projection, Projection::Parallel);
  EXPECT_DOUBLE_EQ(f.camera.view.farDistance, 20.0);
}

TEST(CameraJson, ReadsThePhysicalFormWithDefaults) {
  const CameraFile f = parseCameraJson(R"({"eye": [0, 1, 5], "target": [0, 1, 0], "f_number": 4,
      "focal_length_mm": 50})",
                                       "cam.json");
  ASSERT_TRUE(f.physical.has_value());
  EXPECT_DOUBLE_EQ(f.physical->focusDistance, 5.0);
  EXPECT_EQ(f.physical->sensorMm, glm::dvec2(36, 24));
  EXPECT_NEAR(f.camera.lens.apertureRadius, 0.05 / 8.0, 1e-15);
  const glm::dvec2 uv = projectToWindow(f.camera.view, {0, 1, -3});
  EXPECT_NEAR(uv.x, 0.0, 1e-12);
  EXPECT_NEAR(uv.y, 0.0, 1e-12);
}

TEST(CameraJson, RoundTripsTheLectureForm) {
  const CameraFile f = parseCameraJson(R"({"eye": [1, 2, 5], "target": [0, 1, 0]})", "cam.json");
  const CameraFile back = parseCameraJson(toCameraJson(f.camera), "saved.json");
  EXPECT_NEAR(glm::length(back.camera.view.vrp - f.camera.view.vrp), 0.0, 1e-12);
  EXPECT_NEAR(back.camera.view.window.umax, f.camera.view.window.umax, 1e-12);
  EXPECT_EQ(back.camera.view.farDistance, f.camera.view.farDistance);
}

TEST(CameraJson, RefusesBadInputWithTheKeyNamed) {
  expectRefused("{ not json", "not valid JSON");
  // A key given twice (nlohmann would keep the second silently), at the top and nested.
  expectRefused(R"({"eye": [0, 1, 3], "eye": [0, 2, 3], "target": [0, 0, 0]})", "the key \"eye\" is given twice");
  expectRefused(R"({"eye": [0, 1, 3], "target": [0, 0, 0], "distortion": {"k1": 0.1, "k1": 0.2}})",
                "the key \"k1\" is given twice");
  expectRefused("[1, 2]", "JSON object");
  expectRefused("{}", "no camera");
  expectRefused(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "focal_lenght_mm": 50})", "focal_lenght_mm");
  expectRefused(R"({"eye": [0, 0], "target": [0, 0, 0]})", "\"eye\"");
  expectRefused(R"({"eye": "here", "target": [0, 0, 0]})", "\"eye\"");
  expectRefused(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "f_number": "wide"})", "\"f_number\"");
  expectRefused(R"({"eye": [0, 0, 5]})", "\"target\" is missing");
  expectRefused(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "vrp": [0, 0, 0]})", "mixes");
  expectRefused(R"({"vrp": [0, 0, 0], "vpn": [0, 0, 0], "prp": [0, 0, 1], "window": [-1, -1, 1, 1]})", "vpn");
  expectRefused(R"({"vrp": [0, 0, 0], "vpn": [0, 0, 1], "prp": [0, 0, 1], "window": [1, -1, -1, 1]})", "window");
  expectRefused(
      R"({"projection": "fisheye", "vrp": [0, 0, 0], "vpn": [0, 0, 1], "prp": [0, 0, 1], "window": [-1, -1, 1, 1]})",
      "\"projection\"");
  expectRefused(
      R"({"vrp": [0, 0, 0], "vpn": [0, 0, 1], "prp": [0, 0, 1], "window": [-1, -1, 1, 1], "near": 5, "far": 2})",
      "near");
  expectRefused(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "focus_distance": 0.01})", "focus_distance");
  // One spelling of infinity: "inf" is refused, naming the key.
  expectRefused(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "f_number": 2, "focus_distance": "inf"})", "focus_distance");
}

// Found by fuzzing (tools/fuzz.sh, camera_json_fuzz): a number beyond double's range made
// nlohmann throw out_of_range, not parse_error, which escaped the reader as a non-InputError.
// A focal length in pixels too large to draw is refused as such, not later as a garbled fold-over
// (fx = 1e300 printed an overflowed integer, -9223372036854775808 %).
TEST(CameraJson, FocalLengthInPixelsBeyondItsRangeIsRefused) {
  expectRefused(R"({"intrinsics": {"fx": 1e300, "fy": 1e300, "cx": 480, "cy": 320, "width": 960, "height": 640},
                    "eye": [0, 1, 5], "target": [0, 1, 0], "dist": [0.1, 0, 0, 0]})",
                "\"intrinsics.fx\" (the focal length in pixels): 1e+300 is out of range; give a finite value from "
                "0.001 to 1e+09");
  expectRefused(R"({"intrinsics": {"fx": 500, "fy": 0, "cx": 480, "cy": 320, "width": 960, "height": 640},
                    "eye": [0, 1, 5], "target": [0, 1, 0]})",
                "\"intrinsics.fy\" (the focal length in pixels): 0 is out of range");
}

// What a user wrote is quoted in a message, at most 60 characters of it.
TEST(CameraJson, LongUserTextIsQuotedShort) {
  const std::string key(1 << 20, 'x');
  for (const std::string& text : {R"({"eye": [0, 1, 5], "target": [0, 1, 0], ")" + key + R"(": 1})",
                                  R"({"eye": [0, 1, 5], "target": [0, 1, 0], "near": ")" + key + R"("})"}) {
    try {
      parseCameraJson(text, "cam.json");
      FAIL() << "accepted";
    } catch (const InputError& e) {
      EXPECT_LT(std::string(e.what()).size(), 1000u);
      EXPECT_NE(std::string(e.what()).find("xxx…"), std::string::npos);
    }
  }
}

TEST(CameraJson, NumberBeyondDoubleIsRefusedAsInvalidJson) {
  expectRefused(R"({"eye": [0, 0, 2.5e308], "target": [0, 0, 0]})",
                "not valid JSON: number overflow parsing '2.5e308'");
  expectRefused("[1, -1e400]", "not valid JSON");
}

// Found by reading the reader while fuzzing (no sanitizer sees it): get<int>() wrapped a whole
// number beyond int, so a width of 2^32 + 1 pixels was read as 1 and accepted.
TEST(CameraJson, WholeNumberBeyondIntIsRefusedNotWrapped) {
  const std::string head =
      R"({"eye": [0, 0, 3], "target": [0, 0, 0], "intrinsics": {"fx": 500, "fy": 500, "cx": 0, "cy": 0, )";
  expectRefused(head + R"("width": 4294967297, "height": 480}})", "\"intrinsics.width\" is 4294967297");
  expectRefused(head + R"("width": 640, "height": 18446744073709551615}})",
                "\"intrinsics.height\" is 18446744073709551615");
  expectRefused(head + R"("width": 640, "height": -4294967295}})", "\"intrinsics.height\"");
}

// Found by reasoning while fuzzing (a million-deep value is larger than libFuzzer's inputs): the
// messages quoted the value with nlohmann's recursive dump(), and the stack overflowed.
TEST(CameraJson, DeeplyNestedValueIsRefusedNotACrash) {
  const std::size_t depth = 1000000;
  expectRefused(R"({"vrp": )" + std::string(depth, '[') + std::string(depth, ']') + "}", "nests deeper than 64 levels");
  expectRefused(R"({"distortion": {"k1": )" + std::string(depth, '[') + std::string(depth, ']') + "}}", "nests deeper");
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

TEST(CameraJson, ReadsAndWritesTheAperturesShape) {
  const CameraFile f = parseCameraJson(R"({"eye": [0, 1, 5], "target": [0, 1, 0], "f_number": 2,
      "aperture": {"blades": 7, "rotation_deg": 12.5, "roundness": 0.25, "anamorphic_squeeze": 1.33}})",
                                       "cam.json");
  EXPECT_EQ(f.camera.lens.aperture, (ApertureShape{7, 12.5, 0.25, 1.33}));
  const CameraFile back = parseCameraJson(toCameraJson(f.camera), "saved.json");
  EXPECT_EQ(back.camera.lens.aperture, f.camera.lens.aperture);
  // Absent: round; in every form (here the lecture's).
  EXPECT_TRUE(parseCameraJson(R"({"eye": [0, 1, 5], "target": [0, 1, 0]})", "cam.json").camera.lens.aperture.isRound());
  const CameraFile lecture = parseCameraJson(
      R"({"vrp": [0, 0, 0], "vpn": [0, 0, 1], "prp": [0, 0, 2], "window": [-1, -1, 1, 1], "aperture_radius": 0.1,
          "aperture": {"blades": 5}})",
      "cam.json");
  EXPECT_EQ(lecture.camera.lens.aperture.blades, 5);
}

TEST(CameraJson, RefusesABadApertureShapeNamingTheField) {
  const std::string head = R"({"eye": [0, 1, 5], "target": [0, 1, 0], "f_number": 2, "aperture": )";
  expectRefused(head + R"({"blades": 2}})", "\"aperture.blades\" is 2; give 0 (a circle) or 3 to 64 blades");
  expectRefused(head + R"({"blades": 6.5}})", "\"aperture.blades\" must be a whole number");
  expectRefused(head + R"({"roundness": 1.5}})", "\"aperture.roundness\" is 1.5");
  expectRefused(head + R"({"anamorphic_squeeze": 0}})", "\"aperture.anamorphic_squeeze\" is 0");
  expectRefused(head + R"({"rotation": 10}})", "unknown key \"aperture.rotation\"");
  expectRefused(head + R"(6})", "\"aperture\" must be an object");
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

TEST(CameraJson, ReadsAndWritesTheLensBarrel) {
  const CameraFile f = parseCameraJson(R"({"eye": [0, 1, 5], "target": [0, 1, 0], "f_number": 2,
      "barrel": {"distance_mm": 40, "diameter_mm": 30}})",
                                       "cam.json");
  EXPECT_DOUBLE_EQ(f.camera.lens.barrel.distance, 0.04);
  EXPECT_DOUBLE_EQ(f.camera.lens.barrel.radius, 0.015);
  const CameraFile back = parseCameraJson(toCameraJson(f.camera), "saved.json");
  EXPECT_NEAR(back.camera.lens.barrel.distance, 0.04, 1e-15);
  EXPECT_NEAR(back.camera.lens.barrel.radius, 0.015, 1e-15);
  const std::string head = R"({"eye": [0, 1, 5], "target": [0, 1, 0], "f_number": 2, )";
  expectRefused(head + R"("barrel": {"distance_mm": 40}})", "\"barrel.diameter_mm\" is missing");
  expectRefused(head + R"("barrel": {"distance_mm": -4, "diameter_mm": 30}})", "\"barrel.distance_mm\" is -4");
}

TEST(CameraJson, TakesTheLensBarrelWithDistortionAndLateralColourButNotWithAParallelProjection) {
  const CameraFile f = parseCameraJson(R"({"eye": [0, 1, 5], "target": [0, 1, 0], "f_number": 2,
      "barrel": {"distance_mm": 40, "diameter_mm": 30}, "distortion": {"k1": -0.2, "k2": 0.03},
      "chromatic": {"lateral_red": 0.004, "lateral_blue": -0.004}})",
                                       "cam.json");
  EXPECT_DOUBLE_EQ(f.camera.lens.barrel.radius, 0.015);
  EXPECT_DOUBLE_EQ(f.camera.lens.effects.distortion.k1, -0.2);
  EXPECT_TRUE(f.camera.lens.effects.needsRemap());
  const CameraFile back = parseCameraJson(toCameraJson(f.camera), "saved.json");
  EXPECT_NEAR(back.camera.lens.barrel.distance, 0.04, 1e-15);
  EXPECT_NEAR(back.camera.lens.effects.chromatic.lateralRed, 0.004, 1e-15);
  expectRefused(R"({"projection": "parallel", "vrp": [0, 0, 0], "vpn": [0, 0, 1], "prp": [0, 0, 5],
      "window": [-2, -1, 2, 1], "far": 20, "barrel": {"distance_mm": 40, "diameter_mm": 30}})",
                "\"barrel\" needs a perspective projection");
}

}  // namespace
}  // namespace lenslab
