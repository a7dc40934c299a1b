// lenslab render: one image of a scene through the lecture's camera, rasterized headless.
// lenslab raycast: the same image by the CPU ray-cast reference (same options, plus --spp).
#include "app/AovOption.h"
#include "app/CliOptions.h"
#include "app/ExposureOptions.h"
#include "app/FrameRender.h"
#include "app/LensRequest.h"
#include "app/Commands.h"
#include "app/EnvironmentOptions.h"
#include "app/Stats.h"
#include "app/TiledFile.h"
#include "camera/DepthRange.h"
#include "camera/FocusOnPixel.h"
#include "camera/ImageMap.h"
#include "camera/ImageSize.h"
#include "core/Clock.h"
#include "core/Error.h"
#include "core/Text.h"
#include "gl/GlContext.h"
#include "io/AovChannels.h"
#include "plan/CameraSelection.h"
#include "io/ImageFile.h"
#include "io/OutputPath.h"
#include "io/Progress.h"
#include "plan/FramePlan.h"
#include "raycast/RayCaster.h"
#include "render/RasterDepth.h"
#include "render/Renderer.h"
#include "scene/GltfLoader.h"
#include "scene/SceneAnimation.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <iostream>
#include <memory>
#include <optional>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

enum class Method { Raster, Raycast };

struct RenderOptions {
  Method method = Method::Raster;
  int samplesPerPixel = 64;  // raycast
  std::string scene;
  std::string cameraFile;
  std::string out = "render.png";
  std::optional<int> width;
  std::optional<int> height;
  std::string backend = "osmesa";
  std::string statsFile;
  bool quiet = false;
  LensOptions lens;
  CameraOptions camera;
  std::optional<glm::vec3> background;
  int tileSizePx = 0;                 // render: 0 = tile only when one render target cannot hold the image
  std::optional<double> timeSeconds;  // the glTF animations' pose; none = the rest pose
  AovRequest aovs;                    // --aov, --aov-format, --normal-convention: parsed in runRender
  ExposureOptions exposure;           // PNG output only
  EnvironmentRequest environment;
  std::string lensFile;          // --lens: a prescription (lens/LensPrescription.h)
  double lensTolerancePx = 2.0;  // render --lens: the fitted camera's largest error for the real-time path
};

// The ray caster holds the whole float RGBA image (16 bytes a pixel) in memory.
constexpr std::int64_t kMaxRaycastPixels = std::int64_t{1} << 28;

// The selected AOVs of `map` (the lens the image was rendered with; with --lens the traced lens,
// whichever renderer made the image) from the ray caster; none when none is selected.
AovImages aovsOf(const RayCaster& caster, const ImageMap& map, const AovSelection& aovs) {
  return aovs.any() ? caster.aovImages(map, aovs) : AovImages{};
}

// render's camera after --focus-at (focused on the raster's depth there) and --lens (the thin lens
// fitted for the focus as it now is: the field curvature and the pupil's place follow focus).
// With --lens, `frame` gets the traced lens's map, whose rays the AOVs follow.
Camera refocusAndFit(const RenderOptions& o, const Scene& scene, const SelectedCamera& selected, ImageSize size,
                     Renderer& renderer, const std::optional<FittedLens>& fitted, RunStats& stats,
                     std::unique_ptr<ImageMap>& frame) {
  Camera camera = selected.camera;
  if (o.lens.focusAt) {
    const SelectedCamera focused = focusOnPixel(selected, size, *o.lens.focusAt, rasterDepth(renderer), "--focus-at");
    camera = withDepthRangeFitted(focused.camera, scene.bounds);
    stats.setCamera(focused);
  }
  if (!o.lensFile.empty()) {
    const LensRequest request = lensRequestFor(o.lensFile, selected, camera);
    const FittedLens& fit = fitted && !o.lens.focusAt ? *fitted : fitFor(request);
    // The frame is the real lens's map; the raster draws its real-time form, fitted().
    auto lens = std::make_unique<RealLensMap>(
        lensCameraFor(request), camera, size,
        withDepthRangeFitted(fittedCameraFor(request, fit, camera, o.lensFile), scene.bounds));
    SelectedCamera lensCamera;
    camera = lensCamera.camera = lens->fitted().camera();
    stats.setCamera(lensCamera, focusExplanation(request, fit));
    frame = std::move(lens);
  }
  return camera;
}

// The image, or nothing when it was rendered in tiles and already written, a strip at a time, to
// `out`'s temporary file in `outputs`. `aovImages` gets the selected AOVs (`aovs`) of the
// camera rendered with (refused for a tiled image).
std::optional<Image> rasterize(const RenderOptions& o, const Scene& scene, const SelectedCamera& selected,
                               ImageSize size, const PlanOptions& planOptions, OutputSet& outputs, const fs::path& out,
                               RunStats& stats, ProgressReporter& progress, const DisplaySettings& display,
                               const AovSelection& aovs, AovImages& aovImages,
                               const std::optional<FittedLens>& fitted) {
  auto t = std::chrono::steady_clock::now();
  const std::unique_ptr<GlContext> context = createHeadlessContext(o.backend == "egl" ? Backend::Egl : Backend::OSMesa);
  stats.contextSeconds = secondsSince(t);
  stats.renderer = context->renderer();

  t = std::chrono::steady_clock::now();
  Renderer renderer(scene);
  stats.setupSeconds = secondsSince(t);

  std::unique_ptr<ImageMap> frame;
  const Camera camera = refocusAndFit(o, scene, selected, size, renderer, fitted, stats, frame);
  const auto renderStart = std::chrono::steady_clock::now();
  const FramePlan plan = planFrame(renderer, scene, camera, size, planOptions, stats);
  for (const std::string& w : plan.warnings) std::cerr << "lenslab: warning: " << w << "\n";
  stats.camera = camera.source;

  // Memory bounded by the tile, not the frame (app/TiledFile.h).
  const TilePlan tiles = tilesForFile(camera, size, plan, out, o.tileSizePx);
  if (tiles.tiled && plan.adaptive)
    throw InputError(cat("--target-psnr: ", tiles.why,
                         "; per-tile budgets are not combined with that yet: give a smaller "
                         "--width, or --aperture-samples"));
  if (tiles.tiled && aovs.any())
    throw InputError(cat("--aov ", aovList(aovs), ": ", tiles.why, "; the AOVs are written with an image rendered in ",
                         "one piece: give a smaller --width (and no --tile-size), or use raycast"));
  if (tiles.tiled) {
    renderTiledToFile(renderer, camera, plan, size, tiles, outputs, out, display, stats, progress);
    return std::nullopt;
  }

  Image image = renderPlanned(renderer, camera, plan, size, stats, &progress, o.quiet);
  stats.renderSeconds = secondsSince(renderStart);
  if (aovs.any()) {
    if (!frame) frame = std::make_unique<ThinLensMap>(camera, size);
    aovImages = aovsOf(RayCaster(scene), *frame, aovs);
  }
  return image;
}

Image raycast(const RenderOptions& o, const Scene& scene, const SelectedCamera& selected, ImageSize size,
              RunStats& stats, ProgressReporter& progress, const AovSelection& aovs, AovImages& aovImages) {
  Camera camera = selected.camera;
  if (o.samplesPerPixel < 1) throw InputError(cat("--spp ", o.samplesPerPixel, ": give at least 1 sample per pixel"));
  if (size.pixelCount() > kMaxRaycastPixels)
    throw InputError(cat("--width/--height: raycast holds the whole ", size.widthPx, "x", size.heightPx,
                         " image in memory as float RGBA (", size.pixelCount() * 16 / (1 << 20),
                         " MiB); it takes at most ", kMaxRaycastPixels,
                         " pixels (4 GiB): give a smaller size, or use render, which tiles"));
  auto t = std::chrono::steady_clock::now();
  const RayCaster caster(scene);
  stats.setupSeconds = secondsSince(t);
  stats.renderer = "lenslab ray caster (Embree, TBB)";
  stats.backend = "cpu";
  if (o.lens.focusAt) {
    const SelectedCamera focused = focusOnPixel(
        selected, size, *o.lens.focusAt,
        [&](const Camera& c, ImageSize depthSize, int x, int y) {
          return caster.depthAt(c, {x + 0.5, y + 0.5}, depthSize);
        },
        "--focus-at");
    camera = withDepthRangeFitted(focused.camera, scene.bounds);
    stats.setCamera(focused);
  }
  stats.camera = camera.source;
  stats.plan.apertureSamples = o.samplesPerPixel;
  const RaycastOptions options{o.samplesPerPixel, o.lens.seed};
  const auto onRows = [&](int done, int rows) { progress.update(done, rows); };
  // The traced lens, or the thin lens with its effects: one loop casts either map's rays.
  std::unique_ptr<ImageMap> map;
  std::string rays;
  if (!o.lensFile.empty()) {
    auto frame =
        std::make_unique<RealLensMap>(lensCameraFor(lensRequestFor(o.lensFile, selected, camera)), camera, size);
    stats.plan.samplesWhy = cat(o.samplesPerPixel, " stratified film x exit-pupil samples per pixel (--spp)");
    rays = cat("traced through every surface of ", o.lensFile,
               frame->lens().dispersion() ? ", per channel at 610, 550 and 465 nm" : "");
    map = std::move(frame);
  } else {
    stats.plan.samplesWhy = cat(o.samplesPerPixel, " stratified pixel x lens samples per pixel (--spp)");
    rays = cat("through ", camera.lens.isPinhole() ? "the PRP" : "the thin lens",
               camera.lens.effects.isZero() ? "" : ", each through the inverse lens model (exact)");
    map = std::make_unique<ThinLensMap>(camera, size);
  }
  stats.plan.passes = {{"raycast", cat(o.samplesPerPixel, " rays per pixel ", rays), {}}};
  t = std::chrono::steady_clock::now();
  const Image image = caster.render(*map, options, onRows);
  stats.renderSeconds = secondsSince(t);
  aovImages = aovsOf(caster, *map, aovs);
  return image;
}

// render --lens: the fitted thin lens where its worst error is within --lens-tolerance pixels,
// else the lens traced exactly (as raycast --lens), the aperture samples as rays per pixel: then
// true, with `exact` holding those rays. `fitted` gets the fit.
bool traceLensExactly(const RenderOptions& o, const SelectedCamera& selected, ImageSize size,
                      std::optional<FittedLens>& fitted, RenderOptions& exact) {
  if (o.method != Method::Raster || o.lensFile.empty()) return false;
  const LensRequest request = lensRequestFor(o.lensFile, selected, selected.camera);
  fitted = fitFor(request);
  const double errorPx = fitErrorPx(*fitted, request, size.widthPx);
  if (errorPx <= o.lensTolerancePx) {
    if (!o.quiet)
      std::cerr << "lenslab: note: --lens " << o.lensFile << ": the fitted thin lens, off by up to "
                << std::round(errorPx * 100.0) / 100.0 << " px at this size (lenslab lens " << o.lensFile
                << " shows each effect's error)\n";
    return false;
  }
  exact.samplesPerPixel = std::all_of(o.lens.apertureSamples.begin(), o.lens.apertureSamples.end(), ::isdigit) &&
                                  !o.lens.apertureSamples.empty()
                              ? std::stoi(o.lens.apertureSamples)
                              : 64;
  if (!o.quiet)
    std::cerr << "lenslab: note: --lens " << o.lensFile << ": "
              << (fitted->usable ? cat("the fitted thin lens is off by up to ", std::round(errorPx * 100.0) / 100.0,
                                       " px at this size")
                                 : cat("no thin lens fits (", fitted->why, ")"))
              << ", above --lens-tolerance " << o.lensTolerancePx << ": tracing the lens exactly, "
              << exact.samplesPerPixel << " rays per pixel\n";
  return true;
}

// The line that says what was written (none with --quiet).
void reportWritten(const RenderOptions& o, const fs::path& out, ImageSize size, const RunStats& stats) {
  if (o.quiet) return;
  const bool raster = o.method == Method::Raster;
  const std::string samples = stats.estimate
                                  ? cat("estimated ", stats.estimate->psnrDb, " dB with ", stats.estimate->meanSamples,
                                        " samples per pixel on average (", stats.estimate->minSamples, " to ",
                                        stats.estimate->maxSamples, " per tile)")
                                  : cat(stats.plan.apertureSamples, raster ? " aperture sample" : " sample",
                                        stats.plan.apertureSamples == 1 ? "" : "s", raster ? "" : " per pixel");
  std::cerr << "lenslab: wrote " << out.string() << " (" << size.widthPx << "x" << size.heightPx << ", " << samples
            << ", " << stats.renderer << ", " << stats.seconds << " s)\n";
}

int runRender(const RenderOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const fs::path out = o.out;
  // Every output checked before any work, so that a bad --stats refuses before the image exists.
  checkOutputPath(out, OutputKind::Image, "--out");
  const AovOutput aovs = checkedAovOutput(o.aovs, out, "--out");
  if (!o.statsFile.empty()) checkOutputPath(o.statsFile, OutputKind::Json, "--stats");
  const PlanOptions planOptions = toPlanOptions(o.lens);

  // The bundled scene's camera file is its base camera unless a glTF camera is asked for.
  const auto [scenePath, cameraPath] =
      resolveSceneAndCamera(o.scene, o.cameraFile, o.camera.namesBaseCamera() ? "" : "camera.json");
  checkNotInput(o.statsFile, "--stats", cameraPath.value_or(fs::path()), "--camera");
  Scene scene = loadGltf(scenePath);
  applyBackground(scene, o.background);
  const std::optional<EnvironmentSummary> environment = applyEnvironment(scene, o.environment, std::cerr);
  for (const std::string& w : poseForOneImage(scene, o.camera.animation, o.timeSeconds))
    std::cerr << "lenslab: warning: " << w << "\n";
  if (scene.triangleCount() == 0) throw InputError(cat(scenePath.string(), ": the scene has no triangles to render"));
  const double requestedAspect = (o.width && o.height) ? static_cast<double>(*o.width) / *o.height : 0.0;
  // The camera as selected (framed for --lens's field) and refocused; near/far fitted to the scene.
  SelectedCamera selected = chooseCamera(
      scene, cameraPath, framingForLens(o.camera, o.lensFile, scene, cameraPath.has_value()), requestedAspect);
  // With --lens the prescription's stop is the aperture: a camera file without one still focuses.
  const std::vector<std::string> focusNotes =
      o.lensFile.empty() ? focusWarnings(selected.camera, o.lens) : std::vector<std::string>{};
  selected = applyLensOptions(selected, o.lens);
  for (const std::string& w : focusNotes) std::cerr << "lenslab: warning: " << w << "\n";
  selected.camera = withDepthRangeFitted(selected.camera, scene.bounds);
  const ImageSize size = resolveImageSize(selected.camera, o.width, o.height);
  if (const std::string shape = pixelShapeWarning(selected.camera, o.width, o.height, size); !shape.empty())
    std::cerr << "lenslab: warning: " << shape << "\n";

  // Resolved before any work: a bad exposure refuses at once.
  DisplaySettings display = resolveDisplay(o.exposure, selected);

  RunStats stats;
  stats.environment = environment;
  stats.command = o.method == Method::Raster ? "render" : "raycast";
  stats.scene = scenePath.string();
  stats.size = size;
  stats.backend = o.backend;
  stats.triangles = scene.triangleCount();
  stats.setCamera(selected);

  // The image and the stats appear together or not at all (io/AtomicFile.h).
  OutputSet outputs;
  std::optional<Image> image;
  AovImages aovImages;  // --aov, beside the image
  // One reporter for the whole run: its last line comes after the file is written.
  ProgressReporter progress(stats.command, o.method == Method::Raster ? "samples" : "rows", o.quiet);
  std::optional<FittedLens> fitted;
  RenderOptions exact = o;
  const bool traceExactly = o.method == Method::Raycast || traceLensExactly(o, selected, size, fitted, exact);
  if (!traceExactly) {
    image = rasterize(o, scene, selected, size, planOptions, outputs, out, stats, progress, display, aovs.selection,
                      aovImages, fitted);
  } else {
    image = raycast(exact, scene, selected, size, stats, progress, aovs.selection, aovImages);
  }

  auto t = std::chrono::steady_clock::now();
  if (image) {  // a tiled render has written its file strip by strip
    progress.setDetail(cat("writing ", out.string()));
    for (const auto& w : meterForFile(display, *image, out, !o.statsFile.empty()))
      progress.note("lenslab: warning: " + w);
    prepareForFile(out, *image, display.encoding, "", std::cerr);
    const auto warn = [&](const std::string& w) { progress.note("lenslab: warning: " + w); };
    writeImage(outputs, out, *image, addAovOutputs(outputs, out, aovImages, aovs, scene, warn));
    stats.writeSeconds = secondsSince(t);
  }
  progress.setDetail({});  // written: the last line says no more than the figures
  progress.finish();
  stats.setDisplay(display);  // as the PNG was shown: metered, unless the render was tiled
  stats.seconds = secondsSince(start);
  if (!o.statsFile.empty()) writeStats(outputs, o.statsFile, stats);
  outputs.commit();
  reportWritten(o, out, size, stats);
  return 0;
}

std::function<int()> addImageCommand(CLI::App& app, Method method) {
  auto options = std::make_shared<RenderOptions>();
  options->method = method;
  CLI::App* cmd =
      method == Method::Raster
          ? app.add_subcommand("render", "Render a glTF scene headless through the lecture's camera model")
          : app.add_subcommand("raycast",
                               "Ray cast a glTF scene on the CPU: the reference for `render`, same camera and shading");
  cmd->add_option("scene", options->scene, "glTF 2.0 scene (.gltf or .glb); default: the bundled 'rows' scene");
  cmd->add_option(
      "--camera", options->cameraFile,
      "camera JSON (lecture, physical or OpenCV-intrinsics form, with any lens effects); default: the scene's first "
      "glTF camera, else an automatic framing; the lens and pose options below override it field by field");
  cmd->add_option("--out,-o", options->out, "output image: .png (8-bit sRGB) or .exr (linear float)")
      ->capture_default_str();
  cmd->add_option("--width", options->width,
                  cat("image width in pixels, 1 to 65536 (default 960; height follows the window's aspect); at most ",
                      method == Method::Raster
                          ? "2^30 pixels in all: images beyond one GL render target are rendered in tiles and written "
                            "a strip at a time (20000x13333 on llvmpipe: see docs/usage.md, Image sizes)"
                          : "2^28 pixels in all (the ray caster holds the whole float image)"));
  cmd->add_option("--height", options->height, "image height in pixels (limits as --width)");
  if (method == Method::Raster) {
    cmd->add_option("--tile-size", options->tileSizePx,
                    "render in tiles of at most PX x PX pixels (default: tiles only when one render target cannot hold "
                    "the image); the result is the same image")
        ->check(CLI::Range(16, kMaxImageSidePx))
        ->type_name("PX");
    cmd->add_option("--backend", options->backend, "osmesa (CPU, anywhere) or egl (GPU device, else Mesa surfaceless)")
        ->check(CLI::IsMember({"osmesa", "egl"}))
        ->capture_default_str();
    addLensFileOptions(*cmd, options->lensFile,
                       "render through the real-time camera fitted to this lens prescription (assets/lenses/; "
                       "docs/lenses.md): the thin lens at its entrance pupil with the distortion, colour, field "
                       "curvature and vignetting its rays show; where that fit is off by more than --lens-tolerance, "
                       "the lens is traced exactly instead",
                       &options->lensTolerancePx);
  } else {
    cmd->add_option("--spp", options->samplesPerPixel, "samples per pixel (stratified pixel x lens)")
        ->check(CLI::Range(1, 1 << 20))
        ->capture_default_str();
    addLensFileOptions(*cmd, options->lensFile,
                       "trace every ray through this lens prescription (assets/lenses/; docs/lenses.md) instead of "
                       "the thin lens: the camera's pose, sensor, f-number and focus distance, the lens's own focal "
                       "length, distortion and vignetting");
  }
  addColmapOptions(*cmd, options->camera);
  if (method == Method::Raster) addSamplingOptions(*cmd, options->lens);
  addSeedOption(*cmd, options->lens);
  addFocusOptions(*cmd, options->lens);
  addLensOverrideOptions(*cmd, options->lens);
  if (method == Method::Raster) addTargetOption(*cmd, options->lens);
  addCameraOptions(*cmd, options->camera);
  addBackgroundOption(*cmd, options->background);
  addAovOptions(*cmd, options->aovs);
  addExposureOptions(*cmd, options->exposure);
  addEnvironmentOptions(*cmd, options->environment);
  addTimeOption(*cmd, options->timeSeconds,
                "pose the scene's glTF animations at this time (seconds; as capture does for each frame's time); "
                "default: the rest pose");
  cmd->add_option("--stats", options->statsFile, "write what the run did (plan, timings, renderer) as JSON");
  cmd->add_flag("--quiet,-q", options->quiet, "print nothing on success");
  return [cmd, options]() { return cmd->parsed() ? runRender(*options) : -1; };
}

}  // namespace

std::function<int()> addRenderCommand(CLI::App& app) { return addImageCommand(app, Method::Raster); }
std::function<int()> addRaycastCommand(CLI::App& app) { return addImageCommand(app, Method::Raycast); }

}  // namespace lenslab
