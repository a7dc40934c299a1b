// Lens prescriptions (lens/LensPrescription, ParaxialLens, RealLens) against closed forms: the
// lensmaker's equation for a thick singlet, a plano-convex lens, a flat plate's lateral shift,
// real rays tending to the paraxial focus, the thick-lens equation for focusing, the pupils as
// images of the stop, and the dispersion model's defining numbers.
#include "../common/refusal.h"
#include "lens/LensPrescription.h"
#include "lens/ParaxialLens.h"
#include "lens/RealLens.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace lenslab {
namespace {
using test::refusalOf;

constexpr double kPi = 3.14159265358979323846;

// A stop 2 mm in front of a singlet of radii r1, r2, centre thickness t and index n.
std::string singlet(double r1, double r2, double t, double n, double apertureMm = 20.0) {
  return "# a singlet\n0 2 0 10\n" + std::to_string(r1) + " " + std::to_string(t) + " " + std::to_string(n) + " " +
         std::to_string(apertureMm) + "\n" + (std::isinf(r2) ? std::string("inf") : std::to_string(r2)) + " 0 1 " +
         std::to_string(apertureMm) + "\n";
}

// The lensmaker's equation for a thick lens in air, and its principal planes measured from the
// vertices (positive toward the film).
struct ThickLens {
  double f, frontPrincipalFromFirstVertex, rearPrincipalFromLastVertex;
};
ThickLens thickLens(double r1, double r2, double t, double n) {
  const double power = (n - 1.0) * (1.0 / r1 - 1.0 / r2 + (n - 1.0) * t / (n * r1 * r2));
  const double f = 1.0 / power;
  return {f, -f * (n - 1.0) * t / (n * r2), -f * (n - 1.0) * t / (n * r1)};
}

TEST(LensPrescription, ReadsRowsCommentsAndPbrtsStopRow) {
  const LensPrescription lens = parseLensPrescription(
      "# Test design\n#   radius thickness index aperture\n29.475\t3.76\t1.67\t25.2\n84.83 2 1 25.2 # air gap\n\n"
      "0 4.5 0 17.1\n-14.495 1.18 1.603 17\n-40 0 1 17\n",
      "test.dat");
  ASSERT_EQ(lens.surfaces.size(), 5u);
  EXPECT_EQ(lens.comments.front(), "Test design");
  EXPECT_EQ(lens.stopIndex(), 2u);
  EXPECT_EQ(lens.surfaces[2].indexAfter, 1.0);  // pbrt's 0 on the stop row is air
  EXPECT_EQ(lens.surfaces[3].line, 7);
  EXPECT_DOUBLE_EQ(lens.vertexMm(3), 3.76 + 2.0 + 4.5);
  EXPECT_FALSE(lens.hasDispersion());
}

TEST(LensPrescription, BadRowsAreRefusedNamingRowLineAndColumn) {
  const auto refusal = [](const char* text) { return refusalOf([&] { parseLensPrescription(text, "bad.dat"); }); };
  EXPECT_EQ(refusal("0 2 0 10\n50 x 1.5 20\n-50 0 1 20\n"),
            "bad.dat: row 2 (line 2), column 2 (thickness_mm): 'x' is not a number");
  EXPECT_EQ(refusal("0 2 0 10\n50 5 1.5\n-50 0 1 20\n"),
            "bad.dat: row 2 (line 2) has 3 numbers; give 4 or 5: radius_mm thickness_mm index aperture_mm [abbe]");
  EXPECT_NE(
      refusal("0 2 0 10\n50 -5 1.5 20\n-50 0 1 20\n").find("row 2 (line 2), column 2 (thickness_mm): -5 is negative"),
      std::string::npos);
  EXPECT_NE(refusal("0 2 0 10\n50 5 0.5 20\n-50 0 1 20\n").find("column 3 (index)"), std::string::npos);
  EXPECT_NE(refusal("0 2 0 10\n50 5 1.5 0\n-50 0 1 20\n").find("column 4 (aperture_mm)"), std::string::npos);
  EXPECT_NE(refusal("0 2 0 10\n5 5 1.5 20\n-50 0 1 20\n").find("row 2 (line 2), column 1 (radius_mm)"),
            std::string::npos);
  EXPECT_NE(refusal("50 5 1.5 20\n-50 0 1 20\n").find("0 rows have radius 0"), std::string::npos);
  EXPECT_NE(refusal("0 1 0 10\n0 2 0 10\n50 5 1.5 20\n-50 0 1 20\n").find("2 rows have radius 0"), std::string::npos);
  EXPECT_NE(refusal("0 2 0 10\n50 5 1.5 20\n-50 1 1.5 20\n").find("the last surface must leave the light in air"),
            std::string::npos);
  EXPECT_NE(
      refusal("0 2 0 10\n50 5 1.5 20 64\n-50 2 1.6 20\n-80 0 1 20\n").find("1 of 2 glass rows give an Abbe number"),
      std::string::npos);
  EXPECT_NE(refusal("0 2 0 10\n50 5 1 20 64\n-50 0 1 20\n").find("column 5 (abbe): air has no Abbe number"),
            std::string::npos);
  EXPECT_NE(refusal("0 2 0 10 3\n").find("column 5 (abbe)"), std::string::npos);
}

// Lengths in a stated range (a 1e300 thickness overflowed every sum along the axis), at most
// kMaxLensSurfaces rows (a thousand took minutes), and a lens that forms no real image named as such.
TEST(LensPrescription, LengthsRowCountAndPowerAreBounded) {
  const auto refusal = [](const std::string& text) {
    return refusalOf([&] { parseLensPrescription(text, "l.lens"); });
  };
  EXPECT_EQ(
      refusal("50 1e300 1.5 20\n-50 5 1 20\n0 0 0 10\n"),
      "l.lens: row 1 (line 1), column 2 (thickness_mm): 1e300 is out of range; give a finite value of at most 10000");
  EXPECT_NE(refusal("1e9 5 1.5 20\n-50 5 1 20\n0 0 0 10\n").find("column 1 (radius_mm): 1e9 is out of range"),
            std::string::npos);
  EXPECT_NE(refusal("50 5 1.5 2e4\n-50 5 1 20\n0 0 0 10\n").find("column 4 (aperture_mm): 2e4 is out of range"),
            std::string::npos);
  EXPECT_EQ(refusal("inf 5 1.5 20\n-1e7 5 1 20\n0 0 0 10\n"), "accepted");  // a plane and a nearly flat surface
  std::string rows;
  for (int i = 0; i < kMaxLensSurfaces - 1; ++i) rows += "inf 0.1 1 40\n";
  EXPECT_EQ(refusal(rows + "0 0 0 10\n"), "accepted");
  EXPECT_EQ(
      refusal(rows + "inf 0.1 1 40\n0 0 0 10\n"),
      "l.lens: row 129 (line 129): more than 128 surface rows; lenslab traces at most 128 (a camera lens has fewer "
      "than 60)");
  const LensPrescription diverging = parseLensPrescription("-50 5 1.5 20\n50 5 1 20\n0 0 0 10\n", "d.lens");
  EXPECT_NE(refusalOf([&] { firstOrder(diverging); }).find("d.lens: the lens diverges (its focal length is -49."),
            std::string::npos);
}

// A file whose second column is each surface's distance from the one before (a shifted column)
// gives its first glass no thickness; surfaces that cross within the aperture are refused too.
TEST(LensPrescription, ElementsOfNoThicknessOrCrossingSurfacesAreRefused) {
  EXPECT_EQ(refusalOf([] {
              parseLensPrescription("163.579 0 1.540 107.8\n53.169 5.529 1.0 81.8\n0 10 0 39.8\n-54.424 0 1.0 81.8\n",
                                    "shifted.dat");
            }),
            "shifted.dat: row 1 (line 1), column 2 (thickness_mm): 0 for a glass: an element needs a centre thickness "
            "> 0 (the column is "
            "the distance to the next surface)");
  const std::string crossing =
      refusalOf([] { parseLensPrescription("50 1 1.5 40\n-50 3 1 40\n0 0 0 10\n", "crossing.dat"); });
  EXPECT_NE(
      crossing.find(
          "crossing.dat: rows 1 and 2 (lines 1 and 2) cross inside their clear aperture: 1 mm apart on the axis but"),
      std::string::npos)
      << crossing;
  EXPECT_EQ(refusalOf([] {
              parseLensPrescription("163.579 5.529 1.540 107.8\n53.169 10 1.0 81.8\n0 10 0 39.8\n-54.424 0 1.0 81.8\n",
                                    "ok");
            }),
            "accepted");
}

TEST(ParaxialLens, ThickSingletFollowsTheLensmakersEquation) {
  for (const auto& [r1, r2, t, n] : {std::tuple{50.0, -80.0, 6.0, 1.5168}, std::tuple{30.0, 200.0, 4.0, 1.8},
                                     std::tuple{-60.0, -25.0, 8.0, 1.6}, std::tuple{40.0, -40.0, 12.0, 1.5}}) {
    const LensPrescription lens = parseLensPrescription(singlet(r1, r2, t, n), "singlet");
    const FirstOrder f = firstOrder(lens);
    const ThickLens expected = thickLens(r1, r2, t, n);
    const double first = 2.0, last = 2.0 + t;  // the lens's vertices (the stop is at 0)
    EXPECT_NEAR(f.focalLengthMm, expected.f, 1e-12 * std::abs(expected.f)) << r1 << " " << r2;
    EXPECT_NEAR(f.rearPrincipalMm, last + expected.rearPrincipalFromLastVertex, 1e-10 * std::abs(expected.f));
    EXPECT_NEAR(f.frontPrincipalMm, first + expected.frontPrincipalFromFirstVertex, 1e-10 * std::abs(expected.f));
    EXPECT_NEAR(f.backFocalMm, expected.f + expected.rearPrincipalFromLastVertex, 1e-10 * std::abs(expected.f));
  }
}

TEST(ParaxialLens, PlanoConvexLensHasFocalLengthROverNMinusOne) {
  const double r = 40.0, n = 1.5, t = 5.0;
  const LensPrescription lens = parseLensPrescription(singlet(r, INFINITY, t, n), "plano-convex");
  const FirstOrder f = firstOrder(lens);
  EXPECT_NEAR(f.focalLengthMm, r / (n - 1.0), 1e-12 * r);
  EXPECT_NEAR(f.backFocalMm, r / (n - 1.0) - t / n, 1e-12 * r);  // the plane side: H' at the curved vertex
  // The stop is in front of everything: the entrance pupil is the stop itself.
  EXPECT_NEAR(f.entrancePupilMm, 0.0, 1e-12);
  EXPECT_NEAR(f.entrancePupilDiameterMm, 10.0, 1e-12);
  EXPECT_NEAR(f.fNumber, 80.0 / 10.0, 1e-12);
}

TEST(RealLens, FlatPlateShiftsARaySidewaysByTheClosedForm) {
  const double t = 10.0, n = 1.5;
  const LensPrescription plate = parseLensPrescription("0 1 0 50\ninf 10 1.5 50\ninf 0 1 50\n", "plate");
  EXPECT_NE(refusalOf([&] { firstOrder(plate); }).find("no optical power"), std::string::npos);
  for (double degrees : {0.0, 5.0, 20.0, 45.0}) {
    const double theta = degrees * kPi / 180.0;
    const LensRay in{{0.0, 0.0, -5.0}, {std::sin(theta), 0.0, std::cos(theta)}};
    const std::optional<LensRay> out = traceLens(plate, in, false);
    ASSERT_TRUE(out) << degrees;
    EXPECT_NEAR(glm::length(out->direction - in.direction), 0.0, 1e-14) << "leaves parallel to itself, " << degrees;
    // Lateral displacement between the incident line and the emerging one.
    const double shift =
        t * std::sin(theta) * (1.0 - std::cos(theta) / std::sqrt(n * n - std::sin(theta) * std::sin(theta)));
    const glm::dvec3 offset = out->origin - in.origin;
    const double measured = glm::length(offset - glm::dot(offset, in.direction) * in.direction);
    EXPECT_NEAR(measured, shift, 1e-12) << degrees;
  }
}

// Rays parallel to the axis at height h cross it ever closer to the paraxial rear focal point as
// h → 0 (the difference is spherical aberration, growing as h²).
TEST(RealLens, RealRaysTendToTheParaxialFocusAsTheApertureShrinks) {
  const LensPrescription lens = parseLensPrescription(singlet(50.0, -80.0, 6.0, 1.5168, 30.0), "singlet");
  const FirstOrder f = firstOrder(lens);
  const double paraxialFocus = lens.lengthMm() + f.backFocalMm;
  double previous = INFINITY;
  for (double h : {4.0, 1.0, 0.1, 1e-3}) {
    const std::optional<LensRay> out = traceLens(lens, {{0.0, h, -10.0}, {0.0, 0.0, 1.0}}, false);
    ASSERT_TRUE(out) << h;
    const double crossing = out->origin.z - out->origin.y / out->direction.y * out->direction.z;
    const double error = std::abs(crossing - paraxialFocus) / f.focalLengthMm;
    EXPECT_LT(error, previous) << h;
    previous = error;
    if (h <= 1e-3) {
      EXPECT_LT(error, 1e-6);
    }
    if (h >= 4.0) {
      EXPECT_GT(error, 1e-4) << "a real lens has spherical aberration";
    }
  }
}

TEST(RealLens, ARayTracedToTheFilmAndBackIsTheSameRay) {
  const LensPrescription lens = parseLensPrescription(singlet(50.0, -80.0, 6.0, 1.5168, 30.0), "singlet");
  const LensRay in{{1.0, -2.0, -30.0}, glm::normalize(glm::dvec3(0.02, 0.05, 1.0))};
  const std::optional<LensRay> there = traceLens(lens, in, false);
  ASSERT_TRUE(there);
  const std::optional<LensRay> back = traceLens(lens, {there->origin, -there->direction}, true);
  ASSERT_TRUE(back);
  EXPECT_NEAR(glm::length(back->direction + in.direction), 0.0, 1e-13);
  const glm::dvec3 offset = back->origin - in.origin;
  EXPECT_NEAR(glm::length(offset - glm::dot(offset, in.direction) * in.direction), 0.0, 1e-12);
}

TEST(RealLens, RimsAndTheStopStopRays) {
  const LensPrescription lens = parseLensPrescription(singlet(50.0, -80.0, 6.0, 1.5168, 30.0), "singlet");
  EXPECT_TRUE(traceLens(lens, {{0.0, 4.9, -1.0}, {0.0, 0.0, 1.0}}, false));
  EXPECT_FALSE(traceLens(lens, {{0.0, 5.1, -1.0}, {0.0, 0.0, 1.0}}, false)) << "outside the 10 mm stop";
  LensTrace wide;
  wide.stopDiameterMm = 40.0;  // the stop opened beyond the lens: its 30 mm rim stops the ray
  EXPECT_TRUE(traceLens(lens, {{0.0, 14.0, -1.0}, {0.0, 0.0, 1.0}}, false, wide));
  EXPECT_FALSE(traceLens(lens, {{0.0, 15.5, -1.0}, {0.0, 0.0, 1.0}}, false, wide));
}

// Focusing: the film distance for an object at distance s satisfies the thick-lens equation
// 1/s_o + 1/s_i = 1/f with s_o and s_i measured from the principal planes.
TEST(ParaxialLens, FocusingMovesTheFilmAsTheThickLensEquationSays) {
  const double r1 = 50.0, r2 = -80.0, t = 6.0, n = 1.5168;
  const LensPrescription lens = parseLensPrescription(singlet(r1, r2, t, n), "singlet");
  const ThickLens tl = thickLens(r1, r2, t, n);
  const double first = 2.0, last = 2.0 + t;
  EXPECT_NEAR(filmDistanceForFocusMm(lens, INFINITY), tl.f + tl.rearPrincipalFromLastVertex, 1e-10);
  for (double objectFromStop : {3000.0, 1000.0, 400.0}) {
    const double so = objectFromStop + first + tl.frontPrincipalFromFirstVertex;  // object to H
    const double si = tl.f * so / (so - tl.f);                                    // H' to image
    const double film = last + tl.rearPrincipalFromLastVertex + si;               // from the stop (z = 0)
    const double focusFromFilm = objectFromStop + film;
    EXPECT_NEAR(filmDistanceForFocusMm(lens, focusFromFilm), film - last, 1e-9 * tl.f) << objectFromStop;
  }
  EXPECT_NE(refusalOf([&] { filmDistanceForFocusMm(lens, 100.0); }).find("no real image"), std::string::npos);
}

// The entrance pupil is the stop's image through what lies in front of it: a chief ray aimed at
// the pupil's centre passes through the stop's centre (paraxially), and one aimed at the pupil's
// rim passes the stop's rim.
TEST(ParaxialLens, PupilsAreImagesOfTheStop) {
  const LensPrescription lens = parseLensPrescription(
      "# a stop between two singlets\n40 5 1.6 24\n-120 6 1 24\n0 6 0 8\n90 5 1.6 24\n-45 0 1 24\n", "pair");
  const FirstOrder f = firstOrder(lens);
  const double stopZ = lens.vertexMm(2);
  // The front group alone, the stop's row turned into a plane of air where the trace ends.
  LensPrescription front = lens;
  front.surfaces.resize(3);
  front.surfaces[2].radiusMm = INFINITY;
  front.surfaces[2].apertureMm = 100.0;
  for (double slope : {1e-4, -3e-4}) {
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.0, slope, 1.0));
    const glm::dvec3 onPupil(0.0, 0.0, f.entrancePupilMm);
    const std::optional<LensRay> r = traceLens(front, {onPupil - 50.0 * d, d}, false);
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->origin.z, stopZ, 1e-9);
    // Paraxially 0; what is left is third order in the slope.
    EXPECT_LT(std::abs(r->origin.y), 1e-9) << "the chief ray crosses the stop's centre, slope " << slope;
  }
  // A ray parallel to the axis at the entrance pupil's radius meets the stop's rim (paraxially).
  const double h = 1e-3;
  const std::optional<LensRay> rim =
      traceLens(front, {{0.0, h * f.entrancePupilDiameterMm / 2.0, -10.0}, {0.0, 0.0, 1.0}}, false);
  ASSERT_TRUE(rim);
  EXPECT_NEAR(rim->origin.y / (h * 4.0), 1.0, 1e-5) << "entrance pupil's radius images onto the stop's (4 mm)";
  EXPECT_GT(f.exitPupilDiameterMm, 0.0);
}

TEST(RealLens, TheDispersionModelHasTheAbbeNumbersDefiningValues) {
  for (const auto& [nd, vd] : {std::pair{1.5168, 64.17}, std::pair{1.7552, 27.58}, std::pair{1.62, 36.4}}) {
    EXPECT_NEAR(indexAtWavelength(nd, vd, kLineDNm), nd, 1e-15);
    const double nF = indexAtWavelength(nd, vd, kLineFNm), nC = indexAtWavelength(nd, vd, kLineCNm);
    EXPECT_NEAR((nd - 1.0) / (nF - nC), vd, 1e-9 * vd);
    EXPECT_GT(indexAtWavelength(nd, vd, 450.0), indexAtWavelength(nd, vd, 650.0)) << "normal dispersion";
  }
  EXPECT_EQ(indexAtWavelength(1.5, 0.0, 450.0), 1.5) << "no Abbe number: no dispersion";
}

}  // namespace
}  // namespace lenslab
