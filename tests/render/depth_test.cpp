// Reverse-Z with a float depth buffer keeps surfaces 1e-5 apart (relative) in the right order
// from near = 1e-3 to far = 1e6: the nearer colour wins whichever is drawn first.
#include "camera/Camera.h"
#include "../common/gl_test_context.h"
#include "plan/FramePlan.h"
#include "render/Renderer.h"
#include "scene/ProceduralScenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace lenslab {
namespace {

Scene twoPlanes(double nearDepth, double gapRelative, bool nearFirst) {
  Scene scene;
  scene.source = "two planes";
  const double farDepth = nearDepth * (1.0 + gapRelative);
  // Camera at the origin looking down −z; quads wide enough to fill the view at their depth.
  auto quad = [&](double depth, const glm::vec3& color) {
    addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -depth)), depth, depth, color);
  };
  if (nearFirst) {
    quad(nearDepth, {1, 0, 0});
    quad(farDepth, {0, 1, 0});
  } else {
    quad(farDepth, {0, 1, 0});
    quad(nearDepth, {1, 0, 0});
  }
  return scene;
}

Camera camera(double nearDistance, double farDistance) {
  Camera c;
  c.view.vrp = {0.0, 0.0, -1.0};
  c.view.vpn = {0.0, 0.0, 1.0};
  c.view.prp = {0.0, 0.0, 1.0};
  c.view.window = {-0.5, -0.5, 0.5, 0.5};
  c.view.nearDistance = nearDistance;
  c.view.farDistance = farDistance;
  validate(c.view, "test camera");
  return c;
}

TEST(ReverseZ, KeepsSurfacesOneHundredThousandthApartInOrder) {
  LENSLAB_REQUIRE_GL();
  for (double farDistance : {1e6, std::numeric_limits<double>::infinity()}) {
    const Camera cam = camera(1e-3, farDistance);
    for (double depth : {0.01, 1.0, 100.0, 1e4, 5e5}) {
      for (bool nearFirst : {true, false}) {
        SCOPED_TRACE(testing::Message() << "far " << farDistance << ", depth " << depth
                                        << (nearFirst ? ", near drawn first" : ", far drawn first"));
        const Scene scene = twoPlanes(depth, 1e-5, nearFirst);
        Renderer renderer(scene);
        const Image image = renderer.render(cam, makeFramePlan(scene, cam, {32, 32}), {32, 32});
        int nearWins = 0;
        for (int y = 0; y < image.height; ++y)
          for (int x = 0; x < image.width; ++x) nearWins += image.at(x, y).r > 0.5f && image.at(x, y).g < 0.5f;
        EXPECT_EQ(nearWins, image.width * image.height) << "the farther surface showed through";
      }
    }
  }
}

}  // namespace
}  // namespace lenslab
