// Oracles: images whose exact pixel integrals are known without either renderer (issue #10).
// The truth is the average of the shading over pixel square × aperture disk, textures at level 0
// (tests/common/pixel_integral.h); both renderers must converge to it as their samples grow. A
// renderer that filters textures over a pixel footprint and then averages over the pixel again
// converges to a blurred image instead, and plateaus.
#include "../common/pixel_integral.h"
#include "../common/gl_test_context.h"
#include "io/ImageCompare.h"
#include "plan/FramePlan.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "scene/ProceduralScenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace lenslab {
namespace {
using test::MovingRect;
using test::PinholeProjection;
using test::TexturedPlane;

// Small, so that 4096 rays per pixel stay a few seconds; 3:2 like the window below.
constexpr ImageSize kSize{48, 32};

Camera cameraAt(double focusM, double halfWidth, double apertureRadius) {
  return test::axisCamera(focusM, halfWidth, apertureRadius, kSize);
}

using test::randomTexture;

Scene planeScene(const TexturedPlane& plane, const Sampler& sampler) {
  Scene scene;
  scene.source = "oracle plane";
  scene.images.push_back(*plane.image);
  scene.textures.push_back({0, sampler});
  Material material;
  material.unlit = true;  // shading = texture × factor (1)
  material.doubleSided = true;
  material.baseColorTexture.texture = 0;
  scene.materials.push_back(material);
  scene.meshes.push_back(test::planeMesh(plane, 0));
  scene.instances.push_back({0, glm::dmat4(1.0)});
  scene.bounds = computeBounds(scene);
  return scene;
}

// A floor 1 m below the eye, 1 to 6 m ahead and 6 m wide, seen by a camera tilted 15° down: at
// 9.5° at its far edge, 39° at the bottom of the image. Its far and side edges and the background
// above are in view, its near edge is below the image. 64 × 64 texels of 9.4 × 7.8 cm: at kSize
// about 3 × 1.5 px per texel at the bottom and 9 texels per pixel along the depth at the far edge,
// so it is magnified and minified in one image.
TexturedPlane floorPlane(const TextureImage& image, bool nearest) {
  TexturedPlane plane;
  plane.origin = {-3.0, -1.0, -6.0};
  plane.perU = {1.5, 0.0, 0.0};
  plane.perV = {0.0, 0.0, 1.25};
  plane.uvMin = {0.0, 0.0};
  plane.uvMax = {4.0, 4.0};  // a 16 × 16 texture repeated 4 × 4 times
  plane.image = &image;
  plane.nearest = nearest;
  return plane;
}

Camera floorCamera() {
  Camera camera = cameraAt(1.5, 1.0, 0.0);
  const double tilt = glm::radians(15.0);
  const glm::dvec3 look(0.0, -std::sin(tilt), -std::cos(tilt));
  camera.view.vpn = -look;
  camera.view.vrp = 1.5 * look;  // the PRP, (0, 0, 1.5) in VRC, stays at the origin
  return camera;
}

// The bilinear integrand is rational in the pixel position at a grazing angle: the rule must have
// converged on this floor, i.e. doubling its points changes nothing a float image holds.
TEST(OracleIntegrator, FloorBilinearIntegralHasConverged) {
  const TextureImage image = randomTexture(16, 16, 3);
  const TexturedPlane plane = floorPlane(image, false);
  const PinholeProjection projection(floorCamera(), kSize);
  const auto maxDifference = [](const Image& a, const Image& b) {
    float worst = 0.0f;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) worst = std::max(worst, std::abs(a.rgba[i] - b.rgba[i]));
    return worst;
  };
  const Image coarse = test::planeImage(plane, projection, kSize, glm::dvec3(0.1), 2);
  const Image used = test::planeImage(plane, projection, kSize, glm::dvec3(0.1), 8);
  const Image fine = test::planeImage(plane, projection, kSize, glm::dvec3(0.1), 16);
  std::printf("[ oracle   ] bilinear floor: max change 2 -> 8 points %.2e, 8 -> 16 points %.2e\n",
              static_cast<double>(maxDifference(coarse, used)), static_cast<double>(maxDifference(used, fine)));
  EXPECT_LT(maxDifference(used, fine), 1e-6f);
}

struct Row {
  int samples;
  double psnrDb;
  double seconds;
};

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

std::vector<Row> rayCasterRows(const Scene& scene, const Camera& camera, const Image& truth,
                               const std::vector<int>& spps) {
  const RayCaster caster(scene);
  std::vector<Row> rows;
  for (const int spp : spps) {
    const auto start = std::chrono::steady_clock::now();
    const Image image = caster.render(camera, kSize, RaycastOptions{spp, 7});
    rows.push_back({spp, compareImages(image, truth, 0.0).psnrDb, seconds(start)});
  }
  return rows;
}

std::vector<Row> rasterRows(const Scene& scene, const Camera& camera, const Image& truth,
                            const std::vector<int>& views) {
  // An explicit N with a pinhole is N sub-pixel-jittered views (anti-aliasing), as with a lens.
  const Camera& jittered = camera;
  Renderer renderer(scene);
  std::vector<Row> rows;
  for (const int n : views) {
    const auto start = std::chrono::steady_clock::now();
    const FramePlan plan = makeFramePlan(scene, jittered, kSize, PlanOptions{AperturePattern::Concentric, n, n, 7});
    const Image image = renderer.render(jittered, plan, kSize);
    rows.push_back({n, compareImages(image, truth, 0.0).psnrDb, seconds(start)});
  }
  return rows;
}

void printTable(const std::string& name, const std::vector<Row>& caster, const std::vector<Row>& raster) {
  std::printf("[ oracle   ] %s, %dx%d, PSNR against the exact pixel integral\n", name.c_str(), kSize.widthPx,
              kSize.heightPx);
  std::printf("[ oracle   ]   samples   ray caster           raster\n");
  for (std::size_t i = 0; i < std::max(caster.size(), raster.size()); ++i) {
    const int samples = i < caster.size() ? caster[i].samples : raster[i].samples;
    std::printf("[ oracle   ]   %7d", samples);
    if (i < caster.size())
      std::printf("   %6.2f dB %6.2f s", caster[i].psnrDb, caster[i].seconds);
    else
      std::printf("   %18s", "");
    if (i < raster.size()) std::printf("   %6.2f dB %6.2f s", raster[i].psnrDb, raster[i].seconds);
    std::printf("\n");
  }
  std::fflush(stdout);
}

// Converging: no step loses more than noise (0.5 dB), the whole table gains 10 dB (a renderer
// converging to anything but the truth plateaus), and the last row reaches `floorDb`.
void expectConverges(const std::vector<Row>& rows, const std::string& who, double floorDb) {
  for (std::size_t i = 1; i < rows.size(); ++i)
    EXPECT_GE(rows[i].psnrDb, rows[i - 1].psnrDb - 0.5) << who << " at " << rows[i].samples << " samples";
  EXPECT_GE(rows.back().psnrDb, rows.front().psnrDb + 10.0) << who;
  EXPECT_GE(rows.back().psnrDb, floorDb) << who << " at " << rows.back().samples << " samples";
}

const std::vector<int> kRayCasterSpp{16, 64, 256, 1024, 4096};
const std::vector<int> kRasterViews{16, 64, 256, 1024};

void expectBothConverge(const std::string& name, const Scene& scene, const Camera& camera, const Image& truth,
                        double floorDb = 50.0) {
  const std::vector<Row> caster = rayCasterRows(scene, camera, truth, kRayCasterSpp);
  const std::vector<Row> raster = rasterRows(scene, camera, truth, kRasterViews);
  printTable(name, caster, raster);
  expectConverges(caster, name + ": ray caster", floorDb);
  expectConverges(raster, name + ": raster", floorDb);
}

// The grazing floor of 16×16 random texels through `sampler`, against its exact pixel integral
// (nearest texels, or the bilinear level-0 reconstruction for any LINEAR filter).
void expectFloorConverges(const std::string& name, const Sampler& sampler) {
  const TextureImage image = randomTexture(16, 16, 3);
  const TexturedPlane plane = floorPlane(image, sampler.magFilter == Filter::Nearest);
  const Scene scene = planeScene(plane, sampler);
  const Camera camera = floorCamera();
  const Image truth = test::planeImage(plane, PinholeProjection(camera, kSize), kSize, scene.lighting.background);
  expectBothConverge(name, scene, camera, truth);
}

// NEAREST, no mip levels: each texel is a convex quad in the image, its colour constant.
TEST(Oracle, NearestTexelsOnAGrazingFloor) {
  LENSLAB_REQUIRE_GL();
  expectFloorConverges("nearest floor", Sampler{Wrap::Repeat, Wrap::Repeat, Filter::Nearest, Filter::Nearest});
}

// LINEAR without mips: nothing is pre-filtered, so both renderers converge to the bilinear
// oracle whatever their level of detail. This checks the oracle itself, and leaves the mips as the
// only difference in the next test.
TEST(Oracle, BilinearTexelsWithoutMipsOnAGrazingFloor) {
  LENSLAB_REQUIRE_GL();
  expectFloorConverges("bilinear floor, no mips", Sampler{Wrap::Repeat, Wrap::Repeat, Filter::Linear, Filter::Linear});
}

// glTF's default sampler (LINEAR / LINEAR_MIPMAP_LINEAR, mips on the GPU): the truth is still
// the pixel integral of the bilinear level-0 reconstruction, the mips being only a way to it. A
// texture footprint of a whole pixel, averaged over the pixel again, plateaus here: both renderers
// stayed at 26 dB from 16 samples on before each sample's footprint was its own share of the pixel.
TEST(Oracle, BilinearTexelsOnAGrazingFloor) {
  LENSLAB_REQUIRE_GL();
  expectFloorConverges("bilinear mipmapped floor", Sampler{});
}

struct FlatQuad {
  glm::dmat4 worldFromModel;
  double halfWidth, halfHeight;
  glm::vec3 colour;
};

glm::dmat4 placed(const glm::dvec3& centre, double degreesAboutZ) {
  return glm::rotate(glm::translate(glm::dmat4(1.0), centre), glm::radians(degreesAboutZ), glm::dvec3(0, 0, 1));
}

// Three flat quads at 3, 4 and 6 m, turned so that no edge follows the pixel grid, each partly
// hiding the next.
const std::vector<FlatQuad> kQuadsNearestFirst{
    {placed({-0.35, -0.3, -3.0}, 50.0), 0.35, 0.3, {0.15f, 0.3f, 0.95f}},
    {placed({0.45, -0.15, -4.0}, -35.0), 0.8, 0.5, {0.1f, 0.75f, 0.3f}},
    {placed({-0.3, 0.2, -6.0}, 20.0), 2.2, 1.3, {0.9f, 0.35f, 0.1f}},
};

TEST(Oracle, OccludingFlatQuads) {
  LENSLAB_REQUIRE_GL();
  Scene scene;
  scene.source = "oracle quads";
  for (const FlatQuad& q : kQuadsNearestFirst)
    addUnlitQuad(scene, q.worldFromModel, q.halfWidth, q.halfHeight, q.colour);
  scene.bounds = computeBounds(scene);
  const Camera camera = floorCamera();
  const PinholeProjection projection(camera, kSize);
  std::vector<test::ColouredPolygon> polygons;
  for (const FlatQuad& q : kQuadsNearestFirst) {
    test::Polygon corners;
    for (const glm::dvec2 c : {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)})
      corners.push_back(
          projection.pixel(glm::dvec3(q.worldFromModel * glm::dvec4(c.x * q.halfWidth, c.y * q.halfHeight, 0.0, 1.0))));
    polygons.push_back({corners, glm::dvec3(q.colour)});
  }
  const Image truth = test::polygonsImage(polygons, kSize, scene.lighting.background);
  expectBothConverge("occluding quads", scene, camera, truth);
}

// Thin lens: a NEAREST texture on a fronto-parallel plane 2 m behind the plane of focus, a quad
// 1 m in front of it; both blur to circles of 4 px (2R/3 = 1/3 m on the view plane, 12 px per m).
// Every texel and the quad stay axis-aligned rectangles of the image that slide with the lens
// offset, each depth at its own rate.
TEST(Oracle, ThinLensTexelsBehindAQuad) {
  LENSLAB_REQUIRE_GL();
  const double focusM = 4.0, apertureRadius = 0.5;
  const TextureImage image = randomTexture(16, 16, 5);
  TexturedPlane plane;
  plane.origin = {-2.4, 1.5, -6.0};  // glTF's v runs down the image
  plane.perU = {4.8, 0.0, 0.0};
  plane.perV = {0.0, -3.0, 0.0};
  plane.image = &image;
  Scene scene = planeScene(plane, Sampler{Wrap::Repeat, Wrap::Repeat, Filter::Nearest, Filter::Nearest});
  const glm::dvec3 quadCentre{0.3, 0.2, -3.0};
  const double quadHalfSize = 0.45;
  const glm::vec3 quadColour{0.95f, 0.85f, 0.2f};
  addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), quadCentre), quadHalfSize, quadHalfSize, quadColour);
  scene.bounds = computeBounds(scene);
  const Camera camera = cameraAt(focusM, 2.0, apertureRadius);

  const PinholeProjection centre(camera, kSize), right(camera, kSize, {1.0, 0.0}), up(camera, kSize, {0.0, 1.0});
  const auto moving = [&](const glm::dvec3& corner0, const glm::dvec3& corner1, const glm::dvec3& colour) {
    const glm::dvec2 a = centre.pixel(corner0), b = centre.pixel(corner1);
    return MovingRect{
        glm::min(a, b), glm::max(a, b), {right.pixel(corner0).x - a.x, up.pixel(corner0).y - a.y}, colour};
  };
  std::vector<MovingRect> texels;
  for (int j = 0; j < image.height; ++j)
    for (int i = 0; i < image.width; ++i) {
      const std::uint8_t* p = &image.rgba8[static_cast<std::size_t>(j * image.width + i) * 4];
      texels.push_back(
          moving(plane.world({static_cast<double>(i) / image.width, static_cast<double>(j) / image.height}),
                 plane.world({static_cast<double>(i + 1) / image.width, static_cast<double>(j + 1) / image.height}),
                 {test::decodeSrgb8(p[0]), test::decodeSrgb8(p[1]), test::decodeSrgb8(p[2])}));
    }
  const MovingRect quad = moving(quadCentre - glm::dvec3(quadHalfSize, quadHalfSize, 0.0),
                                 quadCentre + glm::dvec3(quadHalfSize, quadHalfSize, 0.0), glm::dvec3(quadColour));
  const Image truth = test::thinLensRectsImage(quad, texels, kSize, scene.lighting.background, apertureRadius);
  // Slower than the pinhole's: the Concentric pattern pairs lens and pixel strata by a random
  // shuffle, so the defocused (four-dimensional) integrand's variance falls as 1/N, about 10 dB a
  // decade, not as N^-1.5 for edges in the pixel alone: ~50 dB at 1024 views, ~55 at 4096 rays.
  expectBothConverge("thin lens, texels behind a quad", scene, camera, truth, 45.0);
}

}  // namespace
}  // namespace lenslab
