// Exposure (camera/Exposure.h), the view transforms (io/ToneMap.h) and what a PNG of a known value
// holds through them; camera files' shutter_s and iso.
#include "camera/Exposure.h"
#include "core/Error.h"
#include "io/CameraJson.h"
#include "io/ImageFile.h"
#include "io/ToneMap.h"

#include "../common/temp_dir_test.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdint>
#include <functional>
#include <random>
#include <string>

namespace lenslab {
namespace {

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// ---- EV100 and the exposure scale ----

TEST(Ev100, KnownSettings) {
  EXPECT_DOUBLE_EQ(ev100(1.0, 1.0, 100.0), 0.0);  // f/1, 1 s, ISO 100: EV 0 by definition
  // "Sunny 16": f/16 at 1/100 s, ISO 100 is EV100 log2(25600) = 14.64 (light meters: about 15 in sun).
  EXPECT_NEAR(ev100(16.0, 1.0 / 100.0, 100.0), 14.644, 1e-3);
  EXPECT_NEAR(ev100(2.8, 1.0 / 100.0, 100.0), 9.615, 1e-3);
  // One stop each: doubling the time or the ISO lowers EV100 by 1; one full f-stop (×√2) raises it by 1.
  EXPECT_NEAR(ev100(4.0, 1.0 / 50.0, 100.0), ev100(4.0, 1.0 / 100.0, 100.0) - 1.0, 1e-12);
  EXPECT_NEAR(ev100(4.0, 1.0 / 100.0, 200.0), ev100(4.0, 1.0 / 100.0, 100.0) - 1.0, 1e-12);
  EXPECT_NEAR(ev100(4.0 * std::sqrt(2.0), 1.0 / 100.0, 100.0), ev100(4.0, 1.0 / 100.0, 100.0) + 1.0, 1e-12);
}

TEST(Ev100, ScaleIsTheSaturationBasedOne) {
  // At EV100 0 the luminance that saturates is 1.2 cd/m² (78 / (0.65 · 100)).
  EXPECT_NEAR(exposureScaleForEv100(0.0), 1.0 / 1.2, 1e-12);
  // Each stop halves it.
  EXPECT_NEAR(exposureScaleForEv100(3.0) * 8.0, exposureScaleForEv100(0.0), 1e-12);
  EXPECT_DOUBLE_EQ(exposureScaleForStops(0.0), 1.0);
  EXPECT_DOUBLE_EQ(exposureScaleForStops(-2.0), 0.25);
}

// ---- which exposure applies ----

SelectedCamera physicalCamera(double fNumber, std::optional<double> shutter = {}, std::optional<double> iso = {}) {
  PhysicalCamera p;
  p.fNumber = fNumber;
  p.shutterSeconds = shutter;
  p.iso = iso;
  return {toCamera(p, "cam.json"), p};
}

TEST(ResolveExposure, NothingGivenIsZeroEv) {
  const Exposure e = resolveExposure({}, physicalCamera(2.8));
  EXPECT_EQ(e.scale, 1.0);
  EXPECT_EQ(e.source, "none");
}

TEST(ResolveExposure, PhysicalSettingsFromTheFileAndTheCommandLine) {
  const Exposure file = resolveExposure({}, physicalCamera(2.8, 0.01, 400.0));
  EXPECT_EQ(file.source, "physical");
  EXPECT_NEAR(*file.ev100, ev100(2.8, 0.01, 400.0), 1e-12);
  EXPECT_NEAR(file.scale, exposureScaleForEv100(*file.ev100), 1e-15);
  // --shutter over the file's shutter_s; the ISO stays the file's.
  const Exposure over = resolveExposure({.shutterSeconds = 0.02}, physicalCamera(2.8, 0.01, 400.0));
  EXPECT_NEAR(*over.ev100, *file.ev100 - 1.0, 1e-12);
  // No ISO anywhere: 100.
  EXPECT_EQ(*resolveExposure({.shutterSeconds = 0.01}, physicalCamera(2.8)).iso, 100.0);
}

TEST(ResolveExposure, StopsWinOverTheFileAndAreRefusedWithShutterOrIso) {
  const Exposure e = resolveExposure({.stops = 1.5}, physicalCamera(2.8, 0.01, 400.0));
  EXPECT_EQ(e.source, "--exposure");
  EXPECT_NEAR(e.scale, std::exp2(1.5), 1e-12);
  EXPECT_FALSE(e.ev100);
  EXPECT_NE(
      messageOf([] { resolveExposure({.stops = 1.0, .iso = 200.0}, physicalCamera(2.8)); }).find("one or the other"),
      std::string::npos);
}

TEST(ResolveExposure, RefusalsNameTheFieldInOneLine) {
  const auto expectOneLine = [](const std::string& m, const std::string& field) {
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_NE(m.find(field), std::string::npos) << m;
  };
  expectOneLine(messageOf([] { resolveExposure({.iso = 200.0}, physicalCamera(2.8)); }), "--iso");
  expectOneLine(messageOf([] { resolveExposure({.shutterSeconds = 0.01}, physicalCamera(INFINITY)); }), "pinhole");
  expectOneLine(messageOf([] { resolveExposure({.shutterSeconds = 0.0}, physicalCamera(2.8)); }), "--shutter");
  expectOneLine(messageOf([] { resolveExposure({.shutterSeconds = 0.01, .iso = -5.0}, physicalCamera(2.8)); }),
                "--iso");
  expectOneLine(messageOf([] { resolveExposure({.stops = 100.0}, physicalCamera(2.8)); }), "--exposure");
  // A camera without a physical description (the lecture form) has no f-number.
  SelectedCamera lecture = physicalCamera(2.8);
  lecture.physical.reset();
  expectOneLine(messageOf([&] { resolveExposure({.shutterSeconds = 0.01}, lecture); }), "not in the physical form");
}

// ---- camera files ----

const std::string kPhysical = R"({"eye": [0, 0, 5], "target": [0, 0, 0], "f_number": 2.8)";

TEST(CameraFileExposure, ReadsShutterAndIso) {
  const CameraFile f = parseCameraJson(kPhysical + R"(, "shutter_s": 0.004, "iso": 800})", "cam.json");
  ASSERT_TRUE(f.physical);
  EXPECT_EQ(*f.physical->shutterSeconds, 0.004);
  EXPECT_EQ(*f.physical->iso, 800.0);
  EXPECT_FALSE(parseCameraJson(kPhysical + "}", "cam.json").physical->shutterSeconds);
}

TEST(CameraFileExposure, OutOfRangeValuesAreOneLineErrorsNamingTheField) {
  for (const auto& [text, field] : {std::pair{R"(, "shutter_s": 0})", "shutter_s"},
                                    {R"(, "shutter_s": 7200})", "shutter_s"},
                                    {R"(, "iso": 0})", "iso"},
                                    {R"(, "iso": "fast"})", "iso"}}) {
    const std::string m = messageOf([&] { parseCameraJson(kPhysical + text, "cam.json"); });
    EXPECT_NE(m.find(std::string("\"") + field + "\""), std::string::npos) << m;
    EXPECT_NE(m.find("cam.json"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
  // The lecture form has no shutter: an unknown key there.
  EXPECT_THROW(
      parseCameraJson(R"({"vrp": [0,0,0], "vpn": [0,0,1], "prp": [0,0,2], "window": [-1,-1,1,1], "shutter_s": 0.01})",
                      "cam.json"),
      InputError);
}

// ---- Khronos PBR Neutral: its defining properties ----

// HSV hue in turns (0 to 1), for colours with some chroma.
double hueOf(glm::vec3 c) {
  const double mx = std::max({c.r, c.g, c.b}), mn = std::min({c.r, c.g, c.b}), d = mx - mn;
  double h = 0.0;
  if (mx == c.r)
    h = (c.g - c.b) / d;
  else if (mx == c.g)
    h = 2.0 + (c.b - c.r) / d;
  else
    h = 4.0 + (c.r - c.g) / d;
  return std::fmod(h / 6.0 + 1.0, 1.0);
}

TEST(PbrNeutral, BelowTheStartOfCompressionOnlyTheOffsetIsTaken) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 c(0.8f * u(rng), 0.8f * u(rng), 0.8f * u(rng));
    const float x = std::min({c.r, c.g, c.b});
    const float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
    if (std::max({c.r, c.g, c.b}) - offset >= 0.76f) continue;  // compressed: not this property
    const glm::vec3 out = pbrNeutral(c);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(out[k], c[k] - offset, 1e-6f);
  }
  // Colours with every channel from 0.08 to 0.8 come out 0.04 lower: identity but for the offset.
  const glm::vec3 mid = pbrNeutral({0.5f, 0.3f, 0.1f});
  EXPECT_NEAR(mid.r, 0.46f, 1e-6f);
  EXPECT_NEAR(mid.g, 0.26f, 1e-6f);
  EXPECT_NEAR(mid.b, 0.06f, 1e-6f);
  EXPECT_EQ(pbrNeutral(glm::vec3(0.0f)), glm::vec3(0.0f));  // black stays black
}

TEST(PbrNeutral, MapsInfinityAsTheLargestValuesNotToBlack) {
  // A radiance past a float's range (∞) is the brightest there is: white, as 1e30 and 3e38 are.
  const float inf = std::numeric_limits<float>::infinity();
  for (const glm::vec3 c : {glm::vec3(inf), glm::vec3(3e38f), glm::vec3(1e30f), glm::vec3(inf, 1e38f, 2.0f)}) {
    const glm::vec3 out = pbrNeutral(c);
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(std::isfinite(out[k])) << c.r << "," << c.g << "," << c.b;
      EXPECT_GT(out[k], 0.99f) << c.r << "," << c.g << "," << c.b << " channel " << k;
    }
  }
}

TEST(PbrNeutral, MapsEverythingIntoZeroToOneMonotonicallyAndKeepsHue) {
  // A grey ramp from 0 to 1e4: rising, below 1.
  float previous = -1.0f;
  for (int i = 0; i <= 4000; ++i) {
    const float v = std::pow(10.0f, -4.0f + 8.0f * static_cast<float>(i) / 4000.0f);
    const float out = pbrNeutral(glm::vec3(v)).g;
    EXPECT_GE(out, previous) << "at " << v;
    EXPECT_LT(out, 1.0f) << "at " << v;
    previous = out;
  }
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 c = glm::vec3(u(rng), u(rng), u(rng)) * std::pow(10.0f, 4.0f * u(rng) - 1.0f);
    const glm::vec3 out = pbrNeutral(c);
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(out[k], 0.0f);
      EXPECT_LE(out[k], 1.0f);
    }
    // Brighter along the same colour: each channel rises or stays.
    const glm::vec3 brighter = pbrNeutral(1.25f * c);
    for (int k = 0; k < 3; ++k) EXPECT_GE(brighter[k], out[k] - 1e-6f) << "channel " << k;
    // The same HSV hue, where both have chroma to measure it by (desaturation to the peak and the
    // common offset act on all channels alike).
    const float chromaIn = std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b});
    const float chromaOut = std::max({out.r, out.g, out.b}) - std::min({out.r, out.g, out.b});
    if (chromaIn > 1e-3f * std::max({c.r, c.g, c.b}) && chromaOut > 1e-3f) {
      const double dh = std::abs(hueOf(out) - hueOf(c));
      EXPECT_LT(std::min(dh, 1.0 - dh), 2e-3) << c.r << "," << c.g << "," << c.b;
    }
  }
}

TEST(ViewTransform, NamesRoundTripAndNoneClipsAsBefore) {
  EXPECT_EQ(viewTransformNamed("pbr-neutral"), ViewTransform::PbrNeutral);
  EXPECT_EQ(viewTransformNamed("none"), ViewTransform::None);
  EXPECT_FALSE(viewTransformNamed("agx"));
  EXPECT_EQ(viewTransformName(ViewTransform::PbrNeutral), "pbr-neutral");
  // The default encoding is the old PNG encoding: clip to [0, 1], then sRGB.
  for (const float v : {-1.0f, 0.0f, 0.002f, 0.18f, 0.5f, 1.0f, 7.0f})
    EXPECT_EQ(displayEncoded(glm::vec3(v), {}).r, srgbFromLinear(v)) << v;
}

// ---- a PNG of a known linear value through exposure and view transform ----

class ExposedPng : public test::TempDirTest {
 protected:
  // The stored code values of the single-pixel PNG of `linear` through `encoding`.
  glm::ivec3 storedCodes(glm::vec3 linear, const DisplayEncoding& encoding, const char* name) {
    Image image(1, 1);
    image.set(0, 0, glm::vec4(linear, 1.0f));
    applyDisplayForFile(dir_ / name, image, encoding);
    writeImage(dir_ / name, image);
    auto in = OIIO::ImageInput::open((dir_ / name).string());
    EXPECT_TRUE(in);
    std::uint8_t rgb[3] = {0, 0, 0};
    if (in) in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, rgb);
    return {rgb[0], rgb[1], rgb[2]};
  }
};

int code(double displayLinear) {
  const double x = std::clamp(displayLinear, 0.0, 1.0);
  return static_cast<int>(std::lround(255.0 * (x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055)));
}

TEST_F(ExposedPng, EqualsTheClosedForm) {
  // +1 EV, none: 0.3 → 0.6; 0.7 → 1.4, clipped.
  const glm::ivec3 plusOne = storedCodes({0.3f, 0.7f, 0.05f}, {2.0f, ViewTransform::None}, "plus-one.png");
  EXPECT_NEAR(plusOne.r, code(0.6), 1);
  EXPECT_EQ(plusOne.g, 255);
  EXPECT_NEAR(plusOne.b, code(0.1), 1);
  // pbr-neutral of grey 4 (after −1 EV from 8): offset 0.04, peak 3.96, compressed to
  // 1 − 0.24² / (3.96 + 0.24 − 0.76); grey stays grey.
  const double peak = 3.96, d = 0.24, newPeak = 1.0 - d * d / (peak + d - 0.76);
  const glm::ivec3 grey = storedCodes(glm::vec3(8.0f), {0.5f, ViewTransform::PbrNeutral}, "grey.png");
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(grey[c], code(newPeak), 1);
  // An EXR is never exposed: applyDisplayForFile leaves it.
  Image image(1, 1);
  image.set(0, 0, {4.0f, 2.0f, 0.5f, 1.0f});
  applyDisplayForFile(dir_ / "a.exr", image, {0.25f, ViewTransform::PbrNeutral});
  EXPECT_EQ(image.at(0, 0), glm::vec4(4.0f, 2.0f, 0.5f, 1.0f));
}

}  // namespace
}  // namespace lenslab
