// lens/ExitPupil: the boxes hold every ray that passes (no rings in an image), so that sampling
// them integrates the same irradiance as a search of the whole rear element; and the weights are
// the lens's relative illumination, 1 on the axis.
#include "core/TextFile.h"
#include "lens/ExitPupil.h"
#include "lens/LensAnalysis.h"
#include "lens/ParaxialLens.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace lenslab {
namespace {

LensPrescription bundled(const std::string& name) {
  const std::string path = std::string(LENSLAB_UNIT_ASSET_DIR) + "/lenses/" + name;
  return parseLensPrescription(readTextFile(path, "lens file"), path);
}

// The mean weight over an n × n grid of u: the box's quadrature of the film point's irradiance.
double meanWeight(const ExitPupil& pupil, glm::dvec2 film, int n, double* passing = nullptr) {
  double sum = 0.0;
  int passed = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (const std::optional<FilmRay> r = pupil.sample(film, {(i + 0.5) / n, (j + 0.5) / n})) {
        sum += r->weight;
        ++passed;
        EXPECT_LT(r->ray.direction.z, 0.0) << "toward the scene";
      }
  if (passing) *passing = static_cast<double>(passed) / (n * n);
  return sum / (n * n);
}

// At ring edges (where a box computed at one radius would be too small) and between them, in
// several azimuths, the box's integral equals the search of the whole rear element's.
TEST(ExitPupil, BoxesHoldEveryPassingRayOfTheirRing) {
  for (const char* file : {"double-gauss-50mm.lens", "wide-angle-28mm.lens"}) {
    const LensPrescription lens = bundled(file);
    const double filmZ = lens.lengthMm() + filmDistanceForFocusMm(lens, INFINITY);
    const double halfDiagonal = 0.5 * std::hypot(36.0, 24.0);
    const int rings = 16;
    const ExitPupil pupil(lens, filmZ, halfDiagonal, {}, rings);
    for (double t : {0.0, 0.25, 1.0 / rings - 1e-9, 1.0 / rings, 7.5 / rings, 0.62, 1.0 - 1e-9}) {
      const double r = t * halfDiagonal;
      const double searched = filmIrradianceBySearch(lens, filmZ, r, {}, 256) / pupil.axialIrradiance();
      for (double azimuth : {0.0, 2.0, 4.2}) {
        double passing = 0.0;
        const double boxed = meanWeight(pupil, r * glm::dvec2(std::cos(azimuth), std::sin(azimuth)), 96, &passing);
        EXPECT_NEAR(boxed, searched, 0.01 + 0.01 * searched) << file << " at " << r << " mm, azimuth " << azimuth;
        EXPECT_GT(passing, 0.25) << file << " at " << r << " mm: the box should be tight enough to waste few rays";
      }
    }
  }
}

TEST(ExitPupil, WeightsAreTheRelativeIllumination) {
  const LensPrescription lens = bundled("double-gauss-50mm.lens");
  const double filmZ = lens.lengthMm() + filmDistanceForFocusMm(lens, INFINITY);
  const ExitPupil pupil(lens, filmZ, 21.7, {}, 32);
  EXPECT_NEAR(meanWeight(pupil, {0.0, 0.0}, 96), 1.0, 0.01);
  LensAnalysisOptions o;
  o.pupilSamples = 96;
  const LensReport report = analyseLens(lens, o);
  const FieldSample& corner = report.field.back();
  EXPECT_NEAR(meanWeight(pupil, {corner.imageHeightMm, 0.0}, 96), corner.relativeIllumination, 0.01);
}

}  // namespace
}  // namespace lenslab
