// lens/LensAnalysis against closed forms: the field of view of a small sensor, cos⁴ relative
// illumination behind a thin lens with its stop in contact, the third-order growth of spherical
// aberration, a thin lens's axial colour f/V, and the bundled designs' focal lengths and fits.
#include "../common/refusal.h"
#include "core/TextFile.h"
#include "lens/LensAnalysis.h"
#include "lens/LensPrescription.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

namespace lenslab {
namespace {
using test::refusalOf;

constexpr double kDegrees = 180.0 / 3.14159265358979323846;

LensPrescription bundled(const std::string& name) {
  const std::string path = std::string(LENSLAB_UNIT_ASSET_DIR) + "/lenses/" + name;
  return parseLensPrescription(readTextFile(path, "lens file"), path);
}

// A thin plano-convex lens (R, 0.5 mm thick, 10 mm across) with its stop right behind it.
LensPrescription thinLens(double radiusMm, double index, double abbe, double stopMm) {
  std::ostringstream text;
  text << radiusMm << " 0.5 " << index << " 10";
  if (abbe > 0.0) text << " " << abbe;
  text << "\ninf 0.01 1 10\n0 0 0 " << stopMm << "\n";
  return parseLensPrescription(text.str(), "thin");
}

TEST(LensAnalysis, BundledDesignsHaveTheFocalLengthsTheirNamesSay) {
  for (const auto& [file, focal] : {std::pair{"double-gauss-50mm.lens", 50.0}, std::pair{"telephoto-250mm.lens", 250.0},
                                    std::pair{"wide-angle-28mm.lens", 28.0}, std::pair{"fisheye-10mm.lens", 10.0}}) {
    const LensPrescription lens = bundled(file);
    EXPECT_FALSE(lens.comments.empty()) << file << " cites its source";
    EXPECT_NEAR(firstOrder(lens).focalLengthMm / focal, 1.0, 0.015) << file;
  }
}

// Near the axis every lens is the lecture's pinhole: the field of view is 2·atan(h / f).
TEST(LensAnalysis, ASmallSensorSeesTheParaxialFieldOfView) {
  const LensPrescription lens = bundled("double-gauss-50mm.lens");
  LensAnalysisOptions o;
  o.sensorMm = {0.2, 0.1};
  o.fieldSamples = 3;
  o.pupilSamples = 8;
  const LensReport r = analyseLens(lens, o);
  const double f = r.firstOrder.focalLengthMm;
  EXPECT_NEAR(r.fieldOfViewDegrees.x, 2.0 * std::atan(0.1 / f) * kDegrees, 1e-5 * r.fieldOfViewDegrees.x);
  EXPECT_NEAR(r.fieldOfViewDegrees.z, 2.0 * std::atan(0.5 * std::hypot(0.2, 0.1) / f) * kDegrees,
              1e-5 * r.fieldOfViewDegrees.z);
}

// A thin lens with its stop in contact and nothing else to clip: irradiance falls as cos⁴ of the
// chief ray's angle at the film (the exit pupil is the stop, seen obliquely and from farther).
TEST(LensAnalysis, RelativeIlluminationBehindAThinLensIsCosineToTheFourth) {
  const LensPrescription lens = thinLens(50.0, 1.5, 0.0, 4.0);
  LensAnalysisOptions o;
  o.sensorMm = {36.0, 24.0};
  o.fieldSamples = 5;
  o.pupilSamples = 96;
  const LensReport r = analyseLens(lens, o);
  const double pupilToFilm = lens.lengthMm() + r.filmDistanceMm - r.firstOrder.exitPupilMm;
  for (const FieldSample& s : r.field) {
    const double c = std::cos(std::atan(s.imageHeightMm / pupilToFilm));
    EXPECT_NEAR(s.relativeIllumination, c * c * c * c, 0.01) << "at " << s.imageHeightMm << " mm";
  }
}

// Spherical aberration's transverse error grows as the cube of the aperture (third order), so
// halving the stop divides the on-axis RMS spot at paraxial focus by about 8.
TEST(LensAnalysis, OnAxisSpotShrinksAsTheCubeOfTheAperture) {
  const LensPrescription lens = thinLens(50.0, 1.5, 0.0, 8.0);
  LensAnalysisOptions o;
  o.sensorMm = {2.0, 2.0};
  o.fieldSamples = 2;
  o.pupilSamples = 96;
  o.fNumber = 25.0;
  const double wide = analyseLens(lens, o).rmsSpotMm.x;
  o.fNumber = 50.0;
  const double narrow = analyseLens(lens, o).rmsSpotMm.x;
  EXPECT_GT(wide, 0.0);
  EXPECT_NEAR(wide / narrow, 8.0, 0.4);
}

// A thin lens's focal length varies with the index as 1/(n − 1): between the F and C lines the
// back focus moves by −f/V.
TEST(LensAnalysis, AThinLensesAxialColourIsFocalLengthOverAbbe) {
  const double abbe = 64.17;
  const LensPrescription lens = thinLens(50.0, 1.5168, abbe, 4.0);
  LensAnalysisOptions o;
  o.sensorMm = {2.0, 2.0};
  o.fieldSamples = 2;
  o.pupilSamples = 8;
  const LensReport r = analyseLens(lens, o);
  ASSERT_TRUE(r.dispersion);
  EXPECT_NEAR(r.axialColourMm / (-r.firstOrder.focalLengthMm / abbe), 1.0, 0.02);
  EXPECT_LT(std::abs(r.lateralColourMm), 1e-3)
      << "a thin lens with its stop in contact has no lateral colour to first order";
}

TEST(LensAnalysis, DistortionFitsFollowTheTracedField) {
  LensAnalysisOptions o;
  o.pupilSamples = 16;
  const LensReport gauss = analyseLens(bundled("double-gauss-50mm.lens"), o);
  EXPECT_FALSE(gauss.fisheye);
  EXPECT_LT(gauss.brownRmsErrorPercent, 0.1);
  EXPECT_LT(gauss.field.back().distortionPercent, 0.0) << "barrel distortion at the corner";
  o.sensorMm = {18.0, 18.0};
  const LensReport fisheye = analyseLens(bundled("fisheye-10mm.lens"), o);
  EXPECT_TRUE(fisheye.fisheye);
  EXPECT_LT(fisheye.equidistantRmsErrorPercent, 1.0);
  EXPECT_NEAR(fisheye.equidistantFocalMm / fisheye.firstOrder.focalLengthMm, 1.0, 0.02);
  EXPECT_LT(fisheye.field.back().distortionPercent, -40.0) << "far from rectilinear";
}

TEST(LensAnalysis, ASensorBeyondTheImageCircleIsRefusedWithTheCircle) {
  const std::string message = refusalOf([] { analyseLens(bundled("fisheye-10mm.lens"), {}); });
  EXPECT_NE(message.find("the lens covers a circle of"), std::string::npos) << message;
  EXPECT_NE(message.find("give a --sensor whose diagonal is at most"), std::string::npos) << message;
  LensAnalysisOptions o;
  o.fNumber = 1.0;
  EXPECT_NE(refusalOf([&] {
              analyseLens(bundled("double-gauss-50mm.lens"), o);
            }).find("f/1 is faster than the design's full opening"),
            std::string::npos);
}

}  // namespace
}  // namespace lenslab
