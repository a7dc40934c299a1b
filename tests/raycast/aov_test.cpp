// The normal, albedo and instance AOVs (`--aov normal,albedo,instance`) against closed forms: a
// tilted plane's normal in camera space, built here from the physical camera's look-at frame (not
// from lenslab's view basis); the back of a double-sided plane turned to the viewer, as it is
// shaded; the glTF node indices of two triangles over the pixels whose centre rays meet them,
// found here by intersecting those rays with the triangles; the base colour factor as the albedo.
#include "../common/animated_gltf.h"
#include "../common/looking_at.h"
#include "../common/temp_dir_test.h"
#include "camera/PhysicalCamera.h"
#include "core/Error.h"
#include "raycast/RayCaster.h"
#include "scene/GltfLoader.h"
#include "scene/ProceduralScenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace lenslab {
namespace {
using test::Frame;
using test::frameOf;
using test::lookingAt;
using test::pixelDirection;

// A double-sided unlit quad 200 × 200 through `point` with unit normal `normal` (its front side).
Scene planeScene(const glm::dvec3& point, const glm::dvec3& normal) {
  Scene scene;
  scene.source = "plane";
  const glm::dvec3 x = glm::normalize(glm::cross(glm::dvec3(0.0, 1.0, 0.0), normal));
  const glm::dvec3 y = glm::cross(normal, x);
  addUnlitQuad(scene,
               glm::dmat4(glm::dvec4(x, 0.0), glm::dvec4(y, 0.0), glm::dvec4(normal, 0.0), glm::dvec4(point, 1.0)),
               100.0, 100.0, {0.5f, 0.5f, 0.5f});
  return scene;
}

constexpr int kWidth = 96;

// The largest difference of a component of the normal AOV from `expected` (camera space), over
// every pixel; all pixels must see the plane.
double worstNormalError(const AovImages& aovs, const glm::dvec3& expected) {
  double worst = 0.0;
  for (std::size_t i = 0; i < aovs.normal.size(); ++i)
    worst = std::max(worst, std::abs(aovs.normal[i] - expected[static_cast<int>(i % 3)]));
  return worst;
}

AovSelection all() {
  AovSelection s;
  s.depth = s.normal = s.albedo = s.instance = true;
  return s;
}

TEST(NormalAov, TiltedPlaneFromAnOffAxisCameraIsTheAnalyticNormalInCameraSpace) {
  const PhysicalCamera c = lookingAt({0.4, -0.2, 1.0}, {0.1, 0.3, -5.0});
  const glm::dvec3 normal = glm::normalize(glm::dvec3(0.3, 0.2, 1.0));  // towards the camera
  const Scene scene = planeScene({0.0, 0.0, -5.0}, normal);
  const Camera camera = toCamera(c, "test");
  const ImageSize size = resolveImageSize(camera, kWidth, std::nullopt);
  const AovImages aovs = RayCaster(scene).aovImages(camera, size, all());
  ASSERT_EQ(aovs.normal.size(), 3u * static_cast<std::size_t>(size.pixelCount()));
  // Camera space: x right, y up, z toward the viewer (−forward).
  const Frame f = frameOf(c);
  const glm::dvec3 expected(glm::dot(normal, f.right), glm::dot(normal, f.up), glm::dot(normal, -f.forward));
  EXPECT_GT(expected.z, 0.5);  // facing the camera, and tilted in both x and y
  EXPECT_GT(std::abs(expected.x), 0.05);
  EXPECT_GT(std::abs(expected.y), 0.05);
  const double worst = worstNormalError(aovs, expected);
  std::printf("worst normal component error %.3g\n", worst);
  EXPECT_LE(worst, 1e-5);
}

TEST(NormalAov, TheBackOfADoubleSidedPlaneIsTurnedToTheViewerAsItIsShaded) {
  const PhysicalCamera c = lookingAt({0.4, -0.2, 1.0}, {0.1, 0.3, -5.0});
  const glm::dvec3 away = -glm::normalize(glm::dvec3(0.3, 0.2, 1.0));  // the front faces away
  const Scene scene = planeScene({0.0, 0.0, -5.0}, away);
  const Camera camera = toCamera(c, "test");
  const ImageSize size = resolveImageSize(camera, kWidth, std::nullopt);
  const AovImages aovs = RayCaster(scene).aovImages(camera, size, all());
  const Frame f = frameOf(c);
  const glm::dvec3 seen = -away;
  EXPECT_LE(worstNormalError(aovs, {glm::dot(seen, f.right), glm::dot(seen, f.up), glm::dot(seen, -f.forward)}), 1e-5);
}

TEST(NormalAov, UnderDistortionThePlaneKeepsItsNormalAndOnlyTheSelectedImagesAreFilled) {
  const PhysicalCamera c = lookingAt({0.4, -0.2, 1.0}, {0.1, 0.3, -5.0});
  const glm::dvec3 normal = glm::normalize(glm::dvec3(0.3, 0.2, 1.0));
  const Scene scene = planeScene({0.0, 0.0, -5.0}, normal);
  Camera camera = toCamera(c, "test");
  camera.lens.effects.distortion.k1 = -0.2;
  const ImageSize size = resolveImageSize(camera, kWidth, std::nullopt);
  AovSelection normalOnly;
  normalOnly.normal = true;
  const AovImages aovs = RayCaster(scene).aovImages(camera, size, normalOnly);
  EXPECT_TRUE(aovs.depth.empty() && aovs.albedo.empty() && aovs.instance.empty());
  const Frame f = frameOf(c);
  EXPECT_LE(worstNormalError(aovs, {glm::dot(normal, f.right), glm::dot(normal, f.up), glm::dot(normal, -f.forward)}),
            1e-5);
}

// Two triangles placed by glTF nodes 1 and 2 (node 0 an empty parent of node 2, so that node and
// instance indices differ from the order of meshes), one material of base colour factor kBase.
class InstanceAov : public test::TempDirTest {
 protected:
  static constexpr float kBase[4] = {0.2f, 0.45f, 0.7f, 1.0f};
  // Where each node puts the triangle (0,0,0), (1,0,0), (0,1,0) in the z = 0 plane.
  static constexpr double kOffset1[2] = {-1.1, -0.5}, kOffset2[2] = {0.1, -0.4};

  Scene twoNodes() {
    test::AnimatedGltf g;
    const int mesh = g.triangle();
    g.gltf["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {kBase[0], kBase[1], kBase[2], kBase[3]}}}}}};
    g.gltf["meshes"][static_cast<std::size_t>(mesh)]["primitives"][0]["material"] = 0;
    const int parent = g.node({{"name", "parent"}, {"translation", {kOffset2[0], 0.0, 0.0}}});
    g.node({{"name", "left"}, {"mesh", mesh}, {"translation", {kOffset1[0], kOffset1[1], 0.0}}});
    g.node({{"name", "right"}, {"mesh", mesh}, {"translation", {0.0, kOffset2[1], 0.0}}}, parent);
    return loadGltf(g.write(dir_ / "two-nodes.gltf"));
  }

  // Distance of (x, y) inside the unit triangle at `offset`, negative outside (−distance to it).
  static double inside(double x, double y, const double offset[2]) {
    const double u = x - offset[0], v = y - offset[1];
    return std::min({u, v, (1.0 - u - v) / std::sqrt(2.0)});
  }
};

TEST_F(InstanceAov, EachNodesPixelsHoldItsIndexExactlyAndTheAlbedoIsTheBaseColourFactor) {
  const Scene scene = twoNodes();
  ASSERT_EQ(scene.instances.size(), 2u);
  const PhysicalCamera c = lookingAt({0.0, 0.0, 3.0}, {0.0, 0.0, 0.0});
  const Camera camera = toCamera(c, "test");
  const ImageSize size = resolveImageSize(camera, kWidth, std::nullopt);
  const AovImages aovs = RayCaster(scene).aovImages(camera, size, all());
  int counts[3] = {0, 0, 0};  // nothing, node 1, node 2
  const double margin = 1e-4;
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      const glm::dvec3 d = pixelDirection(c, x, y, size);
      const glm::dvec3 p = c.eye + (-c.eye.z / d.z) * d;  // where the centre ray meets z = 0
      const double in1 = inside(p.x, p.y, kOffset1), in2 = inside(p.x, p.y, kOffset2);
      const std::size_t i = static_cast<std::size_t>(y) * size.widthPx + x;
      const float instance = aovs.instance[i];
      if (in1 > margin || in2 > margin) {
        const float node = in1 > margin ? 1.0f : 2.0f;
        ASSERT_EQ(instance, node) << x << "," << y;
        for (int k = 0; k < 3; ++k) ASSERT_NEAR(aovs.albedo[3 * i + k], kBase[k], 1e-6) << x << "," << y;
        ++counts[static_cast<int>(node)];
      } else if (in1 < -margin && in2 < -margin) {
        ASSERT_EQ(instance, kNoSurfaceInstance) << x << "," << y;
        for (int k = 0; k < 3; ++k) ASSERT_EQ(aovs.albedo[3 * i + k], 0.0f);
        for (int k = 0; k < 3; ++k) ASSERT_EQ(aovs.normal[3 * i + k], 0.0f);
        ASSERT_TRUE(std::isinf(aovs.depth[i]));
        ++counts[0];
      }
    }
  EXPECT_GT(counts[0], 100);
  EXPECT_GT(counts[1], 100);
  EXPECT_GT(counts[2], 100);
}

TEST(InstanceAovRange, NodeIndicesUpTo2To24AreHeldExactlyAndALargerOneIsRefused) {
  Scene scene = planeScene({0.0, 0.0, -5.0}, {0.0, 0.0, 1.0});
  const PhysicalCamera c = lookingAt({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0});
  const Camera camera = toCamera(c, "test");
  const ImageSize size = resolveImageSize(camera, 16, std::nullopt);
  AovSelection instance;
  instance.instance = true;
  scene.instances[0].gltfNode = kMaxExactInstance;
  for (const float value : RayCaster(scene).aovImages(camera, size, instance).instance) ASSERT_EQ(value, 16777216.0f);
  scene.instances[0].gltfNode = kMaxExactInstance + 1;  // would round to 2^24 in a float
  EXPECT_THROW(RayCaster(scene).aovImages(camera, size, instance), InputError);
  AovSelection depth;
  depth.depth = true;
  EXPECT_NO_THROW(RayCaster(scene).aovImages(camera, size, depth));  // only the instance AOV cares
}

}  // namespace
}  // namespace lenslab
