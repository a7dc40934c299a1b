// "A new lens model is a new map" (camera/ImageMap.h): a lens model the renderers do not know,
// defined here as an ImageMap, renders through the ray caster's one loop (RayCaster::render(const
// ImageMap&), raycast/RenderLoop.h) with nothing else added. The model is a telecentric
// (orthographic) lens: parallel rays along the camera's axis, so a thing's size in the image does
// not depend on its distance. Two equal squares at 2 and 8 m cover equal areas through it, where
// the pinhole of the same camera shrinks the far one 16 times; the map's gain scales the light.
#include "camera/ImageMap.h"
#include "camera/PhysicalCamera.h"
#include "camera/ViewSpec.h"
#include "raycast/RayCaster.h"
#include "scene/ProceduralScenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cstdio>
#include <limits>

namespace lenslab {
namespace {

// Rays parallel to the camera's axis (−n), one per film point, leaving the plane through the lens
// centre: the film is `widthWorld` world units wide, so a pixel is widthWorld / widthPx on a side at
// any distance. Its lens samples change nothing (a telecentric pinhole); its gain is `gain` everywhere.
class TelecentricMap final : public ImageMap {
 public:
  TelecentricMap(const Camera& camera, ImageSize size, double widthWorld, double gain)
      : ImageMap(camera, size),
        basis_(viewBasis(camera.view)),
        centre_(prpWorld(camera.view)),
        pitch_(widthWorld / size.widthPx),
        gain_(gain) {}

  LensDomain lensDomain() const override { return LensDomain::Disk; }
  int rayChannels() const override { return 1; }
  std::optional<CameraRay> ray(glm::dvec2 pixel, glm::dvec2 lens, int channel,
                               const CameraRay* /*near*/) const override {
    CameraRay r;
    r.ray = rayThrough(pixel);
    r.pixel = pixel;
    r.lensPoint = lens;
    r.channel = channel;
    return r;
  }
  Ray footprintRay(const CameraRay& r, glm::dvec2 offsetPx) const override { return rayThrough(r.pixel + offsetPx); }
  std::optional<CameraRay> centreRay(glm::dvec2 pixel) const override { return ray(pixel, {0.0, 0.0}, 1, nullptr); }
  double gainAt(glm::dvec2 /*pixel*/) const override { return gain_; }

 private:
  // Film position (origin top left, +y down) to the ray: right along u, up along v, looking along −n.
  Ray rayThrough(glm::dvec2 pixel) const {
    const glm::dvec2 offset((pixel.x - 0.5 * size_.widthPx) * pitch_, (0.5 * size_.heightPx - pixel.y) * pitch_);
    return Ray{centre_ + offset.x * basis_.u + offset.y * basis_.v, -basis_.n, 0.0,
               std::numeric_limits<double>::infinity()};
  }

  ViewBasis basis_;
  glm::dvec3 centre_;
  double pitch_;
  double gain_;
};

// The image's coverage (alpha) summed over columns [x0, x1): the pixels a square covers.
double coveredPixels(const Image& image, int x0, int x1) {
  double sum = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = x0; x < x1; ++x) sum += image.at(x, y).a;
  return sum;
}

TEST(ImageMapRaycast, ANewLensModelIsANewMapThroughTheOneLoop) {
  // Two 0.4 m squares facing the camera, the near one left of the axis at 2 m, the far one right at 8 m.
  Scene scene;
  scene.source = "two squares";
  scene.lighting.background = glm::vec3(0.0f);
  const glm::vec3 colour(0.8f, 0.6f, 0.4f);
  addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(-0.3, 0.0, -2.0)), 0.2, 0.2, colour);
  addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(0.3, 0.0, -8.0)), 0.2, 0.2, colour);
  PhysicalCamera physical;  // 35 mm on 36 × 24 mm, a pinhole
  physical.eye = {0.0, 0.0, 0.0};
  physical.target = {0.0, 0.0, -1.0};
  const Camera camera = toCamera(physical, "test");
  const ImageSize size{60, 40};
  const RayCaster caster(scene);

  // 2 m of film over 60 pixels: each square is 12 × 12 pixels, on whole pixels, at either distance.
  const TelecentricMap telecentric(camera, size, 2.0, 0.5);
  const Image image = caster.render(telecentric, RaycastOptions{16, 1});
  const double nearPx = coveredPixels(image, 0, 30), farPx = coveredPixels(image, 30, 60);
  std::printf("telecentric: near square %.2f px, far %.2f px (144 each)\n", nearPx, farPx);
  EXPECT_NEAR(nearPx, 144.0, 1.0);
  EXPECT_NEAR(farPx, 144.0, 1.0);
  // The map's gain, applied by the loop after the samples' mean: half the squares' light.
  for (const glm::ivec2 p : {glm::ivec2(21, 20), glm::ivec2(39, 20)}) {
    EXPECT_NEAR(image.at(p.x, p.y).r, 0.5f * colour.r, 1e-5f) << p.x << "," << p.y;
    EXPECT_NEAR(image.at(p.x, p.y).b, 0.5f * colour.b, 1e-5f) << p.x << "," << p.y;
    EXPECT_EQ(image.at(p.x, p.y).a, 1.0f);
  }

  // The same camera's own map (its pinhole): the far square a sixteenth of the near one's area.
  const Image pinhole = caster.render(camera, size, RaycastOptions{16, 1});
  const double nearPinholePx = coveredPixels(pinhole, 0, 30), farPinholePx = coveredPixels(pinhole, 30, 60);
  std::printf("pinhole: near square %.2f px, far %.2f px\n", nearPinholePx, farPinholePx);
  EXPECT_NEAR(farPinholePx / nearPinholePx, 1.0 / 16.0, 0.01);
}

}  // namespace
}  // namespace lenslab
