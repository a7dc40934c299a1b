// `lenslab diagram`: the lecture's picture of the camera from outside, headless. The scene as a
// pinhole sees it from a point beside the camera, dimmed, with the camera drawn over it as the
// interactive view's outside view draws it (view/LectureDiagram.h): the PRP, the window on the
// view plane (the plane of focus), the view volume through the window's corners, and with an
// aperture the aperture disk, its sample points and rays from them through one window point.
#include "app/CliOptions.h"
#include "app/Commands.h"
#include "core/Error.h"
#include "core/NumberInput.h"
#include "core/Text.h"
#include "gl/GlContext.h"
#include "camera/Projection.h"
#include "io/AtomicFile.h"
#include "io/ImageFile.h"
#include "io/OutputPath.h"
#include "lens/AperturePattern.h"
#include "plan/CameraSelection.h"
#include "plan/FramePlan.h"
#include "plan/SceneChoice.h"
#include "render/LineDrawer.h"
#include "render/Renderer.h"
#include "plan/UserOptions.h"
#include "scene/GltfLoader.h"
#include "view/LectureDiagram.h"
#include "view/ViewerModel.h"

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace lenslab {
namespace {

namespace fs = std::filesystem;

constexpr double kRadiansPerDegree = 0.017453292519943295;
// The scene under the diagram is dimmed, as the interactive view dims it, so that the lines read.
constexpr float kSceneDimming = 0.45f;

struct DiagramOptions {
  std::string scene;
  std::string cameraFile;
  std::string out = "diagram.png";
  std::optional<int> width;
  std::optional<int> height;
  LensOptions lens;
  CameraOptions camera;
  std::optional<double> timeSeconds;
  std::optional<glm::vec3> background;
  view::OutsideOrbit orbit;  // where the picture is taken from; degrees on the command line
  double azimuthDeg = 0.0;
  double elevationDeg = 0.0;
  std::string apertureScale = "auto";
  std::string backend = "osmesa";
  bool quiet = false;
};

// --aperture-scale: auto (the disk a quarter of the window's height across) or a factor ≥ 1.
double apertureScaleFor(const std::string& text, const Camera& camera) {
  if (text == "auto") return view::readableApertureScale(camera);
  return readNumber("--aperture-scale", text, {.min = 1.0, .max = 1e9, .unit = {}});
}

// The diagram's lines in the image's linear light: they are given in display (sRGB) colours.
std::vector<LineSegment> linearSegments(const std::vector<view::DiagramLine>& lines) {
  std::vector<LineSegment> out;
  for (const view::DiagramLine& l : lines)
    out.push_back(
        {l.from, l.to, glm::vec3(linearFromSrgb(l.color.r), linearFromSrgb(l.color.g), linearFromSrgb(l.color.b))});
  return out;
}

int runDiagram(DiagramOptions& o) {
  const fs::path out = o.out;
  checkOutputPath(out, OutputKind::Image, "--out");
  const PlanOptions planOptions = toPlanOptions(o.lens);
  const auto [scenePath, cameraPath] =
      resolveSceneAndCamera(o.scene, o.cameraFile, o.camera.namesBaseCamera() ? "" : "camera.json");
  Scene scene = loadGltf(scenePath);
  applyBackground(scene, o.background);
  for (const std::string& w : poseForOneImage(scene, o.camera.animation, o.timeSeconds))
    std::cerr << "lenslab: warning: " << w << "\n";
  const SelectedCamera selected = applyLensOptions(chooseCamera(scene, cameraPath, o.camera, 0.0), o.lens);
  const Camera& camera = selected.camera;
  // The picture's size: as `render` sizes the camera's own image, unless given.
  const ImageSize size = resolveImageSize(camera, o.width, o.height);

  o.orbit.azimuthRadians = o.azimuthDeg * kRadiansPerDegree;
  o.orbit.elevationRadians = o.elevationDeg * kRadiansPerDegree;
  const Camera outside = o.orbit.cameraFor(camera, static_cast<double>(size.widthPx) / size.heightPx);
  // The aperture samples a render of this camera would take: the plan's (from the scene's bounds;
  // `render` may take fewer after its pre-pass sees what is in view).
  const FramePlan plan = makeFramePlan(scene, camera, size, planOptions);
  const std::vector<LensSample> samples =
      camera.lens.isPinhole() ? std::vector<LensSample>{}
                              : makeApertureSamples(planOptions.pattern, plan.apertureSamples, planOptions.seed);
  view::DiagramStyle style;
  style.apertureScale = apertureScaleFor(o.apertureScale, camera);
  const std::vector<view::DiagramLine> lines =
      view::lectureDiagram(camera, samples, static_cast<int>(samples.size()), style);

  const std::unique_ptr<GlContext> context = createHeadlessContext(o.backend == "egl" ? Backend::Egl : Backend::OSMesa);
  Renderer renderer(scene);
  const gl::RenderTarget& target = renderer.renderPinhole(outside, size);
  Image picture = target.readColor();
  LineDrawer drawer;
  const Image drawn = drawer.drawOffscreen(linearSegments(lines), clipFromWorld(outside.view), size);
  for (std::size_t i = 0; i < picture.rgba.size(); i += 4) {
    const bool line = drawn.rgba[i + 3] > 0.0f;
    for (std::size_t c = 0; c < 3; ++c)
      picture.rgba[i + c] = line ? drawn.rgba[i + c] : kSceneDimming * picture.rgba[i + c];
    picture.rgba[i + 3] = 1.0f;
  }

  OutputSet outputs;
  writeImage(outputs, out, picture);
  outputs.commit();
  if (!o.quiet)
    std::cerr << "lenslab: wrote " << out.string() << " (" << size.widthPx << "x" << size.heightPx
              << ", the camera from outside: azimuth " << o.azimuthDeg << " deg, elevation " << o.elevationDeg
              << " deg, aperture drawn " << style.apertureScale << "x)\n";
  return 0;
}

}  // namespace

std::function<int()> addDiagramCommand(CLI::App& app) {
  auto o = std::make_shared<DiagramOptions>();
  CLI::App* cmd = app.add_subcommand(
      "diagram",
      "Draw the lecture's picture of the camera from outside: the PRP, the window on the plane of focus, the view "
      "volume, the aperture with its samples and their rays, over the scene");
  cmd->add_option("scene", o->scene, "glTF 2.0 scene (.gltf or .glb); default: the bundled 'rows' scene");
  cmd->add_option("--camera", o->cameraFile,
                  "the camera to draw: a camera JSON (as render's --camera); default: the scene's first glTF camera, "
                  "else an automatic framing");
  cmd->add_option("--out,-o", o->out, "output image: .png (8-bit sRGB) or .exr (linear float)")->capture_default_str();
  cmd->add_option("--width", o->width, "picture width in pixels (default 960; height from the camera's window)")
      ->check(CLI::Range(1, 16384));
  cmd->add_option("--height", o->height, "picture height in pixels")->check(CLI::Range(1, 16384));
  o->azimuthDeg = o->orbit.azimuthRadians / kRadiansPerDegree;
  o->elevationDeg = o->orbit.elevationRadians / kRadiansPerDegree;
  cmd->add_option("--azimuth", o->azimuthDeg,
                  "where the picture is taken from, around the camera: degrees from straight behind it toward its "
                  "right")
      ->check(numberIn({.min = -360.0, .max = 360.0, .unit = "degrees"}))
      ->capture_default_str()
      ->type_name("DEG");
  cmd->add_option("--elevation", o->elevationDeg, "and degrees above the horizon")
      ->check(numberIn({.min = -85.0, .max = 85.0, .unit = "degrees"}))
      ->capture_default_str()
      ->type_name("DEG");
  cmd->add_option("--zoom", o->orbit.zoom,
                  "the distance from the camera, in multiples of 2.2 times its size (the larger of PRP.n and the "
                  "window)")
      ->check(numberIn({.min = 0.05, .max = 50.0, .unit = {}}))
      ->capture_default_str()
      ->type_name("X");
  cmd->add_option("--aperture-scale", o->apertureScale,
                  "draw the aperture enlarged by this factor (at least 1), or auto: a quarter of the window's height "
                  "across (an aperture of millimetres beside a window of metres is a dot)")
      ->capture_default_str()
      ->type_name("X|auto");
  cmd->add_option("--backend", o->backend, "osmesa (CPU, anywhere) or egl (GPU device, else Mesa surfaceless)")
      ->check(CLI::IsMember({"osmesa", "egl"}))
      ->capture_default_str();
  addColmapOptions(*cmd, o->camera);
  addSamplingOptions(*cmd, o->lens);
  addSeedOption(*cmd, o->lens);
  cmd->add_option("--focus-distance", o->lens.focusDistance,
                  "put the plane of focus (where the window is drawn) this far from the PRP (world units, or infinity)")
      ->check(numberOrInfinity({.unit = "world units"}));
  addLensOverrideOptions(*cmd, o->lens);
  addCameraOptions(*cmd, o->camera);
  addBackgroundOption(*cmd, o->background);
  addTimeOption(*cmd, o->timeSeconds, "pose the scene's glTF animations at this time (seconds)");
  cmd->add_flag("--quiet,-q", o->quiet, "print nothing on success");
  return [cmd, o]() { return cmd->parsed() ? runDiagram(*o) : -1; };
}

}  // namespace lenslab
