// The rasterizer's order for alphaMode BLEND instances (scene/BlendOrder.h): farthest first from a
// perspective view's eye, or along a parallel view's direction; opaque instances left out.
#include "../common/blend_scene.h"
#include "scene/BlendOrder.h"

#include <gtest/gtest.h>

namespace lenslab {
namespace {

// Blend quads at x = 0, z = 0, −1, −2 (instances 0, 2, 3) and an opaque one at z = −3 (1).
Scene row() {
  Scene scene;
  const int blend = test::addMaterial(scene, {1.0f, 1.0f, 1.0f, 0.5f}, true);
  const int opaque = test::addMaterial(scene, {1.0f, 1.0f, 1.0f, 1.0f}, true, false);
  test::addQuad(scene, {0.0, 0.0, 0.0}, 1.0, 1.0, blend);
  test::addQuad(scene, {0.0, 0.0, -3.0}, 1.0, 1.0, opaque);
  test::addQuad(scene, {0.0, 0.0, -1.0}, 1.0, 1.0, blend);
  test::addQuad(scene, {0.0, 0.0, -2.0}, 1.0, 1.0, blend);
  return scene;
}

TEST(BlendOrder, FarthestFromTheEyeFirst) {
  const Scene scene = row();
  EXPECT_TRUE(anyBlended(scene));
  const glm::dvec3 front(0.0, 0.0, 5.0), back(0.0, 0.0, -7.0);
  EXPECT_EQ(blendBackToFront(scene, &front, {0.0, 0.0, 1.0}), (std::vector<std::size_t>{3, 2, 0}));
  EXPECT_EQ(blendBackToFront(scene, &back, {0.0, 0.0, 1.0}), (std::vector<std::size_t>{0, 2, 3}));
}

TEST(BlendOrder, ParallelViewsOrderAlongTheirDirection) {
  Scene scene = row();
  // Moved far apart sideways: distance from a point would mix x in, distance along the view does not.
  scene.instances[0].worldFromModel[3].x = 1e3;
  const glm::dvec3 fromPlusZ(0.0, 0.0, 1.0), fromMinusZ(0.0, 0.0, -1.0);
  EXPECT_EQ(blendBackToFront(scene, nullptr, fromPlusZ), (std::vector<std::size_t>{3, 2, 0}));
  EXPECT_EQ(blendBackToFront(scene, nullptr, fromMinusZ), (std::vector<std::size_t>{0, 2, 3}));
}

TEST(BlendOrder, TheCentreIsTheBoundsCentreCarriedByTheInstance) {
  Scene scene;
  Mesh mesh = quadMesh(1.0, 1.0, test::addMaterial(scene, glm::vec4(0.5f), true));
  for (Vertex& v : mesh.vertices) v.position.x += 4.0f;  // model bounds x in [3, 5]
  scene.meshes.push_back(mesh);
  Instance instance;
  instance.mesh = 0;
  instance.worldFromModel = glm::scale(glm::translate(glm::dmat4(1.0), {0.0, 1.0, 0.0}), glm::dvec3(2.0));
  scene.instances.push_back(instance);
  const glm::dvec3 centre = instanceBoundsCentre(scene, instance);
  EXPECT_DOUBLE_EQ(centre.x, 8.0);
  EXPECT_DOUBLE_EQ(centre.y, 1.0);
  EXPECT_DOUBLE_EQ(centre.z, 0.0);
}

TEST(BlendOrder, ScenesWithoutBlendHaveNone) {
  Scene scene;
  test::addQuad(scene, {0.0, 0.0, 0.0}, 1.0, 1.0, test::addMaterial(scene, glm::vec4(1.0f), true, false));
  test::addQuad(scene, {0.0, 0.0, 1.0}, 1.0, 1.0, -1);  // glTF's default material
  EXPECT_FALSE(anyBlended(scene));
  const glm::dvec3 eye(0.0, 0.0, 5.0);
  EXPECT_TRUE(blendBackToFront(scene, &eye, {0.0, 0.0, 1.0}).empty());
}

}  // namespace
}  // namespace lenslab
