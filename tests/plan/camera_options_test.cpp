// The camera options (plan/CameraOptions.h): sensor and f-number words, picking a glTF camera and
// an animation clip, how the lens and pose options compose with each kind of base camera, and the
// automatic framing (camera/AutoFraming.h) of a scene's bounding sphere (scene/BoundingSphere.h).
// Scenes are built here or written as small glTF files; the corpus's ToyCar, Fox and DamagedHelmet
// are in suite GltfSamples (ctest's entry `corpus`).
#include "../common/animated_gltf.h"
#include "../common/gltf_corpus.h"
#include "../common/temp_dir_test.h"
#include "camera/AutoFraming.h"
#include "camera/Projection.h"
#include "core/Error.h"
#include "core/Text.h"
#include "plan/CameraSelection.h"
#include "plan/CameraOptions.h"
#include "scene/BoundingSphere.h"
#include "scene/GltfLoader.h"
#include "scene/SceneAnimation.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

// Options are written as designated initializers ({.fNumber = "2"}), the rest defaulted, which
// GCC's -Wextra reports member by member.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace lenslab {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;
using test::AnimatedGltf;

constexpr double kPi = 3.14159265358979323846;

// The message of the InputError `f` throws ("" and a failure when it throws none).
template <class F>
std::string refusal(F f) {
  try {
    f();
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    return message;
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// ---- words ----

TEST(CameraWords, SensorNamesAndSizes) {
  EXPECT_EQ(parseSensorMm("full-frame"), glm::dvec2(36, 24));
  EXPECT_EQ(parseSensorMm("aps-c"), glm::dvec2(23.6, 15.6));
  EXPECT_EQ(parseSensorMm("micro-four-thirds"), glm::dvec2(17.3, 13));
  EXPECT_EQ(parseSensorMm("1-inch"), glm::dvec2(13.2, 8.8));
  EXPECT_EQ(parseSensorMm("22.3x14.9"), glm::dvec2(22.3, 14.9));
  EXPECT_EQ(parseSensorMm("6.17X4.55"), glm::dvec2(6.17, 4.55));
  for (const char* bad :
       {"", "36", "36x", "x24", "36x24x2", "0x24", "-36x24", "36x24mm", "APS-C", "nanx24", "infx24"}) {
    const std::string message = refusal([&] { parseSensorMm(bad); });
    EXPECT_TRUE(contains(message, cat("--sensor ", bad, ": give WIDTHxHEIGHT in millimetres"))) << message;
    EXPECT_TRUE(contains(message, "micro-four-thirds (17.3x13)")) << "the names with their sizes: " << message;
  }
}

TEST(CameraWords, FNumbers) {
  EXPECT_EQ(parseFNumber("2.8"), 2.8);
  EXPECT_TRUE(std::isinf(parseFNumber("infinity")));
  EXPECT_TRUE(std::isinf(parseFNumber("pinhole")));
  for (const char* bad : {"0", "-2", "f/2", "two", "", "inf", "nan"})
    EXPECT_TRUE(contains(refusal([&] { parseFNumber(bad); }), cat("--f-number ", bad, ": give a positive number")));
}

// ---- composition with each kind of base ----

SelectedCamera compose(const BaseCamera& base, const CameraOptions& o, double aspect = 0.0) {
  return composeCamera(base, o, aspect);
}

BaseCamera physicalBase(double focusDistance) {
  PhysicalCamera p;
  p.eye = {0, 1, 6};
  p.target = {0, 1, 0};
  p.focusDistance = focusDistance;
  BaseCamera base;
  base.form = CameraForm::Physical;
  base.name = "cam.json";
  base.selected = {toCamera(p, "cam.json"), p};
  return base;
}

TEST(CameraComposition, PhysicalBaseTakesEveryOptionFieldByField) {
  const BaseCamera base = physicalBase(6.0);  // focused on its target
  CameraOptions o;
  EXPECT_EQ(compose(base, o).camera.view.window.height(), base.selected.camera.view.window.height())
      << "no option: the file's camera";

  o.fNumber = "2";
  SelectedCamera c = compose(base, o);
  ASSERT_TRUE(c.physical);
  EXPECT_DOUBLE_EQ(c.camera.lens.apertureRadius, 0.035 / 4.0) << "f / 2N of the file's 35 mm";
  EXPECT_DOUBLE_EQ(c.physical->focalLengthMm, 35.0);
  EXPECT_TRUE(contains(c.camera.source, "cam.json, --f-number 2")) << c.camera.source;

  o.focalLengthMm = 70.0;
  c = compose(base, o);
  EXPECT_DOUBLE_EQ(c.camera.lens.apertureRadius, 0.070 / 4.0);
  // Twice the focal length: half the field of view's tangent (a little less, with the image distance).
  const double before = base.selected.camera.view.window.height() / base.selected.camera.view.prp.z;
  const double after = c.camera.view.window.height() / c.camera.view.prp.z;
  EXPECT_NEAR(after / before, imageDistance(0.035, 6.0) / imageDistance(0.070, 6.0), 1e-12);

  o.sensor = "aps-c";
  c = compose(base, o);
  EXPECT_EQ(c.physical->sensorMm, glm::dvec2(23.6, 15.6));
  EXPECT_NEAR(c.camera.view.window.width() / c.camera.view.window.height(), 23.6 / 15.6, 1e-12);

  // A new target: the base was focused on its target, so the focus follows.
  o.target = glm::dvec3(0, 1, 2);
  c = compose(base, o);
  EXPECT_DOUBLE_EQ(c.physical->focusDistance, 4.0);
  EXPECT_DOUBLE_EQ(c.camera.focusDistance(), 4.0);
  o.eye = glm::dvec3(3, 1, 2);
  c = compose(base, o);
  EXPECT_DOUBLE_EQ(c.physical->focusDistance, 3.0);
  EXPECT_EQ(c.physical->eye, glm::dvec3(3, 1, 2));
}

TEST(CameraComposition, APhysicalBaseFocusedElsewhereKeepsItsFocusWhenMoved) {
  const BaseCamera base = physicalBase(2.5);
  CameraOptions o;
  o.eye = glm::dvec3(0, 1, 10);
  const SelectedCamera c = compose(base, o);
  EXPECT_DOUBLE_EQ(c.physical->focusDistance, 2.5);
}

TEST(CameraComposition, PhysicalChecksNameTheBaseAndTheOptions) {
  const BaseCamera base = physicalBase(0.04);  // 4 cm: beyond 35 mm, not beyond 50 mm
  CameraOptions o;
  o.focalLengthMm = 50.0;
  const std::string message = refusal([&] { compose(base, o); });
  EXPECT_TRUE(
      contains(message, "cam.json with --focal-length 50: focus_distance is 0.04; it must be beyond the focal length"))
      << message;
  o = {};
  o.eye = glm::dvec3(0, 1, 0);  // the target
  EXPECT_TRUE(contains(refusal([&] { compose(physicalBase(6.0), o); }), "eye and target are the same point"));
}

BaseCamera lectureBase(CameraForm form) {
  ViewSpec v;
  v.vrp = {0, 0, 0};
  v.vpn = {0, 0, 1};
  v.prp = {0, 0, 4};
  v.window = {-1.5, -1, 1.5, 1};
  v.nearDistance = 0.01;
  BaseCamera base;
  base.form = form;
  base.name = "lecture.json";
  base.selected.camera = cameraFocusedOnViewPlane(v, 0.0, "lecture.json");
  return base;
}

// The file's lens effects are checked again against the composed lens: a channel's plane of focus
// at 4 cm is a 35 mm lens's, not a 50 mm one's; a pinhole's channel at 1e-200 changes nothing
// until --f-number gives it an aperture.
TEST(CameraComposition, LensEffectsAreCheckedAgainstTheComposedLens) {
  BaseCamera base = physicalBase(6.0);
  base.selected.camera.lens.effects.chromatic.inverseFocusShiftRed = 1.0 / 0.04 - 1.0 / 6.0;
  CameraOptions o;
  o.fNumber = "2";
  EXPECT_NO_THROW(compose(base, o));
  o.focalLengthMm = 50.0;
  const std::string message = refusal([&] { compose(base, o); });
  EXPECT_TRUE(contains(message,
                       "cam.json with --focal-length 50 --f-number 2: chromatic.focus_distance_red is 0.04; it must be "
                       "beyond the focal length (0.05 world units)"))
      << message;
  BaseCamera lecture = lectureBase(CameraForm::Lecture);
  lecture.selected.camera.lens.effects.chromatic.inverseFocusShiftRed = 1e200;
  o = {};
  o.fNumber = "2";
  o.focalLengthMm = 50.0;
  EXPECT_TRUE(contains(refusal([&] { compose(lecture, o); }),
                       "chromatic.focus_distance_red is 1e-200; it must be beyond the focal length"));
}

TEST(CameraComposition, LectureFormTakesAnFNumberWithAFocalLengthOnly) {
  for (const CameraForm form : {CameraForm::Lecture, CameraForm::Intrinsics}) {
    const BaseCamera base = lectureBase(form);
    const std::string formName = form == CameraForm::Lecture ? "the lecture form" : "the OpenCV-intrinsics form";
    CameraOptions o;
    o.fNumber = "2";
    EXPECT_EQ(refusal([&] { compose(base, o); }),
              "--f-number 2: lecture.json is in " + formName +
                  ", which has no focal length: give --focal-length too, or aperture_radius in the file");
    o.focalLengthMm = 50.0;
    const SelectedCamera c = compose(base, o);
    EXPECT_DOUBLE_EQ(c.camera.lens.apertureRadius, 0.050 / 4.0);
    EXPECT_EQ(c.camera.view.window.height(), 2.0) << "the view stays: the lecture form's field of view is its window";
    EXPECT_FALSE(c.physical);

    o.fNumber.clear();
    EXPECT_TRUE(contains(refusal([&] { compose(base, o); }), "--focal-length 50: lecture.json is in " + formName));
    o = {};
    o.sensor = "aps-c";
    EXPECT_TRUE(contains(refusal([&] { compose(base, o); }), "(it has no sensor)"));
    o = {};
    o.target = glm::dvec3(1, 2, 3);
    EXPECT_TRUE(contains(refusal([&] { compose(base, o); }), "--target: lecture.json is in " + formName));
    o = {};
    o.fNumber = "infinity";
    BaseCamera open = base;
    open.selected.camera.lens.apertureRadius = 0.1;
    EXPECT_TRUE(compose(open, o).camera.lens.isPinhole()) << "f/infinity needs no focal length";
  }
}

Scene sceneWithCameras() {
  Scene scene;
  scene.source = "two.gltf";
  scene.bounds.extend({-1, -1, -1});
  scene.bounds.extend({1, 1, 1});
  SceneCamera front;
  front.name = "Lens";
  front.nodeName = "Front";
  front.gltfNode = 3;
  front.yfovRadians = 0.6;
  front.aspectRatio = 1.5;
  front.znear = 0.1;
  front.worldFromCamera = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 5));
  SceneCamera top;
  top.nodeName = "Top";
  top.gltfNode = 4;
  top.perspective = false;
  top.xmag = 2;
  top.ymag = 2;
  top.znear = 0.1;
  top.zfar = 100;
  top.worldFromCamera = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 5, 0)) *
                        glm::rotate(glm::dmat4(1.0), -kPi / 2, glm::dvec3(1, 0, 0));  // looking down −Y
  scene.cameras = {front, top};
  return scene;
}

// The glTF camera's vertical field of view is kept when it becomes a physical lens: the focal
// length is the one that gives yfov at its focus distance on the sensor.
TEST(CameraComposition, AGltfPerspectiveCameraBecomesALensWithItsOwnView) {
  const Scene scene = sceneWithCameras();
  const BaseCamera base = gltfBaseCamera(scene, 0);
  EXPECT_EQ(base.form, CameraForm::GltfPerspective);
  EXPECT_DOUBLE_EQ(base.gltfFocusDistance, 5.0) << "the scene centre's depth";
  const SelectedCamera plain = compose(base, {});
  EXPECT_FALSE(plain.physical) << "no option: drawn as the file has it";
  EXPECT_NEAR(plain.camera.view.window.height() / plain.camera.view.prp.z, 2.0 * std::tan(0.3), 1e-12);

  CameraOptions o;
  o.fNumber = "2";
  for (const char* sensor : {"", "aps-c", "13x26"}) {
    o.sensor = sensor;
    const SelectedCamera c = compose(base, o);
    ASSERT_TRUE(c.physical) << sensor;
    EXPECT_NEAR(c.camera.view.window.height() / c.camera.view.prp.z, 2.0 * std::tan(0.3), 1e-12)
        << "yfov kept, sensor " << sensor;
    const double h = c.physical->sensorMm.y * 1e-3;
    const double zi = h / (2.0 * std::tan(0.3));
    EXPECT_NEAR(c.physical->focalLengthMm * 1e-3, zi * 5.0 / (zi + 5.0), 1e-15);
    EXPECT_DOUBLE_EQ(c.camera.lens.apertureRadius, c.physical->focalLengthMm * 1e-3 / 4.0);
    EXPECT_DOUBLE_EQ(c.camera.focusDistance(), 5.0);
  }
  EXPECT_EQ(compose(base, CameraOptions{.fNumber = "2"}).physical->sensorMm, glm::dvec2(36, 24))
      << "24 mm high at aspect 1.5";

  // The pose replaced: looking from the side, +Y up.
  o = {};
  o.eye = glm::dvec3(4, 0, 0);
  o.target = glm::dvec3(0, 0, 0);
  const SelectedCamera side = compose(base, o);
  EXPECT_EQ(side.physical->eye, glm::dvec3(4, 0, 0));
  EXPECT_DOUBLE_EQ(side.camera.focusDistance(), 4.0);
  EXPECT_GT(projectToWindow(side.camera.view, {0, 1, 0}).y, 0.0) << "+Y is up in the image";
}

TEST(CameraComposition, AGltfOrthographicCameraHasNoLensButCanMove) {
  const Scene scene = sceneWithCameras();
  const BaseCamera base = gltfBaseCamera(scene, 1);
  EXPECT_EQ(base.form, CameraForm::GltfOrthographic);
  for (const auto& [option, o] :
       std::vector<std::pair<std::string, CameraOptions>>{{"--focal-length 50", CameraOptions{.focalLengthMm = 50.0}},
                                                          {"--f-number 2", CameraOptions{.fNumber = "2"}},
                                                          {"--sensor aps-c", CameraOptions{.sensor = "aps-c"}}})
    EXPECT_EQ(refusal([&] {
                compose(base, o);
              }).rfind(option + ": two.gltf: glTF camera [1] node \"Top\" is orthographic", 0),
              0u);
  EXPECT_TRUE(compose(base, CameraOptions{.fNumber = "infinity"}).camera.lens.isPinhole());
  CameraOptions o;
  o.eye = glm::dvec3(0, 0, 6);
  o.target = glm::dvec3(0, 0, 0);
  const SelectedCamera c = compose(base, o);
  EXPECT_EQ(c.camera.view.projection, Projection::Parallel);
  EXPECT_NEAR(glm::length(c.camera.view.vpn - glm::dvec3(0, 0, 1)), 0.0, 1e-12) << "looking down −Z from +Z";
  EXPECT_DOUBLE_EQ(c.camera.view.window.height(), 4.0) << "its ymag kept";
}

// ---- picking a camera and a clip ----

TEST(CameraSelectionWords, CameraNodeByIndexNodeNameOrCameraName) {
  Scene scene = sceneWithCameras();
  EXPECT_EQ(findSceneCamera(scene, "0"), 0u);
  EXPECT_EQ(findSceneCamera(scene, "1"), 1u);
  EXPECT_EQ(findSceneCamera(scene, "Top"), 1u);
  EXPECT_EQ(findSceneCamera(scene, "Front"), 0u);
  EXPECT_EQ(findSceneCamera(scene, "Lens"), 0u) << "a camera's own name";
  EXPECT_EQ(refusal([&] { findSceneCamera(scene, "Side"); }),
            "--camera-node Side: no camera of two.gltf has that node or camera name; it has [0] node \"Front\" (camera "
            "\"Lens\"), "
            "[1] node \"Top\"");
  EXPECT_TRUE(
      contains(refusal([&] { findSceneCamera(scene, "2"); }), "--camera-node 2: two.gltf has 2 camera(s): [0]"));
  scene.cameras[1].nodeName = "Front";
  EXPECT_TRUE(contains(refusal([&] { findSceneCamera(scene, "Front"); }),
                       "2 cameras of two.gltf have that node name; give an index"));
  scene.cameras.clear();
  EXPECT_TRUE(contains(refusal([&] { findSceneCamera(scene, "0"); }), "--camera-node 0: two.gltf has no cameras"));
}

TEST(CameraSelectionWords, BaseCameraOrderIsFileThenColmapThenNodeThenFirstCameraThenFraming) {
  Scene scene = sceneWithCameras();
  CameraOptions none, top;
  top.cameraNode = "Top";
  EXPECT_EQ(baseCamera(scene, std::nullopt, none).gltfIndex, 0u);
  EXPECT_EQ(baseCamera(scene, std::nullopt, top).gltfIndex, 1u);
  EXPECT_TRUE(contains(refusal([&] { baseCamera(scene, fs::path("cam.json"), top); }),
                       "--camera-node Top: --camera cam.json gives the camera already; give one or the other"));
  // A COLMAP image names a camera too: beside a file or a node, and half given, it is refused
  // before any file is read.
  CameraOptions colmap;
  colmap.colmapDir = "model";
  colmap.colmapImage = "a.png";
  EXPECT_TRUE(contains(refusal([&] { baseCamera(scene, fs::path("cam.json"), colmap); }),
                       "--colmap model and --camera cam.json both give the camera; give one"));
  colmap.cameraNode = "Top";
  EXPECT_TRUE(contains(refusal([&] { baseCamera(scene, std::nullopt, colmap); }),
                       "--camera-node Top: --colmap model gives the camera already"));
  CameraOptions dirOnly;
  dirOnly.colmapDir = "model";
  EXPECT_TRUE(
      contains(refusal([&] { baseCamera(scene, std::nullopt, dirOnly); }), "--colmap model: give --image NAME too"));
  CameraOptions imageOnly;
  imageOnly.colmapImage = "a.png";
  EXPECT_TRUE(
      contains(refusal([&] { baseCamera(scene, std::nullopt, imageOnly); }), "--image a.png: give --colmap DIR too"));
  scene.cameras.clear();
  EXPECT_EQ(baseCamera(scene, std::nullopt, none).form, CameraForm::AutomaticFraming);
}

class CameraFiles : public test::TempDirTest {};

// Two cameras and two clips written as glTF: names and node indices survive the loader; each clip
// poses the scene its own way, and all together the later one wins.
TEST_F(CameraFiles, TwoCamerasAndTwoClipsFromAFile) {
  AnimatedGltf g;
  g.gltf["cameras"] = {{{"type", "perspective"}, {"name", "Wide"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}},
                       {{"type", "perspective"}, {"name", "Tele"}, {"perspective", {{"yfov", 0.2}, {"znear", 0.1}}}}};
  const int box = g.node({{"mesh", g.triangle()}, {"name", "box"}});
  g.node({{"camera", 0}, {"name", "Near"}, {"translation", {0, 0, 3}}});
  g.node({{"camera", 1}, {"name", "Far"}, {"translation", {0, 0, 9}}});
  g.channel(box, "translation", "LINEAR", {0, 1}, {0, 0, 0, 2, 0, 0}, 0);
  g.channel(box, "translation", "LINEAR", {0, 2}, {0, 0, 0, 0, 5, 0}, 1);
  g.gltf["animations"][0]["name"] = "slide";
  g.gltf["animations"][1]["name"] = "lift";
  Scene scene = loadGltf(g.write(dir_ / "two.gltf"));
  ASSERT_EQ(scene.cameras.size(), 2u);
  EXPECT_EQ(findSceneCamera(scene, "Far"), 1u);
  EXPECT_EQ(findSceneCamera(scene, "Tele"), 1u);
  EXPECT_EQ(scene.cameras[1].gltfNode, 2);
  EXPECT_EQ(sceneCameraLabel(scene, 1), "[1] node \"Far\" (camera \"Tele\")");
  const SelectedCamera near = chooseCamera(scene, std::nullopt, {.cameraNode = "Near"}, 1.0);
  const SelectedCamera far = chooseCamera(scene, std::nullopt, {.cameraNode = "1"}, 1.0);
  EXPECT_NEAR(prpWorld(near.camera.view).z, 3.0, 1e-12);
  EXPECT_NEAR(prpWorld(far.camera.view).z, 9.0, 1e-12);

  const auto xyAt = [&](const std::string& clip, double seconds) {
    selectAnimation(scene, clip);
    poseScene(scene, seconds);
    return glm::dvec2(scene.instances[0].worldFromModel[3]);
  };
  EXPECT_EQ(xyAt("", 1.0), glm::dvec2(2, 0)) << "default: the first clip";
  EXPECT_EQ(xyAt("lift", 1.0), glm::dvec2(0, 2.5));
  EXPECT_EQ(xyAt("0", 1.0), glm::dvec2(2, 0));
  EXPECT_EQ(xyAt("all", 1.0), glm::dvec2(0, 2.5)) << "the later clip's channel on the same node and path wins";
  EXPECT_DOUBLE_EQ(animationDurationSeconds(scene), 2.0);
  EXPECT_EQ(refusal([&] { selectAnimation(scene, "jump"); }),
            "--animation jump: no animation of " + scene.source +
                " has that name; it has [0] \"slide\", [1] \"lift\", or all");
  EXPECT_TRUE(contains(refusal([&] { selectAnimation(scene, "2"); }), "has 2 animation(s): [0] \"slide\""));
  Scene still;
  still.source = "still.gltf";
  EXPECT_EQ(refusal([&] { selectAnimation(still, "0"); }), "--animation 0: still.gltf has no animations");
}

TEST(CameraWarnings, FocusOnAPinholeSaysItChangesNothing) {
  const Camera pinhole = lectureBase(CameraForm::Lecture).selected.camera;
  LensOptions lens;
  EXPECT_TRUE(focusWarnings(pinhole, lens).empty());
  lens.focusDistance = "3";
  lens.focusAt = glm::dvec2(10, 20);
  const std::vector<std::string> w = focusWarnings(pinhole, lens);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_TRUE(contains(
      w[0], "--focus-distance 3: the camera has no aperture (a pinhole), so focus changes nothing; give --f-number"))
      << w[0];
  EXPECT_TRUE(contains(w[1], "--focus-at 10,20: ")) << w[1];
  Camera lens35 = pinhole;
  lens35.lens.apertureRadius = 0.01;
  EXPECT_TRUE(focusWarnings(lens35, lens).empty());
}

// ---- the bounding sphere ----

TEST(BoundingSphere, KnownSmallestSpheres) {
  const auto expectSphere = [](const std::vector<glm::dvec3>& points, glm::dvec3 center, double radius,
                               const char* what) {
    const BoundingSphere s = smallestEnclosingSphere(points);
    EXPECT_NEAR(s.radius, radius, 1e-9 * std::max(1.0, radius)) << what;
    EXPECT_NEAR(glm::length(s.center - center), 0.0, 1e-6 * std::max(1.0, radius)) << what;
    for (const glm::dvec3& p : points) EXPECT_LE(glm::length(p - s.center), s.radius * (1 + 1e-12)) << what;
  };
  expectSphere({{1, 2, 3}}, {1, 2, 3}, 0.0, "one point");
  expectSphere({{0, 0, 0}, {2, 0, 0}, {1, 0.5, 0}}, {1, 0, 0}, 1.0, "two points and one inside their ball");
  const double h = std::sqrt(3.0) / 2.0;
  expectSphere({{0, 0, 0}, {1, 0, 0}, {0.5, h, 0}}, {0.5, h / 3.0, 0}, 1.0 / std::sqrt(3.0), "equilateral triangle");
  std::vector<glm::dvec3> cube;
  for (int i = 0; i < 8; ++i) cube.push_back({i & 1 ? 3.0 : 1.0, i & 2 ? 3.0 : 1.0, i & 4 ? 3.0 : 1.0});
  expectSphere(cube, {2, 2, 2}, std::sqrt(3.0), "cube corners");
  // A regular tetrahedron (alternate cube corners): circumradius √3 for edge 2√2.
  expectSphere({{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}, {0, 0, 0}, std::sqrt(3.0), "tetrahedron");
  // Random points on the unit sphere about (5, -3, 2), with 10,000 inside it, at two scales.
  for (const double scale : {1e-6, 1e6}) {
    std::mt19937 random(7);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> uniform(0.0, 0.99);
    std::vector<glm::dvec3> points;
    for (int i = 0; i < 10000; ++i) {
      const glm::dvec3 d = glm::normalize(glm::dvec3(normal(random), normal(random), normal(random)));
      points.push_back(scale * (glm::dvec3(5, -3, 2) + (i % 5 == 0 ? 1.0 : uniform(random)) * d));
    }
    // The smallest sphere of points on a sphere's surface that cover it is that sphere, to within
    // how well 2000 points cover it (their largest cap: a few hundredths of a radian).
    const BoundingSphere s = smallestEnclosingSphere(points);
    EXPECT_NEAR(s.radius / scale, 1.0, 2e-3) << scale;
    EXPECT_LE(s.radius / scale, 1.0 + 1e-9) << "never larger than a sphere that holds them all";
    for (const glm::dvec3& p : points) ASSERT_LE(glm::length(p - s.center), s.radius * (1 + 1e-12));
  }
  EXPECT_TRUE(smallestEnclosingSphere({}).empty());
}

// A latitude-longitude sphere mesh of `radius` about `center`, placed as one instance.
Scene sphereScene(glm::dvec3 center, double radius) {
  Scene scene;
  scene.source = "sphere";
  Mesh mesh;
  const int rings = 48, segments = 96;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double theta = kPi * i / rings, phi = 2.0 * kPi * j / segments;
      Vertex v;
      v.position = glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      mesh.vertices.push_back(v);
    }
  mesh.indices = {0, 1, 2};
  scene.meshes.push_back(mesh);
  Instance instance;
  instance.mesh = 0;
  instance.worldFromModel = glm::scale(glm::translate(glm::dmat4(1.0), center), glm::dvec3(radius));
  scene.instances.push_back(instance);
  scene.bounds = computeBounds(scene);
  return scene;
}

struct Extent {
  double maxAbsX = 0.0, maxAbsY = 0.0;
  glm::dvec2 topVertex{0.0};  // ndc of the vertex highest in the world
};

Extent ndcExtent(const Scene& scene, const Camera& camera) {
  Extent e;
  double highest = -1e300;
  for (const Vertex& v : scene.meshes[0].vertices) {
    const glm::dvec3 p(scene.instances[0].worldFromModel * glm::dvec4(glm::dvec3(v.position), 1.0));
    const glm::dvec2 ndc = ndcFromWindow(camera.view.window, projectToWindow(camera.view, p));
    e.maxAbsX = std::max(e.maxAbsX, std::abs(ndc.x));
    e.maxAbsY = std::max(e.maxAbsY, std::abs(ndc.y));
    if (p.y > highest) {
      highest = p.y;
      e.topVertex = ndc;
    }
  }
  return e;
}

// The sphere's silhouette spans 1/1.02 of the smaller side (the margin): its ndc extent on that
// side is tan(asin(r/D)) / tan(asin(1.02·r/D)), about 0.98, and never beyond 1.
TEST(AutomaticFraming, TheSubjectTouchesTheFramesNearerEdgesUpright) {
  for (const double radius : {1.0, 3e5, 0.02, 0.0005}) {
    const Scene scene = sphereScene({3 * radius, 2 * radius, -radius}, radius);
    for (const char* sensor : {"36x24", "24x36"}) {
      const SelectedCamera c = composeCamera(framingBaseCamera(scene), CameraOptions{.sensor = sensor}, 0.0);
      validate(c.camera.view, "framing");
      const Extent e = ndcExtent(scene, c.camera);
      const bool landscape = std::string(sensor) == "36x24";
      const double nearer = landscape ? e.maxAbsY : e.maxAbsX, other = landscape ? e.maxAbsX : e.maxAbsY;
      const std::string what = cat("radius ", radius, ", sensor ", sensor, ": ", c.camera.source);
      EXPECT_GT(nearer, 0.96) << what;
      EXPECT_LT(nearer, 0.99) << what;
      EXPECT_LT(other, nearer) << what;
      EXPECT_GT(e.topVertex.y, 0.9 * nearer * (landscape ? 1.0 : 24.0 / 36.0))
          << "upright: the top of the sphere at the top; " << what;
      EXPECT_NEAR(e.topVertex.x, 0.0, 1e-6) << what;
      if (c.physical) {
        EXPECT_NEAR(c.camera.focusDistance(), glm::length(c.physical->eye - glm::dvec3(3, 2, -1) * radius),
                    1e-9 * radius)
            << "focused on the centre; " << what;
      }
    }
  }
}

TEST(AutomaticFraming, ACloseUpStaysALensAndBeyondLifeSizeIsAPinhole) {
  const SelectedCamera closeUp = composeCamera(framingBaseCamera(sphereScene({0, 0, 0}, 0.02)), {}, 0.0);
  ASSERT_TRUE(closeUp.physical) << closeUp.camera.source;
  EXPECT_GT(closeUp.physical->focusDistance, 2.0 * 0.035);
  EXPECT_TRUE(contains(closeUp.camera.source, "a close-up at magnification")) << closeUp.camera.source;
  const SelectedCamera tiny = composeCamera(framingBaseCamera(sphereScene({0, 0, 0}, 0.0005)), {}, 0.0);
  EXPECT_FALSE(tiny.physical);
  EXPECT_TRUE(tiny.camera.lens.isPinhole());
  EXPECT_TRUE(contains(tiny.camera.source, "would need a 35 mm on 36x24 mm lens at magnification"))
      << tiny.camera.source;
  EXPECT_TRUE(contains(tiny.camera.source, "beyond life size (1), so a pinhole")) << tiny.camera.source;
  EXPECT_TRUE(contains(refusal([&] {
                         composeCamera(framingBaseCamera(sphereScene({0, 0, 0}, 0.0005)), {.fNumber = "2"}, 0.0);
                       }),
                       "--f-number 2: automatic framing: the scene"));
  // A sensor smaller than the sphere frames it at less than life size.
  EXPECT_TRUE(
      composeCamera(framingBaseCamera(sphereScene({0, 0, 0}, 0.0005)), {.fNumber = "2", .sensor = "0.5x0.5"}, 0.0)
          .physical);
}

TEST(AutomaticFraming, TheFramingDistanceSolvesTheThinLensFit) {
  for (const auto& [r, f, s] : std::vector<std::array<double, 3>>{
           {1, 0.035, 0.024}, {1e-3, 0.035, 0.024}, {1e6, 0.2, 0.036}, {0.05, 0.05, 0.0088}}) {
    const double d = framingDistance(r, f, s);
    EXPECT_GT(d, std::max(r, f));
    const double fits = r / std::sqrt(d * d - r * r), view = s * (d - f) / (2.0 * f * d);
    EXPECT_NEAR(fits / view, 1.0, 1e-9) << r << " " << f << " " << s;
  }
}

TEST(AutomaticFraming, EyeAndTargetPlaceItWithTheGivenLens) {
  const Scene scene = sphereScene({0, 1, 0}, 1.0);
  const BaseCamera base = framingBaseCamera(scene);
  EXPECT_NEAR(base.subject.radius, 1.0, 1e-6);
  SelectedCamera c = composeCamera(base, {.eye = glm::dvec3(0, 1, 10)}, 0.0);
  EXPECT_EQ(c.physical->target, glm::dvec3(0, 1, 0)) << "--eye alone looks at the sphere's centre";
  EXPECT_DOUBLE_EQ(c.camera.focusDistance(), 10.0);
  c = composeCamera(base, {.focalLengthMm = 85.0, .target = glm::dvec3(5, 0, 0)}, 0.0);
  EXPECT_EQ(c.physical->target, glm::dvec3(5, 0, 0));
  EXPECT_DOUBLE_EQ(c.physical->focalLengthMm, 85.0);
  const SelectedCamera wide = composeCamera(base, {.focalLengthMm = 24.0}, 0.0);
  const SelectedCamera tele = composeCamera(base, {.focalLengthMm = 85.0}, 0.0);
  EXPECT_GT(tele.camera.focusDistance(), 3.0 * wide.camera.focusDistance()) << "a longer lens frames from further back";
  EXPECT_NEAR(ndcExtent(scene, tele.camera).maxAbsY, ndcExtent(scene, wide.camera).maxAbsY, 0.01)
      << "the same size in the frame";
}

// ---- the corpus (suite GltfSamples: ctest's entry `corpus`) ----

using test::samplesDirectory;

TEST(GltfSamples, ToyCarsEightCamerasArePickedByNameAndIndex) {
  const fs::path file = samplesDirectory() / "ToyCar/glTF/ToyCar.gltf";
  SKIP_UNLESS_EXISTS(file);
  const Scene scene = loadGltf(file);
  ASSERT_EQ(scene.cameras.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(findSceneCamera(scene, cat("Camera00", i + 1)), i);
  const SelectedCamera a = chooseCamera(scene, std::nullopt, {.cameraNode = "Camera002"}, 0.0);
  const SelectedCamera b = chooseCamera(scene, std::nullopt, {.cameraNode = "1"}, 0.0);
  const SelectedCamera c = chooseCamera(scene, std::nullopt, {.cameraNode = "Camera005"}, 0.0);
  EXPECT_EQ(prpWorld(a.camera.view), prpWorld(b.camera.view));
  EXPECT_GT(glm::length(prpWorld(a.camera.view) - prpWorld(c.camera.view)), 0.01);
}

TEST(GltfSamples, FoxsThreeClipsAreListedAndPicked) {
  const fs::path file = samplesDirectory() / "Fox/glTF-Binary/Fox.glb";
  SKIP_UNLESS_EXISTS(file);
  Scene scene = loadGltf(file);
  ASSERT_EQ(scene.animation.clips.size(), 3u);
  EXPECT_EQ(scene.animation.clips[0].name, "Survey");
  EXPECT_EQ(scene.animation.clips[1].name, "Walk");
  EXPECT_EQ(scene.animation.clips[2].name, "Run");
  selectAnimation(scene, "Run");
  EXPECT_EQ(scene.animation.playing, 2);
  EXPECT_NEAR(animationDurationSeconds(scene), 1.158, 1e-3);
  selectAnimation(scene, "Survey");
  EXPECT_NEAR(animationDurationSeconds(scene), 3.417, 1e-3);
}

// Framed by its bounding sphere the helmet fills at least 85 % of the frame's height (88.8 %; its
// box's circumsphere, 1.39 times the radius, would leave it 62 % of the height).
TEST(GltfSamples, DamagedHelmetFillsTheFrame) {
  const fs::path file = samplesDirectory() / "DamagedHelmet/glTF-Binary/DamagedHelmet.glb";
  SKIP_UNLESS_EXISTS(file);
  const Scene scene = loadGltf(file);
  const SelectedCamera c = chooseCamera(scene, std::nullopt, {}, 0.0);
  double top = -1.0, bottom = 1.0;
  for (const Instance& instance : scene.instances)
    for (const Vertex& v : scene.meshes[static_cast<std::size_t>(instance.mesh)].vertices) {
      const glm::dvec3 p(instance.worldFromModel * glm::dvec4(glm::dvec3(v.position), 1.0));
      const double y = ndcFromWindow(c.camera.view.window, projectToWindow(c.camera.view, p)).y;
      top = std::max(top, y);
      bottom = std::min(bottom, y);
    }
  EXPECT_GT(top - bottom, 2.0 * 0.85) << c.camera.source;
  EXPECT_LT(top, 1.0);
  EXPECT_GT(bottom, -1.0);
}

}  // namespace
}  // namespace lenslab
