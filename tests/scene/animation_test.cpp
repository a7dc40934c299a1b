// glTF node animation (scene/SceneAnimation, read by scene/gltf/Animations): small files written
// here with answers computed by hand in the comments, and the corpus's AnimatedTriangle (suite
// GltfSamples, which ctest runs as the entry `corpus`).
#include "../common/animated_gltf.h"
#include "../common/gltf_corpus.h"
#include "../common/temp_dir_test.h"
#include "core/Error.h"
#include "scene/GltfLoader.h"
#include "scene/SceneAnimation.h"

#include <OpenImageIO/strutil.h>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace lenslab {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;
using test::AnimatedGltf;

const double kHalfSqrt2 = std::sqrt(0.5);

void expectNear(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance, const std::string& what) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << what << ", component " << i;
}

glm::dvec3 origin(const glm::dmat4& worldFromModel) { return glm::dvec3(worldFromModel[3]); }

bool mentions(const Scene& scene, const std::string& words) {
  for (const std::string& note : scene.notes)
    if (note.find(words) != std::string::npos) return true;
  return false;
}

class AnimationFile : public test::TempDirTest {
 protected:
  Scene load(const AnimatedGltf& file) { return loadGltf(file.write(dir_ / "animated.gltf")); }
};

// ---- interpolation ----

TEST_F(AnimationFile, StepHoldsEachValueAndSwitchesExactlyAtItsKey) {
  AnimatedGltf g;
  const int node = g.node({{"mesh", g.triangle()}});
  g.channel(node, "translation", "STEP", {0, 1, 2}, {0, 0, 0, 5, 0, 0, 9, 0, 0});
  Scene scene = load(g);
  const std::pair<double, double> cases[] = {{0.0, 0.0}, {0.999, 0.0}, {1.0, 5.0},
                                             {1.5, 5.0}, {1.999, 5.0}, {2.0, 9.0}};
  for (const auto& [seconds, x] : cases) {
    poseScene(scene, seconds);
    EXPECT_EQ(origin(scene.instances[0].worldFromModel), glm::dvec3(x, 0, 0)) << "at " << seconds << " s";
  }
}

TEST_F(AnimationFile, LinearTranslationIsMidwayAtMidTime) {
  AnimatedGltf g;
  const int node = g.node({{"mesh", g.triangle()}});
  g.channel(node, "translation", "LINEAR", {1, 3}, {0, 0, 0, 4, -2, 6});
  Scene scene = load(g);
  poseScene(scene, 2.0);  // u = (2 - 1) / (3 - 1) = 0.5
  expectNear(origin(scene.instances[0].worldFromModel), {2, -1, 3}, 1e-12, "at 2 s");
  poseScene(scene, 2.5);  // u = 0.75
  expectNear(origin(scene.instances[0].worldFromModel), {3, -1.5, 4.5}, 1e-12, "at 2.5 s");
}

// Identity and 90 degrees about Z (quaternion x, y, z, w = 0, 0, sin 45, cos 45): half way is 45
// degrees, so the model's x axis goes to (cos 45, sin 45, 0) and its y axis to (-sin 45, cos 45, 0).
TEST_F(AnimationFile, LinearRotationIsASlerp) {
  AnimatedGltf g;
  const int node = g.node({{"mesh", g.triangle()}});
  const auto s = static_cast<float>(kHalfSqrt2);
  g.channel(node, "rotation", "LINEAR", {0, 1}, {0, 0, 0, 1, 0, 0, s, s});
  Scene scene = load(g);
  poseScene(scene, 0.5);
  expectNear(glm::dvec3(scene.instances[0].worldFromModel[0]), {kHalfSqrt2, kHalfSqrt2, 0}, 1e-12, "x axis");
  expectNear(glm::dvec3(scene.instances[0].worldFromModel[1]), {-kHalfSqrt2, kHalfSqrt2, 0}, 1e-12, "y axis");
  // At u = 1/3 a slerp turns 30 degrees; a normalised lerp, (0, 0, s/3, 2/3 + s/3), would turn 29.3.
  poseScene(scene, 1.0 / 3.0);
  const double angle = std::atan2(scene.instances[0].worldFromModel[0].y, scene.instances[0].worldFromModel[0].x);
  EXPECT_NEAR(glm::degrees(angle), 30.0, 1e-9);
}

// The same rotation written as -q (q and -q are one rotation): the short way is still 45 degrees,
// where interpolating towards -q the long way would turn -135 degrees.
TEST_F(AnimationFile, LinearRotationTakesTheShortWay) {
  AnimatedGltf g;
  const int node = g.node({{"mesh", g.triangle()}});
  const auto s = static_cast<float>(kHalfSqrt2);
  g.channel(node, "rotation", "LINEAR", {0, 1}, {0, 0, 0, 1, 0, 0, -s, -s});
  Scene scene = load(g);
  poseScene(scene, 0.5);
  expectNear(glm::dvec3(scene.instances[0].worldFromModel[0]), {kHalfSqrt2, kHalfSqrt2, 0}, 1e-12, "x axis");
}

// Keys at 1 s and 3 s (interval 2 s); x: key 0 value p0 = 1, out-tangent b0 = 2; key 1 in-tangent
// a1 = -1, value p1 = 3. The spec's tangents are m0 = 2 s * b0 = 4 and m1 = 2 s * a1 = -2.
// At 1.5 s, u = 0.25:  h00 = 2u³ - 3u² + 1 = 0.84375   h10 = u³ - 2u² + u = 0.140625
//                      h01 = -2u³ + 3u² = 0.15625      h11 = u³ - u² = -0.046875
// x = 0.84375 * 1 + 0.140625 * 4 + 0.15625 * 3 + (-0.046875) * (-2) = 1.96875
// (unscaled tangents would give 1.640625). y: p0 = 0, b0 = 1 (m0 = 2), a1 = 0, p1 = 0:
// y = 0.140625 * 2 = 0.28125. The in-tangent of the first key and the out-tangent of the last
// (here 100) are never used.
TEST_F(AnimationFile, CubicSplineTranslationFollowsTheHermiteFormulaWithScaledTangents) {
  AnimatedGltf g;
  const int node = g.node({{"mesh", g.triangle()}});
  g.channel(node, "translation", "CUBICSPLINE", {1, 3},
            {100, 100, 100, /**/ 1, 0, 0, /**/ 2, 1, 0,     // key 0: in-tangent, value, out-tangent
             -1, 0, 0, /**/ 3, 0, 0, /**/ 100, 100, 100});  // key 1
  Scene scene = load(g);
  poseScene(scene, 1.5);
  expectNear(origin(scene.instances[0].worldFromModel), {1.96875, 0.28125, 0}, 1e-12, "at 1.5 s");
  poseScene(scene, 3.0);
  expectNear(origin(scene.instances[0].worldFromModel), {3, 0, 0}, 1e-12, "at the last key: its value, not a tangent");
}

// Zero tangents between identity and 90 degrees about Z: at u = 0.5 the Hermite weights are 0.5
// and 0.5, so the quaternion is (0, 0, s/2, (1 + s)/2) with s = sin 45, which normalised is 45 degrees.
TEST_F(AnimationFile, CubicSplineRotationIsNormalised) {
  AnimatedGltf g;
  const int node = g.node({{"mesh", g.triangle()}});
  const auto s = static_cast<float>(kHalfSqrt2);
  g.channel(node, "rotation", "CUBICSPLINE", {0, 1},
            {0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, /**/ 0, 0, 0, 0, 0, 0, s, s, 0, 0, 0, 0});
  Scene scene = load(g);
  poseScene(scene, 0.5);
  const glm::dmat4& m = scene.instances[0].worldFromModel;
  expectNear(glm::dvec3(m[0]), {std::cos(glm::radians(45.0)), std::sin(glm::radians(45.0)), 0}, 1e-7, "x axis");
  EXPECT_NEAR(glm::length(glm::dvec3(m[0])), 1.0, 1e-12) << "a rotation, not a scale";
}

TEST_F(AnimationFile, TimesOutsideTheKeysClampToTheFirstAndLastValue) {
  AnimatedGltf g;
  const int linear = g.node({{"mesh", g.triangle()}, {"translation", {7, 7, 7}}});
  const int cubic = g.node({{"mesh", g.triangle()}});
  g.channel(linear, "translation", "LINEAR", {1, 2}, {1, 0, 0, 3, 0, 0});
  g.channel(cubic, "scale", "CUBICSPLINE", {1, 2}, {9, 9, 9, 2, 2, 2, 9, 9, 9, /**/ 9, 9, 9, 4, 4, 4, 9, 9, 9});
  Scene scene = load(g);
  expectNear(origin(scene.instances[0].worldFromModel), {7, 7, 7}, 0, "at rest the node's own translation");
  poseScene(scene, 0.0);
  expectNear(origin(scene.instances[0].worldFromModel), {1, 0, 0}, 0, "before the first key");
  EXPECT_EQ(scene.instances[1].worldFromModel[0].x, 2.0) << "before the first key: its value, not its in-tangent";
  poseScene(scene, 60.0);
  expectNear(origin(scene.instances[0].worldFromModel), {3, 0, 0}, 0, "after the last key");
  EXPECT_EQ(scene.instances[1].worldFromModel[0].x, 4.0) << "after the last key: its value, not its out-tangent";
}

// ---- the hierarchy ----

// Parent: rest rotation 90 degrees about Z, translation animated from (0,0,0) to (10,0,0). Child:
// translation (0,1,0), scale 2, the triangle. At 0.5 s the vertex (1,0,0) goes: scale (2,0,0),
// child translation (2,1,0), parent rotation (-1,2,0), parent translation (4,2,0).
TEST_F(AnimationFile, ChildFollowsItsAnimatedParentAndKeepsItsRestParts) {
  AnimatedGltf g;
  const int parent = g.node({{"rotation", {0, 0, kHalfSqrt2, kHalfSqrt2}}});
  g.node({{"mesh", g.triangle()}, {"translation", {0, 1, 0}}, {"scale", {2, 2, 2}}}, parent);
  g.channel(parent, "translation", "LINEAR", {0, 1}, {0, 0, 0, 10, 0, 0});
  Scene scene = load(g);
  poseScene(scene, 0.5);
  const glm::dmat4& worldFromModel = scene.instances[0].worldFromModel;
  expectNear(glm::dvec3(worldFromModel * glm::dvec4(1, 0, 0, 1)), {4, 2, 0}, 1e-6, "vertex (1,0,0)");
  expectNear(origin(worldFromModel), {4, 0, 0}, 1e-6, "the child's origin");
}

TEST_F(AnimationFile, CameraOnAnAnimatedNodeMoves) {
  AnimatedGltf g;
  g.gltf["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}};
  g.node({{"mesh", g.triangle()}});
  const int rig = g.node({{"translation", {0, 0, 5}}});
  g.node({{"camera", 0}}, rig);
  g.channel(rig, "translation", "LINEAR", {0, 2}, {0, 0, 5, 0, 0, 9});
  Scene scene = load(g);
  ASSERT_EQ(scene.cameras.size(), 1u);
  expectNear(origin(scene.cameras[0].worldFromCamera), {0, 0, 5}, 0, "at rest");
  poseScene(scene, 1.0);
  expectNear(origin(scene.cameras[0].worldFromCamera), {0, 0, 7}, 1e-12, "at 1 s");
  expectNear(origin(scene.instances[0].worldFromModel), {0, 0, 0}, 0, "the still triangle stays");
}

TEST_F(AnimationFile, BoundsFollowThePose) {
  AnimatedGltf g;
  const int node = g.node({{"mesh", g.triangle()}});
  g.channel(node, "translation", "LINEAR", {0, 1}, {0, 0, 0, 10, 0, -4});
  Scene scene = load(g);
  poseScene(scene, 1.0);
  expectNear(scene.bounds.min, {10, 0, -4}, 0, "min");
  expectNear(scene.bounds.max, {11, 1, -4}, 0, "max");
}

// ---- what the loader keeps and notes ----

TEST_F(AnimationFile, EachAnimationIsAClipAndTheFirstPlaysByDefault) {
  AnimatedGltf g;
  const int a = g.node({{"mesh", g.triangle()}});
  const int b = g.node({{"mesh", g.triangle()}});
  g.channel(a, "translation", "LINEAR", {0, 2}, {0, 0, 0, 1, 0, 0}, 0);
  g.channel(b, "scale", "STEP", {0.5, 3.5}, {1, 1, 1, 2, 2, 2}, 1);
  g.gltf["animations"][1]["name"] = "grow";
  Scene scene = load(g);
  ASSERT_EQ(scene.animation.clips.size(), 2u);
  EXPECT_EQ(scene.animation.clips[0].name, "");
  EXPECT_EQ(scene.animation.clips[1].name, "grow");
  EXPECT_EQ(scene.animation.clips[1].fileChannelCount, 1u);
  EXPECT_EQ(scene.animation.playing, 0);
  EXPECT_DOUBLE_EQ(animationDurationSeconds(scene), 2.0) << "the first clip's";
  EXPECT_TRUE(
      mentions(scene, "2 animation(s) (`lenslab info` lists them): `render --time` and `capture` play the first"))
      << testing::PrintToString(scene.notes);
  poseScene(scene, 3.6);  // clip 0 only: a at its last value, b at rest although clip 1 has passed its last key
  expectNear(origin(scene.instances[0].worldFromModel), {1, 0, 0}, 0, "clip 0 moves a");
  EXPECT_EQ(scene.instances[1].worldFromModel[0].x, 1.0) << "clip 1 does not play";

  scene.animation.playing = 1;
  EXPECT_DOUBLE_EQ(animationDurationSeconds(scene), 3.5);
  poseScene(scene, 3.6);
  expectNear(origin(scene.instances[0].worldFromModel), {0, 0, 0}, 0, "clip 0 no longer plays: a at rest");
  EXPECT_EQ(scene.instances[1].worldFromModel[0].x, 2.0) << "clip 1 scales b";

  scene.animation.playing = kAllClips;
  EXPECT_DOUBLE_EQ(animationDurationSeconds(scene), 3.5) << "the longest clip's, on one clock";
  poseScene(scene, 3.0);  // both play: a at its last value, b still at its first
  expectNear(origin(scene.instances[0].worldFromModel), {1, 0, 0}, 0, "animation 0");
  EXPECT_EQ(scene.instances[1].worldFromModel[0].x, 1.0) << "animation 1";
}

TEST_F(AnimationFile, AStillSceneHasNoDurationAndPosingLeavesIt) {
  AnimatedGltf g;
  g.node({{"mesh", g.triangle()}, {"translation", {1, 2, 3}}});
  Scene scene = load(g);
  EXPECT_TRUE(scene.animation.empty());
  EXPECT_TRUE(scene.animation.nodes.empty()) << "no copy of the hierarchy is kept for a still scene";
  EXPECT_EQ(animationDurationSeconds(scene), 0.0);
  poseScene(scene, 1.0);
  expectNear(origin(scene.instances[0].worldFromModel), {1, 2, 3}, 0, "untouched");
}

// Two clips moving the same node (a walk and a run move the same bones): each plays alone; all
// together, the later one wins, as glTF viewers that play every clip at once do.
TEST_F(AnimationFile, ClipsOnTheSameNodeAndPathPlayAloneOrTheLaterWins) {
  AnimatedGltf g;
  const int node = g.node({{"mesh", g.triangle()}});
  g.channel(node, "translation", "LINEAR", {0, 1}, {0, 0, 0, 1, 0, 0}, 0);
  g.channel(node, "translation", "LINEAR", {0, 1}, {0, 0, 0, 0, 8, 0}, 1);
  Scene scene = load(g);
  ASSERT_EQ(scene.animation.clips.size(), 2u);
  EXPECT_FALSE(mentions(scene, "drives too")) << "channels in different clips are no conflict";
  poseScene(scene, 1.0);
  expectNear(origin(scene.instances[0].worldFromModel), {1, 0, 0}, 0, "the first clip");
  scene.animation.playing = 1;
  poseScene(scene, 1.0);
  expectNear(origin(scene.instances[0].worldFromModel), {0, 8, 0}, 0, "the second clip");
  scene.animation.playing = kAllClips;
  poseScene(scene, 1.0);
  expectNear(origin(scene.instances[0].worldFromModel), {0, 8, 0}, 0, "all: the later channel");
}

TEST_F(AnimationFile, ALaterChannelOnTheSameNodeAndPathInOneClipWinsWithANote) {
  AnimatedGltf g;
  const int node = g.node({{"mesh", g.triangle()}});
  g.channel(node, "translation", "LINEAR", {0, 1}, {0, 0, 0, 1, 0, 0}, 0);
  g.channel(node, "translation", "LINEAR", {0, 1}, {0, 0, 0, 0, 8, 0}, 0);
  Scene scene = load(g);
  ASSERT_EQ(scene.animation.clips.size(), 1u);
  EXPECT_EQ(scene.animation.clips[0].channels.size(), 1u);
  EXPECT_EQ(scene.animation.clips[0].fileChannelCount, 2u);
  EXPECT_TRUE(mentions(scene,
                       "animation 0 channel 1 drives the translation of node 0 that an earlier channel of the same "
                       "animation drives too"))
      << testing::PrintToString(scene.notes);
  poseScene(scene, 1.0);
  expectNear(origin(scene.instances[0].worldFromModel), {0, 8, 0}, 0, "the later channel");
}

// A first clip that moves nothing drawn (morph weights only) leaves the scene still until another
// is chosen; the hierarchy is kept for it.
TEST_F(AnimationFile, AFirstClipThatMovesNothingLeavesTheSceneStillUntilAnotherPlays) {
  AnimatedGltf g;
  const int node = g.node({{"mesh", g.triangle()}});
  const int weighted = g.node(json::object());
  g.channel(weighted, "translation", "LINEAR", {0, 1}, {0, 0, 0, 1, 0, 0}, 0);
  g.gltf["animations"][0]["channels"][0]["target"]["path"] = "weights";
  g.channel(node, "translation", "LINEAR", {0, 1}, {0, 0, 0, 5, 0, 0}, 1);
  Scene scene = load(g);
  EXPECT_TRUE(scene.animation.empty()) << "clip 0 plays and moves nothing";
  EXPECT_FALSE(scene.animation.nodes.empty());
  poseScene(scene, 1.0);
  expectNear(origin(scene.instances[0].worldFromModel), {0, 0, 0}, 0, "still");
  scene.animation.playing = 1;
  EXPECT_FALSE(scene.animation.empty());
  poseScene(scene, 1.0);
  expectNear(origin(scene.instances[0].worldFromModel), {5, 0, 0}, 0, "clip 1");
}

TEST_F(AnimationFile, MorphWeightChannelsAreNotPlayedAndNoted) {
  AnimatedGltf g;
  g.node({{"mesh", g.triangle()}});
  const int weighted = g.node(json::object());
  g.channel(weighted, "translation", "LINEAR", {0, 1}, {0, 0, 0, 1, 0, 0});
  g.gltf["animations"][0]["channels"][0]["target"]["path"] = "weights";
  Scene scene = load(g);
  EXPECT_TRUE(scene.animation.empty());
  EXPECT_TRUE(mentions(scene, "1 animation channel(s) drive morph target weights: not played"))
      << testing::PrintToString(scene.notes);
  EXPECT_TRUE(mentions(scene, "none of which moves a drawn node")) << testing::PrintToString(scene.notes);
}

// KHR_lights_punctual lights hang on nodes like meshes and cameras: a spot on a child of a moving,
// turning parent is where the parent puts it and shines along the child's −Z turned with it.
TEST_F(AnimationFile, ALightFollowsItsNodeAndItsParent) {
  AnimatedGltf g;
  g.gltf["extensionsUsed"] = {"KHR_lights_punctual"};
  g.gltf["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "spot"}, {"intensity", 10.0}, {"spot", json::object()}}, {{"type", "point"}, {"intensity", 5.0}}};
  const int parent = g.node({{"mesh", g.triangle()}});
  g.node({{"translation", {0, 0, 2}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}, parent);
  g.node({{"translation", {4, 0, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});  // not animated
  const auto s = static_cast<float>(kHalfSqrt2);
  g.channel(parent, "translation", "LINEAR", {0, 1}, {0, 0, 0, 10, 0, 0});
  g.channel(parent, "rotation", "LINEAR", {0, 1}, {0, 0, 0, 1, 0, s, 0, s});  // to 90 degrees about +Y
  Scene scene = load(g);
  ASSERT_EQ(scene.lights.size(), 2u);
  expectNear(scene.lights[0].worldPosition, {0, 0, 2}, 1e-12, "spot at rest");
  expectNear(scene.lights[0].worldDirection, {0, 0, -1}, 1e-12, "spot's direction at rest");
  poseScene(scene, 1.0);
  // 90 degrees about +Y takes +Z to +X and −Z to −X: the child's (0, 0, 2) lands at 10 + 2 along x.
  expectNear(scene.lights[0].worldPosition, {12, 0, 0}, 1e-9, "spot posed");
  expectNear(scene.lights[0].worldDirection, {-1, 0, 0}, 1e-9, "spot's direction posed");
  expectNear(scene.lights[1].worldPosition, {4, 0, 0}, 1e-12, "the still point light");
  poseScene(scene, 0.0);
  expectNear(scene.lights[0].worldPosition, {0, 0, 2}, 1e-12, "spot back at rest");
}

TEST_F(AnimationFile, ALightWhoseNodeIsScaledToNothingIsRefusedNamingNodeAndTime) {
  AnimatedGltf g;
  g.gltf["extensionsUsed"] = {"KHR_lights_punctual"};
  g.gltf["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "directional"}}};
  g.node({{"mesh", g.triangle()}});
  const int sun = g.node({{"name", "sun"}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  g.channel(sun, "scale", "LINEAR", {0, 1}, {1, 1, 1, 0, 0, 0});
  Scene scene = load(g);
  poseScene(scene, 0.5);
  EXPECT_NEAR(glm::length(scene.lights[0].worldDirection), 1.0, 1e-12);
  try {
    poseScene(scene, 1.0);
    FAIL() << "a directional light with no direction was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("node 1 (sun)"), std::string::npos) << message;
    EXPECT_NE(message.find("at 1 s"), std::string::npos) << message;
    EXPECT_NE(message.find("no direction"), std::string::npos) << message;
  }
}

TEST_F(AnimationFile, KeyTimesThatDoNotIncreaseAreRefused) {
  AnimatedGltf g;
  const int node = g.node({{"mesh", g.triangle()}});
  g.channel(node, "translation", "LINEAR", {0, 1, 1}, {0, 0, 0, 1, 0, 0, 2, 0, 0});
  const fs::path file = g.write(dir_ / "repeated.gltf");
  try {
    loadGltf(file);
    FAIL() << "loaded key times 0, 1, 1";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              file.string() + ": animation 0 channel 0: key times must strictly increase (1 s then 1 s at key 2)");
  }
}

// ---- poses lenslab cannot draw ----

std::string messageOf(Scene& scene, double seconds) {
  try {
    poseScene(scene, seconds);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST_F(AnimationFile, APoseBeyondTheLargestWorldCoordinateIsRefusedNamingFileNodeAndTime) {
  AnimatedGltf g;
  const int node = g.node({{"mesh", g.triangle()}, {"name", "rocket"}});
  g.channel(node, "translation", "LINEAR", {0, 1}, {0, 0, 0, 4e15f, 0, 0});
  Scene scene = load(g);
  EXPECT_EQ(messageOf(scene, 0.1), "") << "4e14 is within reach";
  const std::string message = messageOf(scene, 0.5);
  EXPECT_EQ(
      message.rfind(scene.source + ": at 0.5 s the animation moves node 0 (rocket) so that a vertex lies at (", 0), 0u)
      << message;
  EXPECT_NE(message.find("beyond +-1e+15"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// Eight nested nodes scaled by 1e38 each hold a camera at 1e304 (finite, no vertex to refuse);
// the root's scale animated from 1 to 1e38 takes it past the largest double.
TEST_F(AnimationFile, ANonFiniteTransformIsRefusedNamingFileNodeAndTime) {
  AnimatedGltf g;
  g.gltf["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}};
  g.node({{"mesh", g.triangle()}});
  const int root = g.node(json::object());
  int parent = root;
  for (int i = 0; i < 8; ++i) parent = g.node({{"scale", {1e38, 1e38, 1e38}}}, parent);
  g.node({{"camera", 0}}, parent);
  g.channel(root, "scale", "STEP", {0, 1}, {1, 1, 1, 1e38f, 1e38f, 1e38f});
  Scene scene = load(g);
  EXPECT_EQ(messageOf(scene, 0.5), "") << "the rest scale holds until 1 s";
  const std::string message = messageOf(scene, 1.0);
  EXPECT_EQ(message.rfind(scene.source + ": at 1 s the animation gives node ", 0), 0u) << message;
  EXPECT_NE(message.find("a world transform that is not finite"), std::string::npos) << message;
}

// ---- the corpus's AnimatedTriangle (suite GltfSamples: ctest's entry `corpus`) ----

// The file: one LINEAR rotation channel, keys at 0, 0.25, 0.5, 0.75, 1 s with quaternions (x, y, z, w)
// (0,0,0,1), (0,0,.707,.707), (0,0,1,0), (0,0,.707,-.707), (0,0,0,1): 0, 90, 180, 270, 360 degrees
// about Z. At 0.125 s (u = 0.5 between the first two) the slerp is half way: 45 degrees.
// At 0.875 s the last two are 90 degrees apart only the short way (their dot is -.707): 315 degrees.
TEST(GltfSamples, AnimatedTriangleTurnsAboutZBySlerp) {
  const fs::path file = test::samplesDirectory() / "AnimatedTriangle/glTF/AnimatedTriangle.gltf";
  SKIP_UNLESS_EXISTS(file);
  Scene scene = loadGltf(file);
  ASSERT_EQ(scene.instances.size(), 1u);
  EXPECT_DOUBLE_EQ(animationDurationSeconds(scene), 1.0);
  EXPECT_EQ(scene.instances[0].worldFromModel, glm::dmat4(1.0)) << "loadGltf returns the rest pose";
  const std::pair<double, double> cases[] = {{0.125, 45.0}, {0.25, 90.0}, {0.625, 225.0}, {0.875, 315.0}};
  for (const auto& [seconds, degrees] : cases) {
    poseScene(scene, seconds);
    const glm::dmat4 expected = glm::rotate(glm::dmat4(1.0), glm::radians(degrees), glm::dvec3(0, 0, 1));
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        EXPECT_NEAR(scene.instances[0].worldFromModel[c][r], expected[c][r], 1e-12)
            << "at " << seconds << " s, column " << c << " row " << r;
  }
  // The triangle (0,0,0), (1,0,0), (0,1,0) turned 45 degrees spans x from -sin 45 to cos 45.
  poseScene(scene, 0.125);
  EXPECT_NEAR(scene.bounds.min.x, -kHalfSqrt2, 1e-12);
  EXPECT_NEAR(scene.bounds.max.x, kHalfSqrt2, 1e-12);
}

}  // namespace
}  // namespace lenslab
