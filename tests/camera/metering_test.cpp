// The reflected-light meter of --exposure auto (camera/Metering.h) on synthetic frames with
// closed-form readings, and the exposure it gives (camera/Exposure.h).
#include "camera/Exposure.h"
#include "camera/Metering.h"
#include "core/Error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>

namespace lenslab {
namespace {

// A width × height frame whose pixel (x, y) is grey `value(x, y)`.
Image greyFrame(int width, int height, const std::function<float(int, int)>& value) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float v = value(x, y);
      image.set(x, y, {v, v, v, 1.0f});
    }
  return image;
}

// EV100 = log2(L · 100 / 12.5) of the luminance the frame's float holds.
double closedForm(float luminanceValue) { return std::log2(static_cast<double>(luminanceValue) * 100.0 / 12.5); }

TEST(Metering, LuminanceIsRec709) {
  EXPECT_DOUBLE_EQ(luminance(1.0, 0.0, 0.0), 0.2126);
  EXPECT_DOUBLE_EQ(luminance(0.0, 1.0, 0.0), 0.7152);
  EXPECT_DOUBLE_EQ(luminance(0.0, 0.0, 1.0), 0.0722);
  EXPECT_NEAR(luminance(1.0, 1.0, 1.0), 1.0, 1e-15);
}

TEST(Metering, UniformFrameMetersToTheReflectedMeterCalibration) {
  for (const float l : {1e-6f, 0.18f, 1.0f, 3.0f, 45.0f, 1e5f}) {
    const MeterReading r = meterFrame(greyFrame(61, 40, [l](int, int) { return l; }));
    ASSERT_TRUE(r.ev100) << l;
    EXPECT_NEAR(*r.ev100, closedForm(l), 1e-9) << l;
    EXPECT_NEAR(r.luminance, l, 1e-9 * l);
    EXPECT_EQ(r.pixels, 61 * 40);
  }
  // 1 cd/m² at K = 12.5 and ISO 100: EV100 log2(8) = 3.
  EXPECT_NEAR(*meterFrame(greyFrame(8, 8, [](int, int) { return 1.0f; })).ev100, 3.0, 1e-12);
}

TEST(Metering, TwiceTheLightIsOneStop) {
  const auto texture = [](int x, int y) { return 0.02f + 0.3f * static_cast<float>((x * 7 + y * 13) % 17); };
  const MeterReading once = meterFrame(greyFrame(48, 32, texture));
  const MeterReading twice = meterFrame(greyFrame(48, 32, [&](int x, int y) { return 2.0f * texture(x, y); }));
  EXPECT_NEAR(*twice.ev100 - *once.ev100, 1.0, 1e-9);
}

TEST(Metering, CentreCircleIsHalfTheShorterSideAcross) {
  // 40 × 20: the circle's radius is 5 pixels about (20, 10).
  EXPECT_TRUE(inCentreCircle(19, 9, 40, 20));
  EXPECT_TRUE(inCentreCircle(20, 10, 40, 20));
  EXPECT_TRUE(inCentreCircle(24, 10, 40, 20));   // centre (24.5, 10.5): 4.53 px out
  EXPECT_FALSE(inCentreCircle(25, 10, 40, 20));  // 5.52 px out
  EXPECT_FALSE(inCentreCircle(0, 0, 40, 20));
  EXPECT_FALSE(inCentreCircle(20, 0, 40, 20));  // the short side's edge: 9.5 px out
  EXPECT_TRUE(inCentreCircle(0, 0, 1, 1));      // a one-pixel frame is all centre
}

TEST(Metering, CentreHoldsThreeQuartersOfTheWeight) {
  // The circle at `inside`, the rest at `outside`: log2 L = 0.75 log2(inside) + 0.25 log2(outside).
  const int w = 96, h = 64;
  for (const auto& [inside, outside] : {std::pair{4.0f, 0.25f}, std::pair{0.25f, 4.0f}, std::pair{1.0f, 1e-3f}}) {
    const MeterReading r = meterFrame(greyFrame(
        w, h, [&, in = inside, out = outside](int x, int y) { return inCentreCircle(x, y, w, h) ? in : out; }));
    const double expected = 0.75 * std::log2(double{inside}) + 0.25 * std::log2(double{outside}) + std::log2(8.0);
    EXPECT_NEAR(*r.ev100, expected, 1e-9) << inside << " inside, " << outside << " outside";
  }
}

TEST(Metering, PixelsWithoutLightAreLeftOut) {
  // A lit subject on a black background, where nothing is seen: the subject's reading.
  const MeterReading r = meterFrame(greyFrame(64, 48, [](int x, int) { return x < 32 ? 0.5f : 0.0f; }));
  EXPECT_NEAR(*r.ev100, closedForm(0.5f), 1e-9);
  EXPECT_EQ(r.pixels, 32 * 48);
  // Far under the floor (2^-16 of the average), not finite: left out. Just above it: counted.
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const MeterReading odd = meterFrame(greyFrame(16, 16, [&](int x, int y) {
    return x == 0 && y == 0   ? 1e-30f
           : x == 1 && y == 0 ? nan
           : x == 2 && y == 0 ? inf
           : x == 3 && y == 0 ? -1.0f
                              : 2.0f;
  }));
  EXPECT_NEAR(*odd.ev100, closedForm(2.0f), 1e-9);
  EXPECT_EQ(odd.pixels, 16 * 16 - 4);
  const MeterReading dim = meterFrame(greyFrame(16, 16, [](int x, int y) { return x == 0 && y == 0 ? 1e-4f : 1.0f; }));
  EXPECT_EQ(dim.pixels, 16 * 16);
}

TEST(Metering, BlackFrameHasNoReadingAndExposesAtZeroStops) {
  for (const float v : {0.0f, -1.0f, std::numeric_limits<float>::quiet_NaN()}) {
    const MeterReading r = meterFrame(greyFrame(32, 16, [v](int, int) { return v; }));
    EXPECT_FALSE(r.ev100);
    EXPECT_EQ(r.luminance, 0.0);
    EXPECT_EQ(r.pixels, 0);
    Exposure automatic;
    automatic.source = "--exposure auto";
    const Exposure e = exposedByMeter(automatic, r);
    EXPECT_EQ(e.stops, 0.0);
    EXPECT_EQ(e.scale, 1.0);
    EXPECT_NE(describe(e).find("no light to meter"), std::string::npos) << describe(e);
  }
  EXPECT_FALSE(meterFrame(Image(0, 0)).ev100);
}

TEST(Metering, AutoExposesTheReadingsEv100) {
  Exposure automatic;
  automatic.source = "--exposure auto";
  const MeterReading r = meterFrame(greyFrame(20, 20, [](int, int) { return 0.5f; }));
  const Exposure e = exposedByMeter(automatic, r);
  EXPECT_NEAR(e.scale, exposureScaleForEv100(*r.ev100), 1e-15);
  EXPECT_NEAR(ev100ForScale(e.scale), *r.ev100, 1e-12);
  // The metered luminance lands at 12.5 / (1.2 · 100) = 0.104.
  EXPECT_NEAR(e.scale * 0.5, 12.5 / 120.0, 1e-12);
  // Another exposure only records the reading.
  Exposure stops;
  stops.source = "--exposure";
  stops.stops = 1.0, stops.scale = 2.0;
  const Exposure kept = exposedByMeter(stops, r);
  EXPECT_EQ(kept.scale, 2.0);
  ASSERT_TRUE(kept.meterReading);
  EXPECT_EQ(kept.meterReading->ev100, r.ev100);
}

TEST(Metering, AutoWithPhysicalSettingsIsRefusedAndWinsOverTheFile) {
  PhysicalCamera p;
  p.fNumber = 2.0;
  p.shutterSeconds = 1.0 / 30.0;
  p.iso = 800.0;
  const SelectedCamera camera{toCamera(p, "cam.json"), p};
  ExposureRequest request;
  request.meter = true;
  try {
    ExposureRequest withShutter = request;
    withShutter.shutterSeconds = 0.01;
    resolveExposure(withShutter, camera);
    ADD_FAILURE() << "auto with --shutter taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--exposure auto"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--shutter"), std::string::npos) << e.what();
  }
  const Exposure e = resolveExposure(request, camera);
  EXPECT_EQ(e.source, "--exposure auto");
  EXPECT_FALSE(e.ev100);
  ASSERT_TRUE(e.cameraEv100);
  EXPECT_NEAR(*e.cameraEv100, ev100(2.0, 1.0 / 30.0, 800.0), 1e-12);
}

}  // namespace
}  // namespace lenslab
