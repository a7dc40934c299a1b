// The interactive view's model (no window, no GL): an invalid edit goes back to the last valid
// camera and says why; the sample budget follows the measured cost; every change restarts the
// accumulation; the outside view's orbit camera keeps the lecture camera in sight.
#include "view_fixtures.h"
#include "camera/PhysicalCamera.h"
#include "camera/Projection.h"
#include "core/Error.h"
#include "scene/ProceduralScenes.h"
#include "view/ViewerModel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <sstream>

namespace lenslab::view {
namespace {

using test::rowsDof;

// Three boxes at different depths, so that the auto sample count has something to blur.
Scene boxes() {
  return markerScene({{{0.0, 0.5, -2.0}, 0.3, {1.0f, 0.2f, 0.2f}},
                      {{0.8, 0.5, -4.0}, 0.3, {0.2f, 1.0f, 0.2f}},
                      {{-0.8, 0.5, 0.0}, 0.3, {0.2f, 0.2f, 1.0f}}});
}

struct Fixture {
  Scene scene = boxes();
  std::ostringstream log;
  ViewerModel model{scene, fromPhysical(rowsDof(), "test"), ImageSize{160, 107}, PlanOptions{}, 16.0, log};
  Fixture() { model.restart(); }
};

void expectSameCamera(const Camera& a, const Camera& b) {
  EXPECT_EQ(a.view.vrp, b.view.vrp);
  EXPECT_EQ(a.view.vpn, b.view.vpn);
  EXPECT_EQ(a.view.vup, b.view.vup);
  EXPECT_EQ(a.view.prp, b.view.prp);
  EXPECT_DOUBLE_EQ(a.lens.apertureRadius, b.lens.apertureRadius);
}

TEST(ViewerModel, AnInvalidEditRollsBackToTheLastValidCameraAndSaysWhy) {
  Fixture f;
  ASSERT_TRUE(f.model.error().empty()) << f.model.error();
  const EditableCamera valid = f.model.camera();
  ASSERT_TRUE(valid.physical);

  // VUP along VPN: no view-up direction is left. Taken as typed; the restart finds it invalid.
  Camera c = valid.camera;
  c.view.vup = c.view.vpn;
  f.model.editLecture(c);
  EXPECT_FALSE(f.model.camera().physical) << "a lecture-form edit drops the physical form";
  ASSERT_TRUE(f.model.needsRestart());
  f.model.restart();
  expectSameCamera(f.model.camera().camera, valid.camera);
  EXPECT_TRUE(f.model.camera().physical) << "the last valid camera comes back whole, physical form included";
  EXPECT_NE(f.model.error().find("the panel's camera"), std::string::npos) << f.model.error();
  EXPECT_NE(f.log.str().find("lenslab: error: " + f.model.error()), std::string::npos) << f.log.str();
  EXPECT_FALSE(f.model.needsRestart());

  // A negative aperture radius is no lens either.
  c = valid.camera;
  c.lens.apertureRadius = -0.01;
  f.model.editLecture(c);
  f.model.restart();
  expectSameCamera(f.model.camera().camera, valid.camera);
  EXPECT_NE(f.model.error().find("aperture radius"), std::string::npos) << f.model.error();

  // A valid edit is kept and clears the error.
  c = valid.camera;
  c.lens.apertureRadius = 0.5 * valid.camera.lens.apertureRadius;
  f.model.editLecture(c);
  f.model.restart();
  EXPECT_DOUBLE_EQ(f.model.camera().camera.lens.apertureRadius, c.lens.apertureRadius);
  EXPECT_TRUE(f.model.error().empty()) << f.model.error();
}

TEST(ViewerModel, EditsCheckedOnTheSpotAreRefusedWithoutARestart) {
  Fixture f;
  const Camera before = f.model.camera().camera;
  f.model.refocus(-1.0);
  EXPECT_NE(f.model.error().find("focus distance"), std::string::npos) << f.model.error();
  LensEffects effects;
  effects.distortion.k1 = std::numeric_limits<double>::quiet_NaN();
  f.model.editLensEffects(effects);
  EXPECT_NE(f.model.error().find("finite"), std::string::npos) << f.model.error();
  EXPECT_FALSE(f.model.needsRestart());
  expectSameCamera(f.model.camera().camera, before);
  EXPECT_TRUE(f.model.camera().camera.lens.effects.isZero());

  // A click on the background: nothing to focus on, said in the click's words.
  const DepthAtPixel nothing = [](const Camera&, ImageSize, int, int) {
    return std::numeric_limits<double>::infinity();
  };
  EXPECT_FALSE(f.model.clickAt({10.0, 10.0}, nothing));
  EXPECT_EQ(f.model.error().rfind("click at image pixel", 0), 0u) << f.model.error();
  EXPECT_FALSE(f.model.needsRestart());
  EXPECT_THROW(f.model.focusAt({10.0, 10.0}, nothing, "--click"), InputError) << "a scripted focus fails the run";
  try {
    f.model.focusAt({10.0, 10.0}, nothing, "--click");
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--click 10,10: nothing", 0), 0u) << "names the option given: " << e.what();
  }
}

TEST(ViewerModel, TakesDistortionAndLateralColourWithTheLensBarrel) {
  Scene scene = boxes();
  std::ostringstream log;
  EditableCamera camera = fromPhysical(rowsDof(), "test");
  camera.camera.lens.barrel = LensBarrel{0.04, 0.02};
  ViewerModel model{scene, camera, ImageSize{160, 107}, PlanOptions{}, 16.0, log};
  model.restart();
  ASSERT_TRUE(model.error().empty()) << model.error();
  LensEffects effects;
  effects.distortion.k1 = -0.2;
  effects.chromatic.lateralRed = 0.004;
  effects.chromatic.lateralBlue = -0.004;
  model.editLensEffects(effects);
  EXPECT_TRUE(model.error().empty()) << model.error();
  model.restart();
  EXPECT_TRUE(model.error().empty()) << model.error();
  EXPECT_DOUBLE_EQ(model.camera().camera.lens.effects.distortion.k1, -0.2);
  EXPECT_DOUBLE_EQ(model.camera().camera.lens.effects.chromatic.lateralRed, 0.004);
  EXPECT_EQ(model.camera().camera.lens.barrel, (LensBarrel{0.04, 0.02})) << "the barrel stays with the lens effects";
}

TEST(SampleBudget, FollowsTheMeasuredCostAndTheTimeBudgetAndNeverDropsBelowOne) {
  SampleBudget budget(16.0);
  EXPECT_EQ(budget.samplesForFrame(100), 1) << "nothing measured: one sample tells the cost";
  budget.measured(1, 2.0, false);
  EXPECT_EQ(budget.samplesForFrame(100), 8) << "16 ms at 2 ms a sample";
  budget.measured(8, 32.0, false);
  EXPECT_EQ(budget.samplesForFrame(100), 4) << "the last frame's cost, 4 ms a sample";
  budget.measured(4, 400.0, false);
  EXPECT_EQ(budget.samplesForFrame(100), 1) << "over budget for a single sample: still one";
  EXPECT_DOUBLE_EQ(budget.accumulationMs(), 434.0);
  budget.measured(1, 1e-12, false);
  EXPECT_EQ(budget.samplesForFrame(100), 100) << "nearly free samples: all that remain, no overflow";
  EXPECT_EQ(budget.samplesForFrame(3), 3);
  EXPECT_EQ(budget.samplesForFrame(0), 0) << "converged: no work";
  EXPECT_LT(budget.convergedAfterMs(), 0.0);
  budget.measured(3, 1.0, true);
  EXPECT_GE(budget.convergedAfterMs(), 0.0);

  SampleBudget none(0.0);  // --frame-budget-ms 0: one sample a frame, whatever the cost
  none.measured(1, 5.0, false);
  EXPECT_EQ(none.samplesForFrame(100), 1);
}

TEST(ViewerModel, EveryChangeRestartsTheAccumulation) {
  Fixture f;
  f.model.budget().measured(2, 8.0, true);
  const DepthAtPixel atThree = [](const Camera&, ImageSize, int, int) { return 3.0; };
  ASSERT_TRUE(f.model.camera().physical);
  const PhysicalCamera lens = *f.model.camera().physical;  // "lecture edit" drops the physical form
  const std::vector<std::pair<const char*, std::function<void(ViewerModel&)>>> changes = {
      {"orbit", [](ViewerModel& m) { m.orbit(0.1, -0.05); }},
      {"look around", [](ViewerModel& m) { m.lookAround(-0.1, 0.05); }},
      {"fly",
       [](ViewerModel& m) {
         m.fly({1.0, 0.0, 1.0}, 0.016, true);
       }},
      {"wheel", [](ViewerModel& m) { m.moveForward(2.0); }},
      {"lecture edit", [](ViewerModel& m) { m.editLecture(m.camera().camera); }},
      {"refocus", [](ViewerModel& m) { m.refocus(2.5); }},
      {"physical edit", [&](ViewerModel& m) { m.editPhysical(lens); }},
      {"lens effects",
       [](ViewerModel& m) {
         LensEffects e;
         e.distortion.k1 = -0.05;
         m.editLensEffects(e);
       }},
      {"plan options",
       [](ViewerModel& m) {
         PlanOptions o = m.planOptions();
         o.apertureSamples = 5;
         m.setPlanOptions(o);
       }},
      {"click",
       [&](ViewerModel& m) {
         ASSERT_TRUE(m.clickAt({80.0, 50.0}, atThree));
       }},
  };
  for (const auto& [name, change] : changes) {
    ASSERT_FALSE(f.model.needsRestart()) << name;
    change(f.model);
    EXPECT_TRUE(f.model.needsRestart()) << name;
    f.model.restart();
    EXPECT_TRUE(f.model.error().empty()) << name << ": " << f.model.error();
    EXPECT_EQ(f.model.budget().accumulationMs(), 0.0) << name;
    EXPECT_LT(f.model.budget().convergedAfterMs(), 0.0) << name;
    EXPECT_DOUBLE_EQ(f.model.budget().msPerSample(), 4.0) << name << ": the cost stays as the next estimate";
  }
  // What the changes did reached the camera and the plan.
  EXPECT_EQ(f.model.plan().apertureSamples, 5);
  EXPECT_DOUBLE_EQ(f.model.camera().camera.lens.effects.distortion.k1, -0.05);
  EXPECT_NEAR(f.model.camera().camera.view.prp.z, 3.0, 1e-9) << "the click focused at the depth under it";
  ASSERT_TRUE(f.model.lastFocusDistance());
  EXPECT_NEAR(*f.model.lastFocusDistance(), 3.0, 1e-9);
  ASSERT_TRUE(f.model.camera().physical);
  EXPECT_NEAR(f.model.camera().physical->focusDistance, 3.0, 1e-9);
}

// Inside the view volume of `camera`: in front of it and within the clip rectangle.
bool sees(const Camera& camera, const glm::dvec3& world) {
  const glm::dvec4 clip = clipFromWorld(camera.view) * glm::dvec4(world, 1.0);
  return clip.w > 0.0 && std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w;
}

TEST(OutsideOrbit, KeepsSeeingTheCameraWhereverBothGo) {
  Fixture f;
  std::vector<EditableCamera> lectureCameras = {f.model.camera()};
  lectureCameras.push_back(orbited(lectureCameras[0], 2.0, 0.6));
  lectureCameras.push_back(flown(lectureCameras[0], {30.0, -5.0, 100.0}));
  PhysicalCamera wide = rowsDof();
  wide.focalLengthMm = 14.0;
  wide.focusDistance = 40.0;
  lectureCameras.push_back(fromPhysical(wide, "wide, far focus"));
  for (const EditableCamera& lecture : lectureCameras) {
    const Camera& c = lecture.camera;
    const ViewSpec& s = c.view;
    const ViewBasis b = viewBasis(s);
    std::vector<glm::dvec3> points = {prpWorld(s), focusPivotWorld(c)};
    for (const double u : {s.window.umin, s.window.umax})
      for (const double v : {s.window.vmin, s.window.vmax}) points.push_back(s.vrp + u * b.u + v * b.v);
    for (const double zoomSteps : {0.0, -20.0}) {  // as it starts, and zoomed far out
      for (int i = 0; i < 12; ++i) {
        OutsideOrbit orbit;
        orbit.zoomBy(zoomSteps);
        orbit.orbit(i * std::numbers::pi / 6.0, (i % 5 - 2) * 0.9);  // past the poles: clamped
        EXPECT_LE(std::abs(orbit.elevationRadians), 1.5);
        const Camera outside = orbit.cameraFor(c, 1.5);
        for (std::size_t k = 0; k < points.size(); ++k)
          EXPECT_TRUE(sees(outside, points[k])) << c.source << ", orbit step " << i << ", zoom steps " << zoomSteps
                                                << ": point " << k << " (PRP, pivot, window corners) out of sight";
      }
    }
  }
}

TEST(ViewerModel, TheDiagramEnlargesTheApertureOnlyWhenAsked) {
  Fixture f;
  EXPECT_GT(f.model.diagramApertureScale(), 1.0);
  f.model.setEnlargeAperture(false);
  EXPECT_EQ(f.model.diagramApertureScale(), 1.0);
  EXPECT_FALSE(f.model.needsRestart()) << "a drawing choice: the accumulation goes on";
  EXPECT_FALSE(f.model.diagram({}, 0).empty());
}

}  // namespace
}  // namespace lenslab::view
