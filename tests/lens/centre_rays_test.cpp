// The AOVs' ray through a real lens (lens/CentreRays.h): the mean line of each film point's bundle,
// traced once per radius and turned to each pixel, is the mean line traced at that very point.
#include "core/TextFile.h"
#include "lens/CentreRays.h"
#include "lens/ExitPupil.h"
#include "lens/LensFitBundles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>

namespace lenslab {
namespace {

TEST(CentreRays, TheTableTurnedToAPixelIsTheBundleTracedThere) {
  const std::filesystem::path path =
      std::filesystem::path(LENSLAB_UNIT_ASSET_DIR) / "lenses" / "double-gauss-50mm.lens";
  const auto lens =
      std::make_shared<LensPrescription>(parseLensPrescription(readTextFile(path, "lens file"), path.string()));
  LensCameraSettings settings;
  settings.focusDistance = 2.0;
  const LensCamera camera(lens, settings, LensCameraPose{});
  const CentreRays rays(camera);
  const int width = 180, height = 120;
  // A film pixel is 0.2 mm: 0.004 of slope at 50 mm. The table must be far closer than that.
  double worstSlope = 0.0, worstOffsetMm = 0.0;
  for (const glm::dvec2 pixel : {glm::dvec2(90.0, 60.0), glm::dvec2(3.25, 7.5), glm::dvec2(171.3, 14.9),
                                 glm::dvec2(33.3, 101.1), glm::dvec2(150.0, 110.2), glm::dvec2(0.5, 119.5)}) {
    const std::optional<LensCamera::WorldRay> table = rays.at(pixel, width, height);
    ASSERT_TRUE(table) << pixel.x << "," << pixel.y;
    const LensFitBundle direct =
        traceLensFitBundle(camera.pupil(1), camera.filmMmOf(pixel, width, height), camera.entrancePupilMm(), 48);
    // The direct line in the world (pose: eye at the origin, looking down −z, 1 mm = 1e-3).
    const LensCamera::WorldRay line = camera.toWorld(glm::dvec3(direct.meanA, camera.entrancePupilMm()),
                                                     glm::dvec3(direct.meanB, -1.0), direct.share);
    const glm::dvec2 slopeTable = glm::dvec2(table->direction) / -table->direction.z;
    const glm::dvec2 slopeDirect = glm::dvec2(line.direction) / -line.direction.z;
    worstSlope = std::max(worstSlope, glm::length(slopeTable - slopeDirect));
    // Where each crosses the entrance pupil's plane (z = 0 in the world here), mm.
    const glm::dvec3 a = table->origin + table->direction * (-table->origin.z / table->direction.z);
    worstOffsetMm = std::max(worstOffsetMm, glm::length(glm::dvec2(a - line.origin)) / 1e-3);
    EXPECT_NEAR(table->weight, direct.share, 0.01);
  }
  std::printf("  centre rays: worst slope error %.2e, worst offset at the pupil %.2e mm\n", worstSlope, worstOffsetMm);
  EXPECT_LT(worstSlope, 4e-5);  // 1 % of a pixel
  // The pupil's grid samples each radius's box afresh: the lines' offsets differ by the grid's
  // resolution. A pixel's footprint is 4 mm at 1 m, so 0.05 mm is about 1 % of one there.
  EXPECT_LT(worstOffsetMm, 0.05);
}

}  // namespace
}  // namespace lenslab
