// Focus held as an inverse distance: a huge finite focus tends smoothly to infinity focus (no view
// plane at 1e300), parallel cameras focus off their view plane, and the command line's
// --focus-distance takes the same validation path as a camera file's focus_distance.
#include "../common/refusal.h"
#include "camera/Camera.h"
#include "camera/PhysicalCamera.h"
#include "camera/Projection.h"
#include "core/Error.h"
#include "io/CameraJson.h"
#include "lens/AperturePattern.h"
#include "plan/UserOptions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace lenslab {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

PhysicalCamera lens(double focus) {
  PhysicalCamera p;
  p.eye = {0, 1, 5};
  p.target = {0, 1, 0};
  p.fNumber = 1.4;
  p.focusDistance = focus;
  return p;
}

// Where a world point lands in NDC through each aperture sample (the window moves, the image not).
std::vector<glm::dvec2> landings(const Camera& camera, glm::dvec3 point) {
  std::vector<glm::dvec2> out;
  for (const LensSample& s : makeApertureSamples(AperturePattern::Concentric, 16, 1)) {
    const ViewSpec v = viewThroughLens(camera, s.lens * camera.lens.apertureRadius, {0, 0});
    out.push_back(ndcFromWindow(v.window, projectToWindow(v, point)));
  }
  return out;
}

TEST(FocusAsInverseDistance, HugePhysicalFocusTendsToInfinity) {
  const Camera atInfinity = toCamera(lens(kInf), "inf");
  const glm::dvec3 point(0.3, 1.2, -3.0);
  const std::vector<glm::dvec2> expected = landings(atInfinity, point);
  for (const double focus : {1e15, 1e20, 1e300, std::numeric_limits<double>::max()}) {
    const Camera c = toCamera(lens(focus), "far");
    // The view plane stays at a sane distance; the window is finite and the same as infinity's
    // to the relative size of 1/z_f.
    EXPECT_DOUBLE_EQ(c.view.prp.z, 5.0) << focus;
    EXPECT_NEAR(c.view.window.width(), atInfinity.view.window.width(), 1e-12) << focus;
    const std::vector<glm::dvec2> got = landings(c, point);
    for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(glm::length(got[i] - expected[i]), 0.0, 1e-12) << focus;
  }
}

TEST(FocusAsInverseDistance, RefocusFarAwayKeepsTheViewPlane) {
  const Camera c = toCamera(lens(5.0), "near");
  for (const double focus : {1e4, 1e15, 1e300}) {
    const Camera far = refocused(c, focus, "test");
    EXPECT_DOUBLE_EQ(far.view.prp.z, 5.0);
    EXPECT_DOUBLE_EQ(far.focusDistance(), focus);
    EXPECT_TRUE(std::isfinite(far.view.window.width()));
    // Circles of confusion stay finite, tending to the infinity-focus value 2R·d/z.
    const double radius = c.lens.apertureRadius;
    EXPECT_NEAR(cocDiameterOnWindow(far, 2.0), 2.0 * radius * 5.0 / 2.0, 2.0 * radius * 5.0 / focus * 1.001 + 1e-15);
  }
  // Within kMaxViewPlaneMove the view plane moves to the plane of focus, as it always did.
  EXPECT_DOUBLE_EQ(refocused(c, 50.0, "test").view.prp.z, 50.0);
  EXPECT_FALSE(refocused(c, 50.0, "test").inverseFocusOffPlane);
}

TEST(FocusAsInverseDistance, ParallelLensFocusesOffItsViewPlane) {
  Camera c;
  c.view.projection = Projection::Parallel;
  c.view.vrp = {0, 0, 0};
  c.view.vpn = {0, 0, 1};
  c.view.prp = {0, 0, 4};
  c.view.window = {-1, -1, 1, 1};
  c.view.nearDistance = 0.0;
  c.view.farDistance = 100.0;
  c.lens.apertureRadius = 0.2;
  const Camera focused = refocused(c, 5000.0, "test");  // beyond kMaxViewPlaneMove × 4
  ASSERT_TRUE(focused.inverseFocusOffPlane);
  // A point on the plane of focus (depth 5000 from the PRP) lands on one window point from every
  // aperture point; its circle of confusion is zero there and 2R·|1 − z/z_f| elsewhere.
  const std::vector<glm::dvec2> at = landings(focused, {0.3, -0.2, 4.0 - 5000.0});
  for (const glm::dvec2& p : at) EXPECT_NEAR(glm::length(p - at.front()), 0.0, 1e-9);
  EXPECT_NEAR(cocDiameterOnWindow(focused, 5000.0), 0.0, 1e-12);
  EXPECT_NEAR(cocDiameterOnWindow(focused, 2500.0), 0.2, 1e-12);
  // On the view plane (no off-plane focus) the old formula 2R·|z − d|/d holds.
  EXPECT_NEAR(cocDiameterOnWindow(c, 6.0), 2.0 * 0.2 * 2.0 / 4.0, 1e-12);
}

TEST(FocusAsInverseDistance, LectureFileTakesANumericFocusAndRoundTrips) {
  const std::string text = R"({"vrp": [0, 0, 0], "vpn": [0, 0, 1], "prp": [0, 0, 2], "window": [-1, -1, 1, 1],
                              "aperture_radius": 0.05, "focus_distance": 1e300})";
  const CameraFile file = parseCameraJson(text, "far.json");
  EXPECT_DOUBLE_EQ(file.camera.focusDistance(), 1e300);
  EXPECT_DOUBLE_EQ(file.camera.view.prp.z, 2.0);
  const CameraFile again = parseCameraJson(toCameraJson(file.camera), "again.json");
  EXPECT_DOUBLE_EQ(again.camera.focusDistance(), 1e300);
  // A nearer focus moves the view plane, as refocusing does.
  const std::string near = R"({"vrp": [0, 0, 0], "vpn": [0, 0, 1], "prp": [0, 0, 2], "window": [-1, -1, 1, 1],
                              "aperture_radius": 0.05, "focus_distance": 3})";
  EXPECT_DOUBLE_EQ(parseCameraJson(near, "near.json").camera.view.prp.z, 3.0);
}

TEST(FocusAsInverseDistance, CommandLineAndFileShareOneValidationPath) {
  // A 35 mm lens cannot focus at 0.035 m (no real image): the file refuses it...
  const std::string text = R"({"eye": [0, 1, 5], "target": [0, 1, 0], "f_number": 2, "focus_distance": 0.035})";
  EXPECT_THROW(parseCameraJson(text, "f.json"), InputError);
  // ...and so does --focus-distance on the same camera given without it.
  const std::string good = R"({"eye": [0, 1, 5], "target": [0, 1, 0], "f_number": 2})";
  const CameraFile file = parseCameraJson(good, "g.json");
  const SelectedCamera selected{file.camera, file.physical};
  LensOptions o;
  o.focusDistance = "0.035";
  try {
    applyLensOptions(selected, o);
    FAIL() << "--focus-distance 0.035 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("focal length"), std::string::npos) << e.what();
  }
  // A valid refocus of a physical camera changes its field of view as a real lens's z_i does.
  o.focusDistance = "0.5";
  const SelectedCamera r = applyLensOptions(selected, o);
  ASSERT_TRUE(r.physical);
  EXPECT_DOUBLE_EQ(r.physical->focusDistance, 0.5);
  EXPECT_LT(verticalFovRadians(*r.physical), verticalFovRadians(*file.physical));
}

// No lens in air is faster than f/0.5 (its aperture radius reaches its focal length), and a lens
// focused at d has a focal length below d: f-numbers below 0.5 and a lecture camera's aperture at or
// beyond its focus distance are refused in one line naming the field (they rendered an empty frame).
TEST(FocusAsInverseDistance, ApertureBeyondWhatALensCanHaveIsRefused) {
  const auto message = [](const std::string& text) {
    return test::refusalOf([&] { parseCameraJson(text, "a.json"); });
  };
  EXPECT_NE(message(R"({"eye": [0, 1, 5], "target": [0, 1, 0], "f_number": 1e-320})").find("f_number is"),
            std::string::npos);
  EXPECT_NE(message(R"({"eye": [0, 1, 5], "target": [0, 1, 0], "f_number": 0.49})").find("faster than f/0.5"),
            std::string::npos);
  EXPECT_EQ(message(R"({"eye": [0, 1, 5], "target": [0, 1, 0], "f_number": 0.5})"), "accepted");
  const std::string lecture = R"({"vrp": [0, 0, 0], "vpn": [0, 0, 1], "prp": [0, 0, 2], "window": [-1, -1, 1, 1], )";
  EXPECT_NE(message(lecture + R"("aperture_radius": 1e300, "focus_distance": 5})").find("aperture_radius"),
            std::string::npos);
  EXPECT_NE(message(lecture + R"("aperture_radius": 2})").find("give a radius below 2"), std::string::npos);
  EXPECT_EQ(message(lecture + R"("aperture_radius": 1.9})"), "accepted");
  EXPECT_EQ(message(lecture + R"("aperture_radius": 1e300, "focus_distance": "infinity"})"), "accepted");
}

}  // namespace
}  // namespace lenslab
