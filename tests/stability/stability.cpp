// lenslab_stability: the numerical-stability table. Every row renders a stiff or extreme case
// through the same paths a user's command takes (camera JSON → refocus → depth range fitted to the
// scene → raster and/or ray caster), measures it against an answer that does not come from the
// renderer under test (the same scene nearer the origin, infinity focus, a pinhole, an exact
// constant, the other renderer, a parallel projection), and checks the row's bound.
//
//   lenslab_stability              the default rows (about 20 s on 2 cores); exit 1 if a bound fails
//   lenslab_stability --long       also the slow rows (2400 px tiled vs untiled, 20000 px in tiles)
//   lenslab_stability --markdown F writes the table as Markdown to F (docs/stability.md's table is
//                                  this output: tools/update-stability-table.sh)
//   lenslab_stability --check-doc docs/stability.md
//                                  also fails when the doc's table no longer describes this run: a
//                                  row missing, or a figure beyond its tolerance (TableCheck.h)
//
// Measured figures are printed to 3 significant digits (PSNR to 0.1 dB), so that the table is the
// same from run to run on one machine (llvmpipe and the seeded ray caster are deterministic). On
// another CPU llvmpipe and Embree take other SIMD paths and the last digits move: the doc check
// compares figures with a tolerance, never digit for digit.
#include "camera/Camera.h"
#include "camera/DepthRange.h"
#include "camera/ImageMap.h"
#include "camera/LensMap.h"
#include "camera/PhysicalCamera.h"
#include "core/Error.h"
#include "core/Text.h"
#include "gl/GlContext.h"
#include "io/CameraJson.h"
#include "io/ImageCompare.h"
#include "io/ImageFile.h"
#include "plan/FramePlan.h"
#include "plan/TilePlan.h"
#include "plan/UserOptions.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "render/TiledRender.h"
#include "scene/GltfLoader.h"
#include "scene/ProceduralScenes.h"
#include "scene/Scene.h"

#include "TableCheck.h"

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

using stability::BareNumbers;

struct Row {
  std::string group;
  std::string input;     // the case
  std::string bound;     // what must hold
  std::string measured;  // what did
  bool ok = false;
  BareNumbers bare = BareNumbers::Exact;  // how the doc check compares its bare numbers
};

std::vector<Row> rows;
// Rows this run leaves out (the slow ones without --long): the doc may hold them.
std::vector<Row> skipped;

void record(const std::string& group, const std::string& input, const std::string& bound, const std::string& measured,
            bool ok, BareNumbers bare = BareNumbers::Exact) {
  rows.push_back({group, input, bound, measured, ok, bare});
  std::cout << (ok ? "[ ok   ] " : "[ FAIL ] ") << group << " | " << input << " | " << bound << " | " << measured
            << std::endl;
}

// 3 significant digits, as the table shows them.
std::string sig(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (std::isnan(v)) return "NaN";
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

std::string dB(double v) {
  if (std::isinf(v)) return "identical";
  char b[32];
  std::snprintf(b, sizeof b, "%.1f dB", v);
  return b;
}

bool finite(const Image& image) {
  for (const float v : image.rgba)
    if (!std::isfinite(v)) return false;
  return true;
}

// Nothing drawn: every pixel the same.
bool blank(const Image& image) {
  for (std::size_t i = 4; i < image.rgba.size(); ++i)
    if (image.rgba[i] != image.rgba[i % 4]) return false;
  return true;
}

double psnr(const Image& a, const Image& b) { return compareImages(a, b, 0.0).psnrDb; }

const fs::path kAssets = LENSLAB_STABILITY_ASSET_DIR;

// As `lenslab render`/`raycast` take a camera: the depth range fitted to the scene.
Camera prepared(const Camera& camera, const Scene& scene) { return withDepthRangeFitted(camera, scene.bounds); }

Image raster(const Scene& scene, const Camera& camera, ImageSize size, int views, std::uint32_t seed = 3) {
  const Camera c = prepared(camera, scene);
  const FramePlan plan = makeFramePlan(scene, c, size, PlanOptions{AperturePattern::Concentric, views, views, seed});
  Renderer renderer(scene);
  return renderer.render(c, plan, size);
}

Image raycast(const Scene& scene, const Camera& camera, ImageSize size, int spp, std::uint32_t seed = 3) {
  return RayCaster(scene).render(prepared(camera, scene), size, RaycastOptions{spp, seed});
}

// The message of the InputError that `f` throws; empty when it throws none.
std::string refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

bool oneLine(const std::string& message) { return !message.empty() && message.find('\n') == std::string::npos; }

std::string shortened(const std::string& message) {
  return message.size() <= 120 ? message : message.substr(0, 117) + "...";
}

Camera physical(const std::string& extra) {
  // `extra` (", key: value, ...") overrides the defaults; a camera file itself refuses a key given twice.
  nlohmann::json camera =
      nlohmann::json::parse(R"({"eye": [0, 1, 3], "target": [0, 0.55, -2], "focal_length_mm": 35})");
  if (!extra.empty()) camera.update(nlohmann::json::parse(cat("{", extra.substr(extra.find(',') + 1), "}")));
  return parseCameraJson(camera.dump(), "stability camera").camera;
}

Scene moved(const Scene& scene, const glm::dvec3& offset) {
  Scene s = scene;
  for (Instance& instance : s.instances)
    instance.worldFromModel = glm::translate(glm::dmat4(1.0), offset) * instance.worldFromModel;
  s.bounds = computeBounds(s);
  return s;
}

// ---- the cases ----

void depthRange() {
  // Two unlit quads facing the camera, the nearer (red) 1e-5·z in front of the farther (green),
  // both filling the view; near 1e-5, far at infinity, given (not fitted).
  double worstRaster = 1.0, worstRaycast = 1.0;
  for (const double z : {1e-4, 1e-2, 1.0, 1e2, 1e4, 1e6}) {
    Scene scene;
    addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -z)), z, z, {1, 0, 0});
    addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -z * (1.0 + 1e-5))), z, z, {0, 1, 0});
    scene.bounds = computeBounds(scene);
    const Camera camera =
        parseCameraJson(
            cat(R"({"vrp": [0, 0, -1], "vpn": [0, 0, 1], "prp": [0, 0, 1], "window": [-0.5, -0.5, 0.5, 0.5], "near": 1e-5, "far": "infinity"})"),
            "depth camera")
            .camera;
    for (const bool cast : {false, true}) {
      const Image image = cast ? raycast(scene, camera, {16, 16}, 1) : raster(scene, camera, {16, 16}, 1);
      int red = 0;
      for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) red += image.at(x, y).r > 0.5f && image.at(x, y).g < 0.5f;
      (cast ? worstRaycast : worstRaster) = std::min(cast ? worstRaycast : worstRaster, red / 256.0);
    }
  }
  record("depth range", "near 1e-5, far infinity; two surfaces 1e-5·z apart, z = 1e-4 … 1e6",
         "the nearer surface covers 100 % of pixels (raster, ray cast)",
         cat(sig(100 * worstRaster), " %, ", sig(100 * worstRaycast), " % at the worst depth"),
         worstRaster == 1.0 && worstRaycast == 1.0);
}

void distanceFromOrigin(const Scene& rowsScene) {
  const Camera camera = physical(R"(, "focus_distance": 4)");
  const ImageSize size{96, 64};
  const Image rasterAtOrigin = raster(rowsScene, camera, size, 4);
  const Image castAtOrigin = raycast(rowsScene, camera, size, 4);
  for (const double distance : {1e3, 1e4, 1e5, 1e6, 1e7, 1e8}) {
    const glm::dvec3 offset(distance, 0.25 * distance, -0.5 * distance);
    const Scene far = moved(rowsScene, offset);
    Camera c = camera;
    c.view.vrp += offset;
    const double r = psnr(raster(far, c, size, 4), rasterAtOrigin);
    const double k = psnr(raycast(far, c, size, 4), castAtOrigin);
    record("distance from the origin", cat("rows and its camera moved by ", sig(distance)),
           "each renderer vs itself at the origin ≥ 50 dB", cat("raster ", dB(r), ", ray cast ", dB(k)),
           r >= 50.0 && k >= 50.0);
  }
}

// The scene and its camera scaled together (a pinhole: the picture does not change): Embree's float
// triangle test underflows below about 1e-13 unless the ray caster rescales its geometry.
void sceneSize(const Scene& rowsScene) {
  const ImageSize size{96, 64};
  const Camera camera = physical(R"(, "focus_distance": "infinity")");
  const Image rasterAtOne = raster(rowsScene, camera, size, 1);
  const Image castAtOne = raycast(rowsScene, camera, size, 4);
  for (const double scale : {1e-30, 1e-12, 1e6}) {
    Scene small = rowsScene;
    for (Instance& instance : small.instances)
      instance.worldFromModel = glm::scale(glm::dmat4(1.0), glm::dvec3(scale)) * instance.worldFromModel;
    small.bounds = computeBounds(small);
    const Camera c =
        parseCameraJson(cat(R"({"eye": [0, )", scale, ", ", 3 * scale, R"(], "target": [0, )", 0.55 * scale, ", ",
                            -2 * scale, R"(], "focal_length_mm": 35, "focus_distance": "infinity"})"),
                        "stability camera")
            .camera;
    const double r = psnr(raster(small, c, size, 1), rasterAtOne);
    const double k = psnr(raycast(small, c, size, 4), castAtOne);
    record("scene size", cat("rows and its pinhole camera scaled by ", sig(scale)),
           "each renderer vs itself at scale 1 ≥ 40 dB", cat("raster ", dB(r), ", ray cast ", dB(k)),
           r >= 40.0 && k >= 40.0);
  }
}

void focus(const Scene& rowsScene) {
  const ImageSize size{96, 64};
  const double f = 0.035;
  const Camera infinity = physical(R"(, "f_number": 2.8, "focus_distance": "infinity")");
  const Image rasterInf = raster(rowsScene, infinity, size, 16);
  const Image castInf = raycast(rowsScene, infinity, size, 16);
  for (const double z : {1e6, 1e15, 1e300}) {
    const Camera c = physical(cat(R"(, "f_number": 2.8, "focus_distance": )", z));
    const double r = psnr(raster(rowsScene, c, size, 16), rasterInf);
    const double k = psnr(raycast(rowsScene, c, size, 16), castInf);
    const double bound = z >= 1e15 ? 60.0 : 40.0;
    record("focus distance", cat("f/2.8 focused at ", sig(z), " (the same samples as at infinity)"),
           cat("vs focus at infinity ≥ ", sig(bound), " dB"), cat("raster ", dB(r), ", ray cast ", dB(k)),
           r >= bound && k >= bound);
  }
  // Just beyond the focal length the image distance is huge and the field of view tiny; the
  // renderers must still agree (and give finite numbers).
  for (const auto& [z, label] :
       {std::pair{f * (1.0 + 1e-6), "f·(1 + 1e-6)"}, std::pair{f * 1.01, "1.01 f"}, std::pair{0.5, "0.5 (14.3 f)"}}) {
    const Camera c = physical(cat(R"(, "f_number": 2.8, "focus_distance": )", z));
    const Image a = raster(rowsScene, c, size, 64), b = raycast(rowsScene, c, size, 64);
    const double p = psnr(a, b);
    record("focus distance", cat("f/2.8 (f = 35 mm) focused at ", label),
           "finite; raster (64 views) vs ray cast (64 spp) ≥ 25 dB",
           cat(finite(a) && finite(b) ? "finite, " : "NOT FINITE, ", dB(p)), finite(a) && finite(b) && p >= 25.0);
  }
  for (const double z : {f, 0.5 * f}) {
    const std::string m = refusal([&] { physical(cat(R"(, "f_number": 2.8, "focus_distance": )", z)); });
    record("focus distance", cat("focused at ", sig(z / f), " f (no real image)"), "refused in one line", shortened(m),
           oneLine(m));
  }
}

void fNumber(const Scene& rowsScene) {
  const ImageSize size{96, 64};
  const Image pinhole = raster(rowsScene, physical(R"(, "focus_distance": 2)"), size, 64);
  for (const double n : {0.5, 2.8, 1000.0}) {
    const Camera c = physical(cat(R"(, "focus_distance": 2, "f_number": )", n));
    const Image a = raster(rowsScene, c, size, 64), b = raycast(rowsScene, c, size, 64);
    const double p = psnr(a, b);
    if (n == 1000.0) {
      const double q = psnr(a, pinhole);
      record("f-number", "f/1000", "vs the pinhole ≥ 45 dB; raster vs ray cast ≥ 25 dB", cat(dB(q), "; ", dB(p)),
             q >= 45.0 && p >= 25.0);
    } else {
      record("f-number", cat("f/", sig(n)), "finite; raster (64 views) vs ray cast (64 spp) ≥ 25 dB",
             cat(finite(a) && finite(b) ? "finite, " : "NOT FINITE, ", dB(p)), finite(a) && finite(b) && p >= 25.0);
    }
  }
}

void sampleCounts() {
  // A constant unlit colour fills the view: every accumulated view adds the same value, so the
  // mean must be that value exactly but for float rounding.
  Scene scene;
  const glm::vec3 colour(0.37f, 0.5f, 0.81f);
  addUnlitQuad(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -2)), 10, 10, colour);
  scene.bounds = computeBounds(scene);
  Camera c =
      parseCameraJson(
          R"({"vrp": [0, 0, 0], "vpn": [0, 0, 1], "prp": [0, 0, 1], "window": [-0.5, -0.5, 0.5, 0.5], "aperture_radius": 0.01})",
          "constant camera")
          .camera;
  const std::vector<int> counts = {1024, 4096, 65536};
  for (const int n : counts) {
    const Image image = raster(scene, c, {8, 8}, n);
    double worst = 0.0;
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x)
        for (int ch = 0; ch < 3; ++ch)
          worst = std::max(worst, std::abs(static_cast<double>(image.at(x, y)[ch]) - colour[ch]));
    record("sample count", cat(n, " accumulated views of a constant colour"), "largest abs(mean − exact) ≤ 1e-4",
           sig(worst), worst <= 1e-4, BareNumbers::ColourDifference);
  }
}

void distortion(const Scene& rowsScene) {
  const ImageSize size{96, 64};
  // The window's farthest corner at normalised (distorted) radius c; a pure k1 < 0 folds where
  // d(r(1 + k1 r²))/dr = 0, r = 1/√(−3k1), whose distorted radius is (2/3)·r. The fold enters the
  // image when (2/3)/√(−3k1) < c, i.e. for k1 < −(2/(3c))²/3.
  const Camera base = physical(R"(, "focus_distance": 4)");
  const double c = normalisedWindow(base.view).cornerRadius();
  const double k1Fold = -std::pow(2.0 / (3.0 * c), 2.0) / 3.0;
  for (const double k1 : {0.99 * k1Fold, -0.2, 0.5}) {
    const Camera cam = physical(cat(R"(, "focus_distance": 4, "distortion": {"k1": )", k1, "}"));
    const Image a = raster(rowsScene, cam, size, 16), b = raycast(rowsScene, cam, size, 16);
    const double p = psnr(a, b);
    record("distortion", cat("k1 = ", sig(k1), k1 == 0.99 * k1Fold ? " (fold at 99 % of the corner)" : ""),
           "raster (16 views) vs ray cast (16 spp) ≥ 30 dB", dB(p), finite(a) && finite(b) && p >= 30.0);
  }
  {
    const Camera cam = physical(R"(, "focus_distance": 4, "distortion": {"k1": 2, "k2": -2})");
    const Image a = raster(rowsScene, cam, size, 16), b = raycast(rowsScene, cam, size, 16);
    const double p = psnr(a, b);
    record("distortion", "k1 = 2, k2 = −2 (folds only beyond the image)", "raster vs ray cast ≥ 30 dB", dB(p),
           finite(a) && finite(b) && p >= 30.0);
  }
  const std::string m =
      refusal([&] { physical(cat(R"(, "focus_distance": 4, "distortion": {"k1": )", 1.01 * k1Fold, "}")); });
  record("distortion", cat("k1 = ", sig(1.01 * k1Fold), " (the fold 1 % inside the corner)"), "refused in one line",
         shortened(m), oneLine(m));
}

// A lecture-form camera as JSON.
Camera lecture(const std::string& body) { return parseCameraJson("{" + body + "}", "stability lecture camera").camera; }

// Renders `camera` with both renderers; a refusal in one line also counts as handled.
struct References {
  Image raster, raycast;
};

void bothOrRefused(const std::string& group, const std::string& input, const Scene& scene,
                   const std::function<Camera()>& make, double minimumDb, const References* reference = nullptr,
                   double referenceDb = 60.0) {
  Camera camera;
  const std::string m = refusal([&] { camera = make(); });
  if (!m.empty()) {
    record(group, input, cat("refused in one line, or raster vs ray cast ≥ ", sig(minimumDb), " dB"),
           cat("refused: ", shortened(m)), oneLine(m));
    return;
  }
  const ImageSize size{96, 64};
  Image a, b;
  const std::string r = refusal([&] {
    a = raster(scene, camera, size, 16);
    b = raycast(scene, camera, size, 16);
  });
  if (!r.empty()) {
    record(group, input, "refused in one line, or rendered", cat("refused at render: ", shortened(r)), oneLine(r));
    return;
  }
  if (const char* dir = std::getenv("LENSLAB_STABILITY_IMAGES")) {
    writeImage(fs::path(dir) / cat(rows.size(), "-raster.png"), a);
    writeImage(fs::path(dir) / cat(rows.size(), "-raycast.png"), b);
  }
  const double p = psnr(a, b);
  std::string measured = cat(finite(a) && finite(b) ? "" : "NOT FINITE, ", blank(a) || blank(b) ? "BLANK, " : "",
                             "raster vs ray cast ", dB(p));
  bool ok = finite(a) && finite(b) && !blank(a) && !blank(b) && p >= minimumDb;
  if (reference) {
    const double q = psnr(a, reference->raster), s = psnr(b, reference->raycast);
    measured += cat("; vs reference: raster ", dB(q), ", ray cast ", dB(s));
    ok = ok && q >= referenceDb && s >= referenceDb;
  }
  record(group, input,
         cat("raster vs ray cast ≥ ", sig(minimumDb), " dB",
             reference ? cat("; each vs its reference ≥ ", sig(referenceDb), " dB") : ""),
         measured, ok);
}

void degenerateCameras(const Scene& rowsScene) {
  const std::string g = "near-degenerate camera";
  for (const double angle : {1e-6, 1e-9}) {
    bothOrRefused(
        g, cat("VUP ", sig(angle), " rad from VPN"), rowsScene,
        [&] {
          return lecture(cat(R"("vrp": [0, 0.5, -2], "vpn": [0, 0, 1], "vup": [0, )", std::sin(angle), ", ",
                             std::cos(angle), R"(], "prp": [0, 0, 5], "window": [-1.5, -1, 1.5, 1], "near": 0.05)"));
        },
        30.0);
  }
  // The window scaled with the PRP's distance: the same picture from the same point.
  const auto scaled = [](double w) {
    const double d = 5.0 * w / 3.0;  // window 3 wide at distance 5, scaled to w wide
    return lecture(cat(R"("vrp": [0, 0.5, )", 3.0 - d, R"(], "vpn": [0, 0, 1], "prp": [0, 0, )", d, R"(], "window": [)",
                       -0.5 * w, ", ", -w / 3.0, ", ", 0.5 * w, ", ", w / 3.0, R"(], "near": 0.05)"));
  };
  const References reference{raster(rowsScene, scaled(3.0), {96, 64}, 16),
                             raycast(rowsScene, scaled(3.0), {96, 64}, 16)};
  for (const double w : {1e-9, 1e-3, 1e3, 1e6})
    bothOrRefused(
        g, cat("window ", sig(w), " wide (PRP distance scaled with it; reference 3 wide)"), rowsScene,
        [&] { return scaled(w); }, 30.0, &reference, 60.0);
  for (const double n : {1e-9, 1e-4, 1e-3, 1e3, 1e9}) {
    // A PRP n from the view plane through the middle of the rows: from 1e9 away a telephoto.
    bothOrRefused(
        g, cat("PRP n = ", sig(n)), rowsScene,
        [&] {
          return lecture(
              cat(R"("vrp": [0, 0.5, -2], "vpn": [0, 0.2, 1], "prp": [0, 0, )", n, R"(], "window": [-3, -2, 3, 2])"));
        },
        30.0);
  }
  {
    // At PRP n = 1e9 the projection is all but parallel: compare with the parallel projection.
    const Camera parallel =
        lecture(R"("projection": "parallel", "vrp": [0, 0.5, -2], "vpn": [0, 0.2, 1], "prp": [0, 0, 1e9],
                                       "window": [-3, -2, 3, 2], "near": 999999950, "far": 1000000050)");
    const References ref{raster(rowsScene, parallel, {96, 64}, 16), raycast(rowsScene, parallel, {96, 64}, 16)};
    bothOrRefused(
        g, "PRP n = 1e9 vs the parallel projection", rowsScene,
        [&] {
          return lecture(R"("vrp": [0, 0.5, -2], "vpn": [0, 0.2, 1], "prp": [0, 0, 1e9], "window": [-3, -2, 3, 2])");
        },
        30.0, &ref, 30.0);
  }
  // Oblique parallel: the DOP 89.99° from the view-plane normal.
  bothOrRefused(
      g, "oblique parallel, DOP 89.99° from the normal", rowsScene,
      [&] {
        // Tilted toward the floor, so that the nearly grazing rays meet it along a strip at z ≈ −2.
        const double t = std::tan((90.0 - 0.01) * std::numbers::pi / 180.0);
        return lecture(cat(R"("projection": "parallel", "vrp": [0, 0.5, -2], "vpn": [0, 0, 1], "prp": [0, )", 5.0 * t,
                           R"(, 5], "window": [-3, -2, 3, 2], "near": -40, "far": 40)"));
      },
      30.0);
  bothOrRefused(
      g, "parallel with near = -1", rowsScene,
      [&] {
        return lecture(
            R"("projection": "parallel", "vrp": [0, 0.5, 0.5], "vpn": [0, 0.3, 1], "prp": [0, 0, 1], "window": [-3, -2, 3, 2], "near": -1, "far": 60)");
      },
      30.0);
}

void imageSizes(const Scene& rowsScene, bool longRun) {
  const Camera camera = prepared(physical(R"(, "focus_distance": 4)"), rowsScene);
  const Image a = raster(rowsScene, camera, {1, 1}, 1024), b = raycast(rowsScene, camera, {1, 1}, 1024);
  const double diff = compareImages(a, b, 0.0).maxAbs;
  record("image size", "1 × 1", "raster (1024 views) vs ray cast (1024 spp) within 0.01", sig(diff),
         finite(a) && finite(b) && diff <= 0.01, BareNumbers::ColourDifference);
  // Tiles: the same samples through sub-windows of the same view plane must give the same image.
  const Camera lens = prepared(physical(R"(, "focus_distance": 2, "f_number": 2.8)"), rowsScene);
  for (const ImageSize size : {ImageSize{600, 400}, ImageSize{2400, 1600}}) {
    // Planning is cheap: a skipped row is still named, so that the doc check knows it.
    const FramePlan plan = makeFramePlan(rowsScene, lens, size, PlanOptions{AperturePattern::Concentric, 16, 16, 3});
    const TilePlan tiles = planTiles(lens, size, plan, queryRenderTargetLimits(), size.widthPx / 5);
    const std::string input =
        cat(size.widthPx, " × ", size.heightPx, " f/2.8 in ", tiles.tiles.size(), " forced tiles");
    const std::string bound = "tiled vs untiled (same samples) ≥ 60 dB";
    if (size.widthPx > 600 && !longRun) {
      skipped.push_back({"image size", input, bound, "", true});
      continue;
    }
    Renderer renderer(rowsScene);
    const Image whole = renderer.render(lens, plan, size);
    const Image tiled = renderTiled(renderer, lens, plan, size, tiles);
    const double p = psnr(tiled, whole);
    record("image size", input, bound, dB(p), finite(tiled) && p >= 60.0);
  }
  // The largest image the tiles allow is kMaxImagePixels; 20000 wide is what docs/usage.md's image
  // sizes measure. Every pixel must arrive once and be finite.
  const ImageSize big = resolveImageSize(camera, 20000, std::nullopt);
  const FramePlan plan = makeFramePlan(rowsScene, camera, big, PlanOptions{AperturePattern::Concentric, 1, 1, 3});
  const TilePlan tiles = planTiles(camera, big, plan, queryRenderTargetLimits(), 0);
  const std::string input =
      cat(big.widthPx, " × ", big.heightPx, " in ", tiles.tiles.size(), " tiles (GL's limit: one 4096² target)");
  const std::string bound = "every pixel once, finite";
  if (!longRun) {
    skipped.push_back({"image size", input, bound, "", true});
    return;
  }
  Renderer renderer(rowsScene);
  std::int64_t pixels = 0;
  bool allFinite = true;
  renderTiles(renderer, camera, plan, big, tiles, [&](const PixelRect&, const Image& block) {
    pixels += std::int64_t{block.width} * block.height;
    allFinite = allFinite && finite(block);
  });
  record("image size", input, bound,
         cat(pixels, " of ", big.pixelCount(), " pixels", allFinite ? ", finite" : ", NOT FINITE"),
         allFinite && pixels == big.pixelCount());
}

// A glTF file with one triangle whose apex is at (0, y, −5): in view it is a band 4 wide, its sides
// all but vertical however far the apex is.
fs::path triangleFile(const fs::path& dir, double y) {
  const float v[9] = {-2.0f, -2.0f, -5.0f, 2.0f, -2.0f, -5.0f, 0.0f, static_cast<float>(y), -5.0f};
  std::string bytes(reinterpret_cast<const char*>(v), sizeof v);
  static const char* kB64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string b64;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned n = (static_cast<unsigned char>(bytes[i]) << 16) |
                       (i + 1 < bytes.size() ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0) |
                       (i + 2 < bytes.size() ? static_cast<unsigned char>(bytes[i + 2]) : 0);
    b64 += kB64[(n >> 18) & 63];
    b64 += kB64[(n >> 12) & 63];
    b64 += i + 1 < bytes.size() ? kB64[(n >> 6) & 63] : '=';
    b64 += i + 2 < bytes.size() ? kB64[n & 63] : '=';
  }
  const float lo[3] = {-2.0f, -2.0f, -5.0f}, hi[3] = {2.0f, v[7], -5.0f};
  const fs::path file = dir / cat("triangle-", sig(y), ".gltf");
  std::ofstream(file) << cat(
      R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [)",
      lo[0], ", ", lo[1], ", ", lo[2], "], \"max\": [", hi[0], ", ", hi[1], ", ", hi[2], R"(]}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,)",
      b64, R"("}]})");
  return file;
}

void vertexValues() {
  const fs::path dir = fs::temp_directory_path() / cat("lenslab-stability-", ::getpid());
  fs::create_directories(dir);
  const Camera camera = lecture(R"("vrp": [0, 0, 0], "vpn": [0, 0, 1], "prp": [0, 0, 1], "window": [-1, -1, 1, 1])");
  for (const double x : {1e6, 1e12, 1e15}) {
    const Scene scene = loadGltf(triangleFile(dir, x));
    const Image a = raster(scene, camera, {64, 64}, 16), b = raycast(scene, camera, {64, 64}, 16);
    const double p = psnr(a, b);
    record("vertex values", cat("a triangle with its apex at y = ", sig(x)), "raster vs ray cast ≥ 30 dB",
           cat(blank(a) || blank(b) ? "BLANK, " : "", dB(p)),
           finite(a) && finite(b) && !blank(a) && !blank(b) && p >= 30.0);
  }
  for (const double x : {1e16, 1e38}) {
    const std::string m = refusal([&] { loadGltf(triangleFile(dir, x)); });
    record("vertex values", cat("a vertex at y = ", sig(x), " (beyond ±", sig(kMaxWorldCoordinate), ")"),
           "refused in one line", shortened(m.substr(m.find(": ") + 2)), oneLine(m));
  }
  fs::remove_all(dir);
}

// ---- lens-effect extremes (fx-framing): planes of focus inside the focal length, distortion
// beyond what the raster can place at the image's resolution ----
void lensExtremes(const Scene& rowsScene) {
  for (const char* effect :
       {R"("chromatic": {"focus_distance_red": 1e-200})", R"("field_curvature": {"corner_focus_distance": 1e-200})"}) {
    const std::string m = refusal([&] { physical(cat(R"(, "focus_distance": 2, "f_number": 1.4, )", effect)); });
    record("lens extremes", cat(effect, " on a 35 mm lens"), "refused in one line", shortened(m), oneLine(m));
  }
  const auto distorted = [&](double k1) {
    return prepared(physical(cat(R"(, "focus_distance": 4, "distortion": {"k1": )", k1, "}")), rowsScene);
  };
  const std::string m = refusal([&] { makeFramePlan(rowsScene, distorted(1e6), {64, 43}); });
  record("lens extremes", "distortion k1 = 1e6 at 64 px (the raster's samples would land 200 px astray)",
         "refused in one line", shortened(m), oneLine(m));
  // Just inside the limit at this width: magnified about 10× at the corners, so the raster needs
  // many views for every pixel to receive samples, but it converges to the ray caster's image.
  const ImageSize size{96, 64};
  const Camera c = distorted(100.0);
  const Image a = raster(rowsScene, c, size, 256), b = raycast(rowsScene, c, size, 256);
  const double p = psnr(a, b);
  record("lens extremes", "distortion k1 = 100 at 96 px", "raster (256 views) vs ray cast (256 spp) ≥ 30 dB",
         cat(dB(p), " (samples ", sig(ThinLensMap(c, size).forwardLinearisationErrorPx()), " px from the linear map)"),
         finite(a) && finite(b) && p >= 30.0);
}

// ---- ends of the scales (fx-scales2): a field of view down to 1e-9 rad, the view plane down to
// the smallest PRP distance the camera takes ----
void scaleExtremes(const Scene& rowsScene) {
  const std::string g = "ends of the scales";
  const ImageSize size{96, 64};
  const auto agree = [&](const std::string& input, const Camera& c, double minimumDb, int samples = 4) {
    const Image a = raster(rowsScene, c, size, samples), b = raycast(rowsScene, c, size, samples);
    const double p = psnr(a, b);
    record(g, input, cat("raster (", samples, " views) vs ray cast (", samples, " spp) ≥ ", sig(minimumDb), " dB"),
           cat(finite(a) && finite(b) ? "" : "NOT FINITE, ", dB(p)), finite(a) && finite(b) && p >= minimumDb);
  };
  // A patch of one colour 5 units away: the raster placed the floor's triangles, 1e8 window
  // widths off-axis, with float's 7 digits and drew a band of sky across the patch. Both images
  // are one colour, so the bound is tight.
  for (const double fov : {1e-7, 1e-9}) {
    // 24 mm of sensor height over the focal length: the vertical field of view in radians.
    agree(cat("a patch of one colour at field of view ", sig(fov), " rad by focal_length_mm ", sig(24.0 / fov)),
          physical(cat(R"(, "focus_distance": "infinity", "focal_length_mm": )", 24.0 / fov)), 50.0);
    agree(cat("a patch of one colour at field of view ", sig(fov), " rad by sensor_mm (35 mm lens)"),
          physical(cat(R"(, "focus_distance": "infinity", "sensor_mm": [)", 1.5 * 35.0 * fov, ", ", 35.0 * fov, "]")),
          50.0);
  }
  {
    const std::string m = refusal([&] { physical(R"(, "focus_distance": "infinity", "focal_length_mm": 2.4e14)"); });
    record(g, "field of view 1e-13 rad by focal_length_mm 2.4e+14 (below the narrowest drawn, 1e-12 rad)",
           "refused in one line", shortened(m), oneLine(m));
  }
  // A box's corner at the centre (its top and right edges and the floor beyond): under a narrow
  // field the projection is all but affine, so the picture does not depend on the field of view.
  // The ray caster finds edges in Embree's float (about 1e-7 of the distance), so its image at
  // 1e-5 rad is the reference for the raster's at 1e-7 and 1e-9 rad.
  const auto corner = [&](double fov) {
    return physical(
        cat(R"(, "target": [1, 0.5, -0.75], "focus_distance": "infinity", "focal_length_mm": )", 24.0 / fov));
  };
  const Image reference = raycast(rowsScene, corner(1e-5), size, 4);
  agree("a box corner at field of view 1e-5 rad", corner(1e-5), 30.0);
  for (const double fov : {1e-7, 1e-9}) {
    const Image a = raster(rowsScene, corner(fov), size, 4);
    const double p = psnr(a, reference);
    record(g, cat("a box corner at field of view ", sig(fov), " rad (raster)"), "vs the ray cast at 1e-5 rad ≥ 30 dB",
           cat(finite(a) ? "" : "NOT FINITE, ", dB(p)), finite(a) && !blank(a) && p >= 30.0);
  }
  // The view plane (and the window with it) brought to n of the PRP, the PRP in the middle of the
  // rows: the ray caster built its rays from two world points equal in all but their last digits.
  // Both must render here: a refusal counts as a failure down to the smallest accepted distance.
  for (const double n : {1e-15, kMinPrpDistance}) {
    const std::string input =
        cat("PRP n = ", sig(n), n == kMinPrpDistance ? " (the smallest accepted)" : "", ", window 6n × 4n");
    const std::string m = refusal([&] {
      agree(input,
            lecture(cat(R"("vrp": [0, 0.5, -2], "vpn": [0, 0.2, 1], "prp": [0, 0, )", n, R"(], "window": [)", -3 * n,
                        ", ", -2 * n, ", ", 3 * n, ", ", 2 * n, "]")),
            30.0, 16);
    });
    if (!m.empty())
      record(g, input, "raster (16 views) vs ray cast (16 spp) ≥ 30 dB", cat("refused: ", shortened(m)), false);
  }
  const double below = 0.1 * kMinPrpDistance;
  const std::string m = refusal([&] {
    lecture(cat(R"("vrp": [0, 0.5, -2], "vpn": [0, 0.2, 1], "prp": [0, 0, )", below, R"(], "window": [)", -3 * below,
                ", ", -2 * below, ", ", 3 * below, ", ", 2 * below, "]"));
  });
  record(g, cat("PRP n = ", sig(below)), "refused in one line", shortened(m), oneLine(m));
}

// The measured cell as the table writes it: a failed bound says so.
std::string measuredCell(const Row& r) { return r.measured + (r.ok ? "" : " **(fails)**"); }

std::string markdown() {
  using stability::escapeCell;
  std::ostringstream s;
  s << "| | case | bound | measured |\n|---|---|---|---|\n";
  std::string group;
  for (const Row& r : rows) {
    s << "| " << (r.group != group ? r.group : "") << " | " << escapeCell(r.input) << " | " << escapeCell(r.bound)
      << " | " << escapeCell(measuredCell(r)) << " |\n";
    group = r.group;
  }
  return s.str();
}

// Whether `doc`'s table (between its stability markers) still describes this run: every row this
// run produced is there, found by its group, case and bound, with its measured figures within the
// tolerances of TableCheck.h; and every row there is one this run produced or skipped. The table
// is this program's output, so a row that fails here means the doc no longer tells the truth.
int checkDoc(const fs::path& doc, const std::vector<stability::TableRow>& documented) {
  const auto same = [](const stability::TableRow& d, const Row& r) {
    return d.group == r.group && d.input == r.input && d.bound == r.bound;
  };
  const auto rowName = [](const std::string& group, const std::string& input, const std::string& bound) {
    return cat(group, " | ", input, " | ", bound);
  };
  int stale = 0;
  for (const Row& r : rows) {
    const auto d = std::find_if(documented.begin(), documented.end(), [&](const auto& x) { return same(x, r); });
    if (d == documented.end()) {
      std::cerr << doc.string() << ": missing row: " << rowName(r.group, r.input, r.bound) << " | " << measuredCell(r)
                << "\n";
      ++stale;
    } else if (const std::string why = stability::cellDifference(d->measured, measuredCell(r), r.bare); !why.empty()) {
      std::cerr << doc.string() << ": " << rowName(r.group, r.input, r.bound) << ": " << why << "\n";
      ++stale;
    }
  }
  for (const stability::TableRow& d : documented) {
    const auto known = [&](const std::vector<Row>& list) {
      return std::any_of(list.begin(), list.end(), [&](const Row& r) { return same(d, r); });
    };
    if (!known(rows) && !known(skipped)) {
      std::cerr << doc.string() << ": a row this program does not produce: " << rowName(d.group, d.input, d.bound)
                << "\n";
      ++stale;
    }
  }
  if (stale)
    std::cerr
        << doc.string() << ": " << stale << (stale == 1 ? " row" : " rows")
        << " of the stability table not matching this run; regenerate the table with tools/update-stability-table.sh"
        << " (it runs lenslab_stability --long and rewrites the table)\n";
  else
    std::cout << doc.string() << ": the stability table matches this run (" << rows.size() << " rows compared, "
              << skipped.size()
              << " slow rows not run; figures within the tolerances of tests/stability/TableCheck.h)\n";
  return stale ? 1 : 0;
}

int run(int argc, char** argv) {
  bool longRun = false;
  std::string markdownFile, doc;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--long")
      longRun = true;
    else if (a == "--markdown" && i + 1 < argc)
      markdownFile = argv[++i];
    else if (a == "--check-doc" && i + 1 < argc)
      doc = argv[++i];
    else {
      std::cerr << "usage: lenslab_stability [--long] [--markdown FILE] [--check-doc docs/stability.md]\n";
      return 2;
    }
  }
  // The doc is read first, so that a wrong path fails before the run rather than after it.
  std::vector<stability::TableRow> documented;
  if (!doc.empty()) {
    std::ifstream in(doc);
    if (!in)
      throw InputError(
          cat("--check-doc ", doc, ": cannot read the file; give the page that holds the table (docs/stability.md)"));
    std::stringstream text;
    text << in.rdbuf();
    documented = stability::parseDocTable(text.str(), doc);
  }
  const auto context = createHeadlessContext(Backend::OSMesa);
  // Which SIMD paths made these figures (llvmpipe names its vector width; Embree's is forced here).
  const char* embree = std::getenv("LENSLAB_EMBREE_CONFIG");
  std::cout << "GL: " << context->renderer() << "; Embree config: " << (embree && *embree ? embree : "(default)")
            << "\n";
  const auto start = std::chrono::steady_clock::now();
  const Scene rowsScene = loadGltf(kAssets / "rows/rows.gltf");
  depthRange();
  distanceFromOrigin(rowsScene);
  sceneSize(rowsScene);
  focus(rowsScene);
  fNumber(rowsScene);
  sampleCounts();
  distortion(rowsScene);
  degenerateCameras(rowsScene);
  imageSizes(rowsScene, longRun);
  vertexValues();
  lensExtremes(rowsScene);
  scaleExtremes(rowsScene);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  int failed = 0;
  for (const Row& r : rows) failed += !r.ok;
  std::cout << rows.size() << " rows, " << failed << " failed, " << std::lround(seconds) << " s\n";
  if (!markdownFile.empty()) std::ofstream(markdownFile) << markdown();
  const int docResult = doc.empty() ? 0 : checkDoc(doc, documented);
  return failed == 0 && docResult == 0 ? 0 : 1;
}

}  // namespace
}  // namespace lenslab

int main(int argc, char** argv) {
  try {
    return lenslab::run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "lenslab_stability: " << e.what() << "\n";
    return 1;
  }
}
