// `render --lens`: the real-time camera fitted to a prescription (lens/LensFit, camera/LensFitCamera)
// against the same lens traced exactly by the ray caster. The fit must come closer to the exact
// image than the first-order thin lens a user would otherwise build from the lens's data sheet
// (its effective focal length and paraxial pupil, no effects), and each of its effects must
// earn its place.
#include "camera/LensFitCamera.h"
#include "camera/PhysicalCamera.h"
#include "core/Text.h"
#include "../common/gl_test_context.h"
#include "io/ImageCompare.h"
#include "core/TextFile.h"
#include "lens/LensCamera.h"
#include "lens/LensFit.h"
#include "lens/ParaxialLens.h"
#include "plan/FramePlan.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "scene/GltfLoader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>

namespace lenslab {
namespace {

TEST(LensFitRender, TheFitComesCloserToTheExactLensThanFirstOrder) {
  LENSLAB_REQUIRE_GL();
  const std::filesystem::path assets = LENSLAB_TEST_ASSET_DIR;
  const Scene scene = loadGltf(assets / "rows" / "rows.gltf");
  const std::string path = (assets / "lenses" / "double-gauss-50mm.lens").string();
  const auto lens = std::make_shared<LensPrescription>(parseLensPrescription(readTextFile(path, "lens file"), path));

  // camera-dof.json's place, the lens at f/4 focused on the red box's row.
  PhysicalCamera physical;
  physical.eye = {0.0, 1.0, 3.0};
  physical.target = {0.0, 0.55, -2.0};
  physical.focalLengthMm = 50.0;
  physical.fNumber = 4.0;
  physical.focusDistance = 4.0;
  const Camera like = toCamera(physical, "rows through the double Gauss");
  LensCameraSettings settings;
  settings.fNumber = 4.0;
  settings.focusDistance = like.focusDistance();
  LensCameraPose pose;
  pose.eye = physical.eye;
  pose.forward = glm::normalize(physical.target - physical.eye);
  pose.right = glm::normalize(glm::cross(pose.forward, physical.up));
  pose.up = glm::cross(pose.right, pose.forward);
  const LensCamera exactLens(lens, settings, pose);

  LensFitSettings fitSettings;
  fitSettings.fNumber = 4.0;
  fitSettings.focusDistanceMm = settings.focusDistance / pose.worldPerMm;
  const FittedLens fit = fitLens(*lens, fitSettings);
  ASSERT_TRUE(fit.usable) << fit.why;
  const Camera fitted = cameraForFittedLens(like, fit, settings.sensorMm, pose.worldPerMm, "fitted");
  // The data sheet's thin lens: effective focal length, paraxial pupil, the focus asked for.
  FittedLens sheet;
  sheet.usable = true;
  sheet.focalLengthMm = firstOrder(*lens).focalLengthMm;
  sheet.entrancePupilDiameterMm = fit.entrancePupilDiameterMm;
  sheet.inverseFocusPerMm = 1.0 / fitSettings.focusDistanceMm;
  const Camera firstOrderCamera = cameraForFittedLens(like, sheet, settings.sensorMm, pose.worldPerMm, "first order");

  const ImageSize size{120, 80};
  const RayCaster caster(scene);
  const Image exactA = caster.render(exactLens, like, size, RaycastOptions{128, 3});
  const Image exactB = caster.render(exactLens, like, size, RaycastOptions{128, 4});
  const double noise = compareImages(exactA, exactB, 0.0).rmse;
  Renderer renderer(scene);
  const auto psnrOf = [&](const Camera& camera) {
    const Image image = renderer.render(
        camera, makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Sobol, 256, 256, 1}), size);
    const double raw = compareImages(image, exactA, 0.0).rmse;
    return -20.0 * std::log10(std::sqrt(std::max(raw * raw - 0.5 * noise * noise, 1e-12)));
  };
  const double fittedDb = psnrOf(fitted), firstOrderDb = psnrOf(firstOrderCamera);
  Camera noDistortion = fitted;
  noDistortion.lens.effects.distortion = {};
  const double noDistortionDb = psnrOf(noDistortion);
  Camera noVignetting = fitted;
  noVignetting.lens.effects.vignetting = {};
  const double noVignettingDb = psnrOf(noVignetting);
  std::cout << "[ measure  ] rows, double Gauss f/4 focused at 4 m, 120x80: fitted " << fittedDb << " dB, first order "
            << firstOrderDb << " dB, fitted without distortion " << noDistortionDb << " dB, without vignetting "
            << noVignettingDb << " dB against the exact trace "
            << "(128 spp, its noise taken out)\n";
  RecordProperty("fitted_db", cat(fittedDb));
  EXPECT_GE(fittedDb, firstOrderDb + 10.0);
  EXPECT_GE(fittedDb, noDistortionDb + 6.0);
  EXPECT_GE(fittedDb, noVignettingDb + 6.0);
  EXPECT_GE(fittedDb, 38.0);
}

}  // namespace
}  // namespace lenslab
