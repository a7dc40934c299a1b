// Vignetting (lens/LensEffects.h): the gain polynomial, where it reaches 0, the camera file's
// "vignetting" key and its refusals, and the frame plan's pass (left out at zero strength).
#include "camera/LensMap.h"
#include "core/Error.h"
#include "core/Text.h"
#include "io/CameraJson.h"
#include "lens/LensEffects.h"
#include "plan/FramePlan.h"
#include "scene/ProceduralScenes.h"
#include "../common/refusal.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace lenslab {
namespace {

// Window ±0.6 × ±0.4 at PRP distance 2: normalised corner radius √(0.3² + 0.2²) ≈ 0.3606.
const std::string kView = R"("vrp": [0,0,0], "vpn": [0,0,1], "prp": [0,0,2], "window": [-0.6,-0.4,0.6,0.4])";
constexpr double kCornerR2 = 0.3 * 0.3 + 0.2 * 0.2;

std::string refusal(const std::string& tail) {
  return test::refusalOf([&] { parseCameraJson("{" + kView + ", " + tail + "}", "v.json"); });
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(Vignetting, ZeroIsNoGain) {
  const Vignetting none;
  EXPECT_TRUE(none.isZero());
  for (const double r2 : {0.0, 0.5, 4.0}) EXPECT_EQ(none.gain(r2), 1.0);
  for (const Vignetting v : {Vignetting{-0.1, 0, 0}, Vignetting{0, 0.2, 0}, Vignetting{0, 0, -1e-9}})
    EXPECT_FALSE(v.isZero());
}

TEST(Vignetting, GainIsThePolynomialInRSquaredClampedAtZero) {
  const Vignetting v{-0.4, 0.1, -0.02};
  EXPECT_EQ(v.gain(0.0), 1.0);  // the centre keeps its light
  EXPECT_NEAR(v.gain(1.0), 1.0 - 0.4 + 0.1 - 0.02, 1e-15);
  EXPECT_NEAR(v.gain(0.25), 1.0 - 0.4 * 0.25 + 0.1 * 0.0625 - 0.02 * 0.015625, 1e-15);
  // Monotone falling for this lens over the field, and never below 0 far beyond it.
  EXPECT_LT(v.gain(0.5), v.gain(0.25));
  EXPECT_EQ((Vignetting{-2.0, 0, 0}.gain(1.0)), 0.0);
  EXPECT_EQ((Vignetting{-2.0, 0, 0}.gain(10.0)), 0.0);
}

TEST(Vignetting, ZeroCrossingIsFoundWhereTheGainFirstReachesZero) {
  // 1 − t: crosses at t = 1.
  EXPECT_FALSE(vignettingZeroWithin(Vignetting{-1.0, 0, 0}, 0.99));
  ASSERT_TRUE(vignettingZeroWithin({-1.0, 0, 0}, 2.0));
  EXPECT_NEAR(*vignettingZeroWithin({-1.0, 0, 0}, 2.0), 1.0, 1e-12);
  // 1 − 2.2t + 1.2t² dips below 0 between t = 5/6 and 1 and is positive again at the end (0.4 at
  // 1.5): a check of the ends alone would miss it.
  const Vignetting dip{-2.2, 1.2, 0.0};
  EXPECT_GT(dip.gain(1.5), 0.0);
  ASSERT_TRUE(vignettingZeroWithin(dip, 1.5));
  EXPECT_NEAR(*vignettingZeroWithin(dip, 1.5), 5.0 / 6.0, 1e-12);
  // A cubic with a dip that just misses 0 stays positive: 1 − 3t + 3t² − t³·0 has its minimum 0.25.
  EXPECT_FALSE(vignettingZeroWithin({-3.0, 3.0, 0.0}, 10.0));
  // A real fit (cos⁴-like fall-off) inside its field.
  EXPECT_FALSE(vignettingZeroWithin({-0.9, 0.3, -0.05}, 1.0));
  EXPECT_FALSE(vignettingZeroWithin({}, 1e6));
}

TEST(Vignetting, LargestGainIsFoundAtATurningPointInside) {
  EXPECT_EQ(vignettingLargestGain({}, 4.0), 1.0);
  EXPECT_EQ(vignettingLargestGain(Vignetting{-0.5, 0, 0}, 1.0), 1.0);  // falling: the centre's
  EXPECT_NEAR(vignettingLargestGain(Vignetting{0.5, 0, 0}, 1.0), 1.5, 1e-15);
  // 1 + 2t − t²: largest 2 at its turning point t = 1, more than at either end of [0, 1.9].
  EXPECT_NEAR(vignettingLargestGain(Vignetting{2.0, -1.0, 0}, 1.9), 2.0, 1e-12);
}

TEST(VignettingJson, ReadsTheKeyAndWritesItBack) {
  const Camera c = parseCameraJson("{" + kView + R"(, "vignetting": {"a1": -0.35, "a3": 0.02}})", "v.json").camera;
  EXPECT_EQ(c.lens.effects.vignetting.a1, -0.35);
  EXPECT_EQ(c.lens.effects.vignetting.a2, 0.0);  // missing keys are 0
  EXPECT_EQ(c.lens.effects.vignetting.a3, 0.02);
  EXPECT_FALSE(c.lens.effects.isZero());
  EXPECT_FALSE(c.lens.effects.needsRemap());  // a gain moves no pixel
  const Camera again = parseCameraJson(toCameraJson(c), "again.json").camera;
  EXPECT_EQ(again.lens.effects.vignetting.a1, -0.35);
  EXPECT_EQ(again.lens.effects.vignetting.a2, 0.0);
  EXPECT_EQ(again.lens.effects.vignetting.a3, 0.02);
  // Written only when present.
  EXPECT_FALSE(has(toCameraJson(parseCameraJson("{" + kView + "}", "plain.json").camera), "vignetting"));
}

TEST(VignettingJson, BadValuesGiveOneLineErrorsNamingTheField) {
  for (const auto& [tail, field] : {std::pair{R"("vignetting": {"b1": 0.1})", "vignetting.b1"},
                                    std::pair{R"("vignetting": {"a1": "dark"})", "vignetting.a1"},
                                    std::pair{R"("vignetting": {"a2": 1e999})", "1e999"},
                                    std::pair{R"("vignetting": {"a2": 1e300})", "must stay at most 100"},
                                    std::pair{R"("vignetting": [-0.3, 0, 0])", "vignetting"}}) {
    const std::string m = refusal(tail);
    EXPECT_TRUE(m.starts_with("v.json: ")) << m;
    EXPECT_TRUE(has(m, field)) << tail << " → " << m;
    EXPECT_FALSE(has(m, "\n")) << m;
  }
  const std::string parallel = test::refusalOf([&] {
    parseCameraJson(R"({"projection": "parallel", "far": 10, )" + kView + R"(, "vignetting": {"a1": -0.1}})", "p.json");
  });
  EXPECT_TRUE(has(parallel, "vignetting")) << parallel;
}

// A gain that reaches 0 inside the image is refused, naming the field and where it crosses; the
// same polynomial is accepted on a narrower image that ends before the crossing.
TEST(VignettingJson, AGainReachingZeroInsideTheImageIsRefused) {
  // 1 − 10 r²: 0 at r = 0.316, inside the corner radius 0.361.
  const std::string m = refusal(R"("vignetting": {"a1": -10})");
  EXPECT_TRUE(m.starts_with("v.json: vignetting (a1 = -10")) << m;
  EXPECT_TRUE(has(m, "reaches gain 0 at normalised radius 0.316")) << m;
  EXPECT_TRUE(has(m, "88% of the way")) << m;
  EXPECT_FALSE(has(m, "\n")) << m;
  EXPECT_EQ(refusal(R"("vignetting": {"a1": -7.5})"), "accepted");  // 0 at r = 0.365, past the corner
  EXPECT_LT(0.0, (Vignetting{-7.5, 0, 0}.gain(kCornerR2)));
  // The dipping polynomial, scaled into this image: positive at the corner, negative on the way.
  const double s = 1.0 / kCornerR2;
  const std::string dip = refusal(cat(R"("vignetting": {"a1": )", -2.2 * s, R"(, "a2": )", 1.2 * s * s, "}"));
  EXPECT_TRUE(has(dip, "reaches gain 0")) << dip;
}

Scene oneQuad() {
  Scene scene;
  addUnlitQuad(scene, glm::dmat4(1.0), 1.0, 1.0, glm::vec3(1.0f));
  scene.bounds.max = {1.0, 1.0, 0.0};
  scene.bounds.min = {-1.0, -1.0, -1.0};
  return scene;
}

std::vector<std::string> passNames(const FramePlan& plan) {
  std::vector<std::string> names;
  for (const PlannedPass& p : plan.passes) names.push_back(p.name);
  return names;
}

TEST(VignettingPlan, TheGainIsPlannedLastAndOnlyWhenItIsNotZero) {
  const Scene scene = oneQuad();
  const ImageSize size{120, 80};
  const Camera plain = parseCameraJson("{" + kView + "}", "plain.json").camera;
  const Camera zero =
      parseCameraJson("{" + kView + R"(, "vignetting": {"a1": 0, "a2": 0, "a3": 0}})", "zero.json").camera;
  const FramePlan a = makeFramePlan(scene, plain, size), z = makeFramePlan(scene, zero, size);
  EXPECT_EQ(passNames(z), passNames(a));
  EXPECT_FALSE(z.vignetting);

  const Camera dark = parseCameraJson("{" + kView + R"(, "vignetting": {"a1": -0.5}})", "dark.json").camera;
  // A pinhole, one view asked: the view, then the gain.
  FramePlan p = makeFramePlan(scene, dark, size, PlanOptions{AperturePattern::Sobol, 1, 256, 1});
  EXPECT_TRUE(p.vignetting);
  EXPECT_EQ(passNames(p), (std::vector<std::string>{"scene", "vignetting"}));
  EXPECT_FALSE(p.remap);
  EXPECT_EQ(p.overscan.size.widthPx, size.widthPx);
  // With distortion and an aperture: after the lens pass and the resolve.
  const Camera all = parseCameraJson("{" + kView + R"(, "aperture_radius": 0.05, "distortion": {"k1": -0.1},
                                          "vignetting": {"a1": -0.5}})",
                                     "all.json")
                         .camera;
  // Many views: the resolve multiplies it in (a variant), no pass of its own.
  p = makeFramePlan(scene, all, size, PlanOptions{AperturePattern::Sobol, 16, 16, 1});
  EXPECT_TRUE(p.vignetting);
  EXPECT_EQ(passNames(p), (std::vector<std::string>{"scene", "accumulate", "resolve", "lens"}));
  EXPECT_EQ(p.passes[2].variants, std::vector<std::string>{"vignetting"});
  // Per-tile budgets resolve two streams: the pass of its own again.
  PlanOptions target{AperturePattern::Sobol, 0, 16, 1};
  target.targetPsnrDb = 40.0;
  p = makeFramePlan(scene, all, size, target);
  EXPECT_EQ(passNames(p).back(), "vignetting");
}

}  // namespace
}  // namespace lenslab
