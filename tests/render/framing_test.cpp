// Automatic framing, rendered: a glTF without cameras, written here at sizes from a micrometre to
// a thousand kilometres, comes out in frame, upright and filling it, through both renderers —
// the thin lens (with depth of field) where it can focus on the subject, a pinhole beyond life
// size. The subject is a square, its top half red and its bottom half blue (unlit), facing the
// camera: upside down, cropped or empty images all fail.
#include "../common/animated_gltf.h"
#include "../common/temp_dir_test.h"
#include "camera/Camera.h"
#include "camera/DepthRange.h"
#include "core/Text.h"
#include "../common/gl_test_context.h"
#include "plan/CameraSelection.h"
#include "plan/FramePlan.h"
#include "io/ImageCompare.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "scene/GltfLoader.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace lenslab {
namespace {

// A square of side `side` in the XY plane about the origin, red above y = 0 and blue below, under
// a root node scaled by `rootScale` (as a model exported at the wrong unit is) and moved by
// `rootOffset` (as a model in geographic coordinates is).
std::filesystem::path writeTwoToneSquare(const std::filesystem::path& file, double side, double rootScale,
                                         double rootOffset = 0.0, bool lit = false) {
  test::AnimatedGltf g;
  const float h = static_cast<float>(0.5 * side);
  const auto half = [&](float y0, float y1) {
    const int positions = g.floats({-h, y0, 0, h, y0, 0, h, y1, 0, -h, y0, 0, h, y1, 0, -h, y1, 0}, "VEC3", 6);
    g.gltf["accessors"][static_cast<std::size_t>(positions)]["min"] = {-h, y0, 0};
    g.gltf["accessors"][static_cast<std::size_t>(positions)]["max"] = {h, y1, 0};
    return positions;
  };
  const int top = half(0.0f, h), bottom = half(-h, 0.0f);
  if (!lit) g.gltf["extensionsUsed"] = {"KHR_materials_unlit"};
  for (const auto& colour : {std::vector<double>{1, 0, 0, 1}, std::vector<double>{0, 0, 1, 1}}) {
    g.gltf["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorFactor", colour}}}, {"doubleSided", true}});
    if (!lit) g.gltf["materials"].back()["extensions"] = {{"KHR_materials_unlit", nlohmann::json::object()}};
  }
  g.gltf["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", top}}}, {"material", 0}}}}});
  g.gltf["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", bottom}}}, {"material", 1}}}}});
  const int root =
      g.node({{"scale", {rootScale, rootScale, rootScale}}, {"translation", {rootOffset, 0.5 * rootOffset, 0.0}}});
  g.node({{"mesh", 0}}, root);
  g.node({{"mesh", 1}}, root);
  return g.write(file);
}

struct Coverage {
  int red = 0, blue = 0;
  double redRow = 0.0, blueRow = 0.0;                          // mean row (0 at the top)
  int top = 1 << 30, bottom = -1, left = 1 << 30, right = -1;  // the subject's pixel rows and columns
};

Coverage coverage(const Image& image) {
  Coverage c;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const glm::vec4 p = image.at(x, y);
      const bool red = p.r > 0.5f && p.b<0.2f, blue = p.b> 0.5f && p.r < 0.2f;
      if (!red && !blue) continue;
      (red ? c.red : c.blue) += 1;
      (red ? c.redRow : c.blueRow) += y;
      c.top = std::min(c.top, y), c.bottom = std::max(c.bottom, y);
      c.left = std::min(c.left, x), c.right = std::max(c.right, x);
    }
  if (c.red) c.redRow /= c.red;
  if (c.blue) c.blueRow /= c.blue;
  return c;
}

class AutomaticFramingGl : public test::TempDirTest {};

// Lit, so that shading takes the direction toward the eye: in a scene 1e-30 across its squared
// length underflows a float (normalize gave NaN: the probe's C22 had 204 of 600 pixels NaN; the ray
// caster works in double).
TEST_F(AutomaticFramingGl, ALitSubjectOfAnySizeIsShadedFinitelyAsTheRayCastShadesIt) {
  LENSLAB_REQUIRE_GL();
  for (const double side : {1e-30, 1e-12, 1.0, 1e6}) {
    const Scene scene = loadGltf(writeTwoToneSquare(dir_ / "lit.gltf", side, 1.0, 0.0, true));
    const Camera camera = withDepthRangeFitted(chooseCamera(scene, std::nullopt, {}, 0.0).camera, scene.bounds);
    const ImageSize size{48, 32};
    Renderer renderer(scene);
    const Image raster = renderer.render(
        camera, makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, 16, 16, 1}), size);
    int notFinite = 0;
    for (const float v : raster.rgba) notFinite += std::isfinite(v) ? 0 : 1;
    EXPECT_EQ(notFinite, 0) << "side " << side;
    const Image cast = RayCaster(scene).render(camera, size, RaycastOptions{16, 1});
    EXPECT_GE(compareImages(raster, cast, 0.0).psnrDb, 30.0) << "side " << side;
  }
}

TEST_F(AutomaticFramingGl, AnySizeOfSubjectFillsTheFrameUpright) {
  LENSLAB_REQUIRE_GL();
  // {side, root scale, root offset}: 1e-30 m to 1000 km (below about 1e-13 m Embree's float
  // triangle test underflows unless the ray caster rescales), the 1 and 2–3 cm that used to come
  // out upside down or cropped, a 4 cm model under a root scaled by 0.15 (Avocado's case), and a
  // 1 m square 1e11 and 1e13 from the origin (framed to a speck when its framing took 1e-9 of
  // the distance from the origin as the smallest radius).
  struct Case {
    double side, rootScale, rootOffset;
  };
  for (const auto& [side, rootScale, rootOffset] : std::vector<Case>{{1e-30, 1.0, 0.0},
                                                                     {1e-12, 1.0, 0.0},
                                                                     {1e-6, 1.0, 0.0},
                                                                     {1e-3, 1.0, 0.0},
                                                                     {0.01, 1.0, 0.0},
                                                                     {0.02, 1.0, 0.0},
                                                                     {0.03, 1.0, 0.0},
                                                                     {1.0, 1.0, 0.0},
                                                                     {1e6, 1.0, 0.0},
                                                                     {0.04, 0.15, 0.0},
                                                                     {1.0, 1.0, 1e11},
                                                                     {1.0, 1.0, 1e13}}) {
    const Scene scene = loadGltf(writeTwoToneSquare(dir_ / "square.gltf", side, rootScale, rootOffset));
    // As `render` frames it, and with depth of field where the lens can focus on the subject
    // (`render --f-number 2`; a pinhole's framing refuses an f-number).
    for (const char* fNumber : {"", "2"}) {
      if (*fNumber && !chooseCamera(scene, std::nullopt, {}, 0.0).physical) continue;
      CameraOptions options;
      options.fNumber = fNumber;
      const Camera camera = withDepthRangeFitted(chooseCamera(scene, std::nullopt, options, 0.0).camera, scene.bounds);
      const ImageSize size{72, 48};
      Renderer renderer(scene);
      const Image raster = renderer.render(
          camera, makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, 16, 16, 1}), size);
      const Image cast = RayCaster(scene).render(camera, size, RaycastOptions{8, 1});
      for (const auto& [name, image] : {std::pair<const char*, const Image&>{"raster", raster}, {"ray cast", cast}}) {
        const Coverage c = coverage(image);
        const std::string what =
            cat(name, ", side ", side, " x root scale ", rootScale, " at ", rootOffset, ": ", camera.source);
        // Half the square each, and together most of the frame's height (the square's diagonal
        // spans the bounding sphere's diameter: its side about 0.69 of the frame's height).
        EXPECT_GT(c.red, size.widthPx * size.heightPx / 10) << what;
        EXPECT_GT(c.blue, size.widthPx * size.heightPx / 10) << what;
        EXPECT_LT(c.redRow, c.blueRow) << "upright: red above blue; " << what;
        EXPECT_GT(c.bottom - c.top + 1, size.heightPx / 2) << what;
        EXPECT_GE(c.top, 1) << "in frame, not cropped; " << what;
        EXPECT_LE(c.bottom, size.heightPx - 2) << what;
        EXPECT_GE(c.left, 1) << what;
        EXPECT_LE(c.right, size.widthPx - 2) << what;
      }
    }
  }
}

}  // namespace
}  // namespace lenslab
