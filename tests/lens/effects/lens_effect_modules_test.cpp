// The lens-effect modules (lens/effects/): the registry lists each effect once; every effect's keys
// round-trip through the camera writer and reader; each effect is interpolated along a path; at
// zero strength no effect asks anything of the frame; each module's shader snippet exists; the
// vignetting polynomial is one text for C++ and GLSL.
#include "camera/CameraPath.h"
#include "core/DataPaths.h"
#include "io/CameraJson.h"
#include "io/CameraPathJson.h"
#include "lens/effects/LensEffectRegistry.h"
#include "plan/FramePlan.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <cmath>
#include <random>
#include <string>

namespace lenslab {
namespace {

const char* const kView = R"({"vrp": [0,0,0], "vpn": [0,0,1], "prp": [0,0,2], "window": [-0.6,-0.4,0.6,0.4],
                              "aperture_radius": 0.05})";

// Every effect at a strength that no default has, each field its own value.
Lens everyEffect() {
  Lens lens;
  Distortion& d = lens.effects.distortion;
  d.k1 = -0.05, d.k2 = 0.011, d.p1 = 0.0013, d.p2 = -0.0007, d.k3 = 0.0021, d.alpha = 0.012, d.beta = -0.019,
  d.gamma = 0.0031;
  Chromatic& c = lens.effects.chromatic;
  c.lateralRed = 0.002, c.lateralBlue = -0.0015, c.inverseFocusShiftRed = -0.02, c.inverseFocusShiftBlue = 0.03;
  lens.effects.fieldCurvature.inverseFocusPerRadius2 = 0.1;
  lens.effects.vignetting = {-0.3, 0.05, -0.01};
  lens.aperture = {7, 10.0, 0.3, 1.5};
  lens.barrel = barrelFromMillimetres(20.0, 30.0);
  return lens;
}

Camera cameraWith(const Lens& lens) {
  Camera camera = parseCameraJson(kView, "view.json").camera;
  camera.lens.effects = lens.effects;
  camera.lens.aperture = lens.aperture;
  camera.lens.barrel = lens.barrel;
  camera.source = "test camera";
  return camera;
}

void expectSameLens(const Lens& a, const Lens& b) {
  const Distortion &x = a.effects.distortion, &y = b.effects.distortion;
  for (const auto& [p, q] : {std::pair{x.k1, y.k1},
                             {x.k2, y.k2},
                             {x.p1, y.p1},
                             {x.p2, y.p2},
                             {x.k3, y.k3},
                             {x.alpha, y.alpha},
                             {x.beta, y.beta},
                             {x.gamma, y.gamma}})
    EXPECT_DOUBLE_EQ(p, q);
  const Chromatic &c = a.effects.chromatic, &e = b.effects.chromatic;
  EXPECT_DOUBLE_EQ(c.lateralRed, e.lateralRed);
  EXPECT_DOUBLE_EQ(c.lateralBlue, e.lateralBlue);
  EXPECT_NEAR(c.inverseFocusShiftRed, e.inverseFocusShiftRed, 1e-12);
  EXPECT_NEAR(c.inverseFocusShiftBlue, e.inverseFocusShiftBlue, 1e-12);
  EXPECT_NEAR(a.effects.fieldCurvature.inverseFocusPerRadius2, b.effects.fieldCurvature.inverseFocusPerRadius2, 1e-12);
  EXPECT_DOUBLE_EQ(a.effects.vignetting.a1, b.effects.vignetting.a1);
  EXPECT_DOUBLE_EQ(a.effects.vignetting.a2, b.effects.vignetting.a2);
  EXPECT_DOUBLE_EQ(a.effects.vignetting.a3, b.effects.vignetting.a3);
  EXPECT_EQ(a.aperture, b.aperture);
  EXPECT_NEAR(a.barrel.distance, b.barrel.distance, 1e-15);
  EXPECT_NEAR(a.barrel.radius, b.barrel.radius, 1e-15);
}

TEST(LensEffectModules, TheRegistryListsEachEffectOnce) {
  const std::set<std::string> keys = lensEffectKeys();
  EXPECT_EQ(keys,
            (std::set<std::string>{"aperture", "barrel", "chromatic", "distortion", "field_curvature", "vignetting"}));
  EXPECT_EQ(keys.size(), lensEffectModules().size());
}

TEST(LensEffectModules, EveryEffectsKeysRoundTripThroughWriteAndRead) {
  const Camera camera = cameraWith(everyEffect());
  const CameraFile again = parseCameraJson(toCameraJson(camera), "again.json");
  expectSameLens(again.camera.lens, everyEffect());
}

TEST(LensEffectModules, EachModuleWritesItsOwnKeyAndReadsItBack) {
  const Lens all = everyEffect();
  for (const LensEffectModule* module : lensEffectModules()) {
    SCOPED_TRACE(module->key);
    Lens one;
    module->interpolate(all, all, 0.0, one);  // the module's part of `all`, nothing else
    const std::string text = toCameraJson(cameraWith(one));
    for (const LensEffectModule* other : lensEffectModules()) {
      const bool written = text.find(std::string("\"") + other->key + "\"") != std::string::npos;
      EXPECT_EQ(written, other == module) << other->key << " in " << text;
    }
    expectSameLens(parseCameraJson(text, "one.json").camera.lens, one);
  }
}

TEST(LensEffectModules, EachEffectIsInterpolatedAlongAPath) {
  const Lens b = everyEffect();
  Lens a;  // zero strength; the aperture and the barrel are the first key's along a segment
  a.aperture = b.aperture;
  a.barrel = b.barrel;
  const Lens quarter = interpolateLens(a, b, 0.25);
  const Distortion& d = quarter.effects.distortion;
  EXPECT_DOUBLE_EQ(d.k1, 0.25 * b.effects.distortion.k1);
  EXPECT_DOUBLE_EQ(d.p2, 0.25 * b.effects.distortion.p2);
  EXPECT_DOUBLE_EQ(d.gamma, 0.25 * b.effects.distortion.gamma);
  EXPECT_DOUBLE_EQ(quarter.effects.chromatic.lateralRed, 0.25 * b.effects.chromatic.lateralRed);
  EXPECT_DOUBLE_EQ(quarter.effects.chromatic.inverseFocusShiftBlue, 0.25 * b.effects.chromatic.inverseFocusShiftBlue);
  EXPECT_DOUBLE_EQ(quarter.effects.fieldCurvature.inverseFocusPerRadius2,
                   0.25 * b.effects.fieldCurvature.inverseFocusPerRadius2);
  EXPECT_DOUBLE_EQ(quarter.effects.vignetting.a1, 0.25 * b.effects.vignetting.a1);
  EXPECT_DOUBLE_EQ(quarter.effects.vignetting.a3, 0.25 * b.effects.vignetting.a3);
  EXPECT_EQ(quarter.aperture, b.aperture);
  EXPECT_EQ(quarter.barrel, b.barrel);
  // Either end is the key itself.
  expectSameLens(interpolateLens(a, b, 1.0), b);
}

// Along a camera path, between keys: vignetting too (it was once held at zero between keys).
TEST(LensEffectModules, APathCarriesEveryEffectBetweenItsKeys) {
  const CameraPath path = parseCameraPath(R"({"fps": 1, "keys": [
      {"time": 0, "eye": [0,0,5], "target": [0,0,0], "f_number": 4, "vignetting": {"a1": -0.2},
       "distortion": {"k1": -0.1}, "chromatic": {"lateral_red": 0.002}},
      {"time": 2, "eye": [0,0,5], "target": [0,0,0], "f_number": 4, "vignetting": {"a1": -0.4},
       "distortion": {"k1": -0.2}, "chromatic": {"lateral_red": 0.004}}]})",
                                          "path.json");
  const PathKey middle = cameraAt(path, 1.0);
  EXPECT_NEAR(middle.lens.effects.vignetting.a1, -0.3, 1e-15);
  EXPECT_NEAR(middle.lens.effects.distortion.k1, -0.15, 1e-15);
  EXPECT_NEAR(middle.lens.effects.chromatic.lateralRed, 0.003, 1e-15);
}

TEST(LensEffectModules, ZeroStrengthAsksNothingOfTheFrame) {
  PlanView view;
  view.inverseFocus = 0.5;
  view.farthestCornerSlope = 0.36;
  Lens zero;  // an aperture, no effect
  zero.apertureRadius = 0.05;
  const EffectNeeds none;
  const auto same = [](const EffectNeeds& x, const EffectNeeds& y) {
    return x.viewsPerSample == y.viewsPerSample && x.sceneVariants == y.sceneVariants &&
           x.fieldCurvatureWarp == y.fieldCurvatureWarp && x.lensVariants == y.lensVariants &&
           x.remapTables == y.remapTables && x.finalGain == y.finalGain &&
           x.idleThroughPinhole == y.idleThroughPinhole && x.minApertureSamples == y.minApertureSamples;
  };
  for (const LensEffectModule* module : lensEffectModules()) {
    SCOPED_TRACE(module->key);
    EffectNeeds needs;
    module->plan(zero, view, needs);
    EXPECT_TRUE(same(needs, none));
    // At strength, every module but the aperture's asks something (the aperture widens the
    // circles of confusion, which the plan reads from the camera).
    Lens one = zero;
    const Lens all = everyEffect();
    module->interpolate(all, all, 0.0, one);
    EffectNeeds strong;
    module->plan(one, view, strong);
    if (std::string(module->key) != "aperture") {
      EXPECT_FALSE(same(strong, none));
    }
  }
  EXPECT_TRUE(same(effectNeeds(zero, view), none));
}

TEST(LensEffectModules, ZeroVignettingAddsNoPass) {
  Scene scene;
  scene.bounds.min = {-1.0, -1.0, -1.0};
  scene.bounds.max = {1.0, 1.0, 0.0};
  const std::string view = R"("vrp": [0,0,0], "vpn": [0,0,1], "prp": [0,0,2], "window": [-0.72,-0.48,0.72,0.48])";
  for (const std::string& lens : {std::string(), std::string(R"(, "aperture_radius": 0.05)")}) {
    const FramePlan plain = makeFramePlan(scene, parseCameraJson("{" + view + lens + "}", "a.json").camera, {120, 80});
    const FramePlan zero = makeFramePlan(
        scene, parseCameraJson("{" + view + lens + R"(, "vignetting": {"a1": 0, "a2": 0})" + "}", "b.json").camera,
        {120, 80});
    ASSERT_EQ(plain.passes.size(), zero.passes.size());
    for (std::size_t i = 0; i < plain.passes.size(); ++i) {
      EXPECT_EQ(plain.passes[i].name, zero.passes[i].name);
      EXPECT_EQ(plain.passes[i].variants, zero.passes[i].variants);
    }
    EXPECT_FALSE(zero.vignetting);
  }
}

TEST(LensEffectModules, EachShaderSnippetExists) {
  const std::optional<std::filesystem::path> shaders = shaderDirectory();
  ASSERT_TRUE(shaders);
  for (const LensEffectModule* module : lensEffectModules())
    if (*module->shaderSnippet) {
      EXPECT_TRUE(std::filesystem::exists(*shaders / module->shaderSnippet)) << module->key;
    }
}

// The C++ polynomial is the shader's text (common/vignetting_gain.glsl) compiled in double:
// Horner's form of 1 + a1 r² + a2 r⁴ + a3 r⁶, clamped at 0 for the gain (0 for NaN).
TEST(LensEffectModules, VignettingPolynomialIsTheShadersText) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0), radius2(0.0, 2.0);
  for (int i = 0; i < 4096; ++i) {
    const double a1 = coefficient(random), a2 = 0.5 * coefficient(random), a3 = 0.2 * coefficient(random),
                 r2 = radius2(random);
    const double exact = 1.0 + r2 * (a1 + r2 * (a2 + r2 * a3));
    EXPECT_EQ(vignettingPolynomial(r2, a1, a2, a3), exact);
    EXPECT_EQ(Vignetting({a1, a2, a3}).gain(r2), exact > 0.0 ? exact : 0.0);
  }
  EXPECT_EQ(Vignetting({-1.0, 0.0, 0.0}).gain(std::nan("")), 0.0);
}

}  // namespace
}  // namespace lenslab
