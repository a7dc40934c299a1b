// lens/LensFit: the real-time camera fitted to a prescription, held to what first-order optics
// and independent traces say it must be: the paraxial focal length and focus of a slow lens, a
// singlet's change of power with wavelength, and the relative illumination lens/LensAnalysis
// integrates on its own grid.
#include "core/TextFile.h"
#include "lens/LensAnalysis.h"
#include "lens/LensFit.h"
#include "lens/LensPrescription.h"
#include "lens/ParaxialLens.h"
#include "lens/RealLens.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

namespace lenslab {
namespace {

LensPrescription bundled(const std::string& name) {
  const std::string path = std::string(LENSLAB_UNIT_ASSET_DIR) + "/lenses/" + name;
  return parseLensPrescription(readTextFile(path, "lens file"), path);
}

// A BK7 biconvex singlet (R ±100 mm, 4 mm thick, 20 mm across), its stop 2 mm in front.
LensPrescription bk7Singlet(double abbe) {
  std::ostringstream text;
  text << "0 2 1 8\n100 4 1.5168 20";
  if (abbe > 0.0) text << " " << abbe;
  text << "\n-100 0 1 20\n";
  return parseLensPrescription(text.str(), "singlet");
}

TEST(LensFit, ASlowLensWithASmallFieldIsItsParaxialSelf) {
  const LensPrescription lens = bundled("double-gauss-50mm.lens");
  LensFitSettings s;
  s.sensorMm = {3.0, 2.0};
  s.fNumber = 16.0;
  const FittedLens fit = fitLens(lens, s);
  ASSERT_TRUE(fit.usable) << fit.why;
  EXPECT_NEAR(fit.focalLengthMm / firstOrder(lens).focalLengthMm, 1.0, 1e-3);
  EXPECT_NEAR(fit.entrancePupilDiameterMm, firstOrder(lens).focalLengthMm / 16.0, 1e-6);
  EXPECT_LT(fit.error.positionUm, 0.1);
  EXPECT_LT(fit.error.illumination, 0.01);
  EXPECT_FALSE(fit.barrelRadiusMm > 0.0) << "no rim clips a 2 mm field at f/16";
}

TEST(LensFit, FocusOnTheAxisIsTheParaxialConjugateForASmallStop) {
  const LensPrescription lens = bundled("double-gauss-50mm.lens");
  for (const double focusMm : {1000.0, 5000.0}) {
    LensFitSettings s;
    s.sensorMm = {3.0, 2.0};
    s.fNumber = 22.0;
    s.focusDistanceMm = focusMm;
    const FittedLens fit = fitLens(lens, s);
    ASSERT_TRUE(fit.usable) << fit.why;
    EXPECT_NEAR(1.0 / fit.inverseFocusPerMm / focusMm, 1.0, 0.02) << focusMm;
  }
  LensFitSettings s;
  s.sensorMm = {3.0, 2.0};
  s.fNumber = 22.0;
  const FittedLens atInfinity = fitLens(lens, s);
  // At infinity focus the best focus is infinity, or a blur far below a micrometre off it.
  EXPECT_LT(atInfinity.inverseFocusPerMm * atInfinity.entrancePupilDiameterMm * atInfinity.focalLengthMm * 1000.0, 0.5);
}

TEST(LensFit, AxialColourOfASingletIsItsChangeOfPower) {
  const LensPrescription lens = bk7Singlet(64.17);
  LensFitSettings s;
  s.sensorMm = {2.0, 2.0};
  const FittedLens fit = fitLens(lens, s);
  ASSERT_TRUE(fit.usable) << fit.why;
  // A thin lens's 1/z_f = 1/f − 1/z_i with the film fixed: each channel's 1/z_f moves by its 1/f's change.
  const auto power = [&](double wavelengthNm) {
    LensPrescription at = lens;
    for (LensSurface& surface : at.surfaces)
      surface.indexAfter = indexAtWavelength(surface.indexAfter, surface.abbeAfter, wavelengthNm),
      surface.abbeAfter = 0.0;
    return 1.0 / firstOrder(at).focalLengthMm;
  };
  const double green = power(550.0);
  EXPECT_NEAR(fit.inverseFocusShiftRedPerMm / (power(610.0) - green), 1.0, 0.05);
  EXPECT_NEAR(fit.inverseFocusShiftBluePerMm / (power(465.0) - green), 1.0, 0.05);
  EXPECT_LT(fit.inverseFocusShiftRedPerMm, 0.0) << "red focuses further away";
}

TEST(LensFit, LateralColourIsFittedNotLeftInTheImage) {
  // The stop 30 mm in front of a singlet: the chief rays cross the lens off its centre, and
  // each wavelength bends them by a different angle.
  const LensPrescription lens = parseLensPrescription("0 30 1 8\n100 6 1.5168 36 40\n-100 0 1 36\n", "front stop");
  LensFitSettings s;
  s.sensorMm = {24.0, 16.0};
  const FittedLens fit = fitLens(lens, s);
  ASSERT_TRUE(fit.usable) << fit.why;
  const double cornerUm = 1000.0 * fit.samples.back().imageHeightMm;
  const double displacedUm = std::max(std::abs(fit.lateralRed), std::abs(fit.lateralBlue)) * cornerUm;
  EXPECT_GT(displacedUm, 5.0) << "the channels' images differ in size";
  EXPECT_LT(fit.error.lateralColourUm, 0.2 * displacedUm);
  EXPECT_LT(fit.lateralRed * fit.lateralBlue, 0.0) << "red and blue on either side of green";
}

TEST(LensFit, IlluminationMatchesTheAnalysisOwnIntegral) {
  const LensPrescription lens = bundled("double-gauss-50mm.lens");
  LensFitSettings s;
  s.fieldSamples = 11;
  const FittedLens fit = fitLens(lens, s);
  ASSERT_TRUE(fit.usable) << fit.why;
  EXPECT_GT(fit.barrelRadiusMm, 0.0) << "the double Gauss's rims clip its corners";
  EXPECT_LT(fit.error.illumination, 0.05);
  LensAnalysisOptions o;
  const LensReport report = analyseLens(lens, o);
  ASSERT_EQ(report.field.size(), fit.samples.size());
  for (std::size_t i = 0; i < fit.samples.size(); ++i)
    EXPECT_NEAR(fit.samples[i].relativeIllumination, report.field[i].relativeIllumination, 0.03)
        << "field " << report.field[i].fieldFraction;
}

TEST(LensFit, BundledRectilinearLensesFitWithinMicrometres) {
  for (const char* name : {"double-gauss-50mm.lens", "telephoto-250mm.lens", "wide-angle-28mm.lens"}) {
    const FittedLens fit = fitLens(bundled(name), LensFitSettings{});
    ASSERT_TRUE(fit.usable) << name << ": " << fit.why;
    EXPECT_LT(fit.error.positionUm, 3.0) << name;
    EXPECT_LT(fit.error.illumination, 0.05) << name;
    EXPECT_TRUE(std::isfinite(fit.error.worstUm())) << name;
  }
  // A fisheye's image is not a rectilinear one distorted a little: the fit says how far off it is.
  LensFitSettings s;
  s.sensorMm = {18.0, 18.0};
  EXPECT_GT(fitLens(bundled("fisheye-10mm.lens"), s).error.positionUm, 50.0);
}

TEST(LensFit, ASensorPastTheImageCircleHasNoFit) {
  LensFitSettings s;
  s.sensorMm = {36.0, 24.0};
  const FittedLens fit = fitLens(bundled("fisheye-10mm.lens"), s);
  EXPECT_FALSE(fit.usable);
  EXPECT_NE(fit.why.find("the image circle ends inside the sensor"), std::string::npos) << fit.why;
}

}  // namespace
}  // namespace lenslab
