// lenslab sweep: error against run time for every method, against the ray-cast reference.
#include "app/CliOptions.h"
#include "app/Commands.h"
#include "app/EnvironmentOptions.h"
#include "app/LensRequest.h"
#include "core/Clock.h"
#include "camera/DepthRange.h"
#include "camera/ImageMap.h"
#include "camera/ImageSize.h"
#include "core/Error.h"
#include "core/Text.h"
#include "gl/GlContext.h"
#include "io/AtomicFile.h"
#include "plan/CameraSelection.h"
#include "io/ImageFile.h"
#include "io/OutputPath.h"
#include "io/Progress.h"
#include "plan/TilePlan.h"
#include "report/Plot.h"
#include "report/Sweep.h"
#include "scene/GltfLoader.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

struct SweepCommandOptions {
  std::string scene;
  std::string cameraFile;
  std::string outDir;
  std::optional<int> width;
  std::optional<int> height;
  std::string backend = "osmesa";
  LensOptions lens;
  CameraOptions camera;  // the lens, pose and glTF camera; no clip (a sweep draws the rest pose)
  std::optional<glm::vec3> background;
  EnvironmentRequest environment;
  SweepOptions sweep;
  std::string lensFile;  // --lens: the exact lens is the reference, its fitted thin lens is swept
  bool quiet = false;
};

// The shortest text that reads back as `v` (40.00000000001, where cat writes 40).
std::string shortestText(double v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  return std::string(text, end);
}

// Each adaptive image is named by its target, to 10 significant digits: two targets with one
// name would overwrite one image, found only after the reference and the rows before it.
void refuseTargetsSharingAName(const std::vector<double>& targetsDb) {
  std::map<std::string, double> targetNamed;
  for (const double target : targetsDb) {
    const auto [named, added] = targetNamed.emplace(sweepAdaptiveImageName(target), target);
    if (added) continue;
    if (named->second == target)
      throw InputError(cat("--target-psnr: ", target, " dB is given twice; give each target once"));
    throw InputError(cat(
        "--target-psnr: ", shortestText(named->second), " and ", shortestText(target), " dB both name the image ",
        named->first, " (targets name their images to 10 significant digits); give targets that differ within them"));
  }
}

// --lens: the lens placed at the camera (`exactLens`) and the thin lens fitted to it (returned),
// with which the frame's real-lens map is made once the image size is known.
Camera prepareExactLens(SweepCommandOptions& o, const SelectedCamera& selected, const Camera& camera,
                        const Scene& scene, std::optional<LensCamera>& exactLens) {
  const LensRequest request = lensRequestFor(o.lensFile, selected, camera);
  const FittedLens fit = fitFor(request);
  exactLens.emplace(lensCameraFor(request));
  o.sweep.inputFiles.push_back(o.lensFile);
  o.sweep.inputOptions.push_back(cat(
      "lens settings ", shortestText(request.settings.sensorMm.x), " ", shortestText(request.settings.sensorMm.y), " ",
      shortestText(request.settings.fNumber.value_or(0.0)), " ", shortestText(request.settings.focusDistance)));
  const Camera fitted = withDepthRangeFitted(fittedCameraFor(request, fit, camera, o.lensFile), scene.bounds);
  o.sweep.lensAblations = fittedCameraAblations(fitted);
  return fitted;
}

// The reference's inputs beyond the scene's own files and the camera used (report/ReferenceCache.h):
// the files' bytes and the options that change what the ray caster computes.
void addReferenceInputs(SweepCommandOptions& o, const std::optional<fs::path>& cameraPath) {
  if (cameraPath) o.sweep.inputFiles.push_back(*cameraPath);
  if (o.background)
    o.sweep.inputOptions.push_back(cat("background ", shortestText(o.background->r), " ", shortestText(o.background->g),
                                       " ", shortestText(o.background->b)));
  if (!o.environment.file.empty()) {
    o.sweep.inputFiles.push_back(o.environment.file);
    o.sweep.inputOptions.push_back(
        cat("environment ", shortestText(o.environment.intensity), " ", shortestText(o.environment.rotationDegrees)));
  }
}

// Every file the sweep writes goes into one set, committed at the end: a failure anywhere (a full
// disk on the last image) leaves nothing new, not even the folders made here. The folders are made
// now, so that each file's place can be checked before the costly reference.
void prepareOutputs(OutputSet& outputs, const fs::path& out) {
  outputs.createFolders(out / "images");
  for (const char* name : {"sweep.csv", "sweep.md"}) checkOutputPath(out / name, OutputKind::Any, "--out");
  checkOutputPath(out / "error_vs_time.png", OutputKind::Image, "--out");
  checkOutputPath(out / "reference.exr", OutputKind::Image, "--out");          // the reference's cache
  checkOutputPath(out / "images" / "raster.png", OutputKind::Image, "--out");  // the rows' images
}

// One reporter a phase (the reference's rows, then the images), each with its own clock.
void attachReporters(SweepOptions& sweep, std::unique_ptr<ProgressReporter>& progress, bool quiet) {
  sweep.log = [&progress, quiet](const std::string& line) {
    if (quiet) return;
    if (progress)
      progress->note("lenslab: sweep: " + line);
    else
      std::cerr << "lenslab: sweep: " << line << "\n";
  };
  sweep.progress = [&progress, quiet](const std::string& unit, std::int64_t done, std::int64_t total) {
    if (!progress || progress->unit() != unit) {
      if (progress) progress->finish();
      progress = std::make_unique<ProgressReporter>("sweep", unit, quiet);
    }
    progress->update(done, total);
  };
}

struct SweepTimes {
  double contextSeconds = 0.0;
  double sweepSeconds = 0.0;
};

std::string sweepHeader(const SweepCommandOptions& o, const fs::path& scenePath, const Camera& camera, ImageSize size,
                        const std::optional<EnvironmentSummary>& environment, const GlContext& context,
                        const SweepResult& result, const SweepTimes& times) {
  return cat(
      "# Error against run time: ", scenePath.filename().string(), "\n\n", "- scene `", scenePath.string(),
      "`, camera ", camera.source, ", ", size.widthPx, "x", size.heightPx, "\n",
      environment ? cat("- environment `", environment->file, "`, intensity ", environment->intensity, ", rotation ",
                        environment->rotationDegrees, "°\n")
                  : std::string(),
      "- renderer: ", context.renderer(), " (", o.backend, "); ray caster: Embree + TBB on this machine's CPU\n",
      o.lensFile.empty() ? std::string()
                         : cat("- lens `", o.lensFile,
                               "`: the reference and the ray-cast rows trace it exactly; the raster rows are the "
                               "thin lens fitted to it (`lenslab lens` gives the fit)\n"),
      "- reference: ray cast at ", o.sweep.referenceSpp, " spp",
      result.referenceCached ? " (from the cache)" : cat(", ", result.referenceSeconds, " s"),
      " (the pixel integral: each sample's texture filtered over its own stratum); its own noise, from its two ",
      "halves: RMSE ", result.referenceNoiseRmse, ", so no method can show more than about ",
      -20.0 * std::log10(result.referenceNoiseRmse), " dB here\n", "- GL context creation ", times.contextSeconds,
      " s; scene upload, shader compilation and a warm-up frame ", result.setupSeconds,
      " s; neither is in the rows, which time each frame with the GPU finished and read back ",
      "(median of 3 for raster and post-process)\n",
      "- occlusion-edge pixels (within their circle of confusion of a depth step): ", result.edgeFraction * 100.0,
      " %\n", "- whole sweep: ", times.sweepSeconds, " s\n");
}

// Each series in its own colour and marker (report/PlotStyle.h), in the rows' order; the dashed
// line is the reference's own noise, the floor under which no series can be measured.
Image errorPlot(const SweepResult& result) {
  std::vector<PlotSeries> series;
  for (const SweepRow& row : result.rows) {
    const std::string key = row.method + " " + row.pattern;
    if (series.empty() || series.back().name != key) series.push_back({key, {}});
    series.back().points.push_back({row.seconds, row.rmse});
  }
  return logLogPlot(series, "seconds", "RMSE", "error against run time",
                    HorizontalLine{result.referenceNoiseRmse, "reference noise"});
}

int runSweepCommand(SweepCommandOptions& o) {
  refuseTargetsSharingAName(o.sweep.targetsDb);
  const auto [scenePath, cameraPath] =
      resolveSceneAndCamera(o.scene, o.cameraFile, o.camera.namesBaseCamera() ? "" : "camera-dof.json");
  Scene scene = loadGltf(scenePath);
  applyBackground(scene, o.background);
  const std::optional<EnvironmentSummary> environment = applyEnvironment(scene, o.environment, std::cerr);
  const SelectedCamera selected = applyLensOptions(
      chooseCamera(scene, cameraPath, framingForLens(o.camera, o.lensFile, scene, cameraPath.has_value()), 0.0),
      o.lens);
  Camera camera = withDepthRangeFitted(selected.camera, scene.bounds);
  addReferenceInputs(o, cameraPath);
  std::optional<LensCamera> exactLens;
  if (!o.lensFile.empty()) camera = prepareExactLens(o, selected, camera, scene, exactLens);
  // About 320 wide unless a side is given (the reference is costly); a height alone sets the
  // width from the window.
  const ImageSize size = resolveImageSize(camera, o.width, o.height, 320);
  if (const std::string shape = pixelShapeWarning(camera, o.width, o.height, size); !shape.empty())
    std::cerr << "lenslab: warning: " << shape << "\n";
  requireOneTarget(size, RenderTargetLimits{}, "sweep");
  // --lens: the frame is the real lens's map. The reference and the ray-cast rows trace it; the
  // raster rows draw its real-time form, fitted(). It is placed at the fitted camera, whose lens
  // centre the reference is kept relative to and whose name its messages carry.
  std::optional<RealLensMap> frame;
  if (exactLens) {
    frame.emplace(std::move(*exactLens), camera, size, camera);
    o.sweep.exactLens = &*frame;
  }
  const fs::path out = o.outDir;
  OutputSet outputs;
  prepareOutputs(outputs, out);

  SweepTimes times;
  auto t = std::chrono::steady_clock::now();
  const std::unique_ptr<GlContext> context = createHeadlessContext(o.backend == "egl" ? Backend::Egl : Backend::OSMesa);
  times.contextSeconds = secondsSince(t);
  o.sweep.outDir = out;
  o.sweep.outputs = &outputs;
  o.sweep.seed = o.lens.seed;
  std::unique_ptr<ProgressReporter> progress;
  attachReporters(o.sweep, progress, o.quiet);
  t = std::chrono::steady_clock::now();
  const SweepResult result = runSweep(scene, frame ? frame->fitted().camera() : camera, size, o.sweep);
  if (progress) progress->finish();
  times.sweepSeconds = secondsSince(t);

  outputs.add(out / "sweep.csv", sweepCsv(result));
  outputs.add(out / "sweep.md",
              sweepMarkdown(result, sweepHeader(o, scenePath, camera, size, environment, *context, result, times)));
  writeImage(outputs, out / "error_vs_time.png", errorPlot(result));
  outputs.commit();
  const auto images =
      std::count_if(result.rows.begin(), result.rows.end(), [](const SweepRow& r) { return !r.image.empty(); });
  if (!o.quiet)
    std::cerr << "lenslab: sweep: wrote " << (out / "sweep.csv").string() << ", sweep.md, error_vs_time.png and "
              << images << " images in " << (out / "images").string() << "\n";
  return 0;
}

}  // namespace

std::function<int()> addSweepCommand(CLI::App& app) {
  auto o = std::make_shared<SweepCommandOptions>();
  CLI::App* cmd = app.add_subcommand("sweep", "Error against run time of every method, against the ray-cast reference");
  cmd->add_option("scene", o->scene, "glTF 2.0 scene; default: the bundled 'rows' with camera-dof.json");
  cmd->add_option("--camera", o->cameraFile, "camera JSON with an aperture (f_number or aperture_radius)");
  cmd->add_option("--out,-o", o->outDir, "folder for sweep.csv, sweep.md, error_vs_time.png and images/")->required();
  cmd->add_option(
      "--width", o->width,
      "image width in pixels (default about 320 here, the nearest that keeps pixels square: the reference is costly)");
  cmd->add_option("--height", o->height, "image height in pixels");
  cmd->add_option("--backend", o->backend, "osmesa or egl")
      ->check(CLI::IsMember({"osmesa", "egl"}))
      ->capture_default_str();
  addLensFileOptions(*cmd, o->lensFile,
                     "sweep the real-time camera fitted to this lens prescription against the lens traced exactly (the "
                     "reference and the raycast rows), with each fitted effect also left out in turn (docs/lenses.md)");
  cmd->add_option("--reference-spp", o->sweep.referenceSpp, "samples per pixel of the reference")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  cmd->add_option("--max-views", o->sweep.maxViews, "largest raster budget (views)")
      ->check(CLI::Range(1, 65536))
      ->capture_default_str();
  cmd->add_option("--max-spp", o->sweep.maxSpp, "largest ray-cast budget (spp)")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  cmd->add_option("--seed", o->lens.seed, "seed for every sampler")->capture_default_str();
  cmd->add_option("--target-psnr", o->sweep.targetsDb, "the adaptive method's targets (dB), e.g. 30,40")
      ->delimiter(',')
      ->check(numberIn({.min = 10.0, .max = 100.0, .unit = "dB"}))
      ->type_name("DB[,DB...]")
      ->capture_default_str();
  cmd->add_option(
         "--methods", o->sweep.series,
         "the series to run: " +
             [] {
               std::string names;
               for (const std::string& n : sweepSeriesNames()) names += (names.empty() ? "" : ",") + n;
               return names;
             }() +
             " (default all)")
      ->delimiter(',')
      ->check(CLI::IsMember(sweepSeriesNames()))
      ->type_name("LIST");
  addBackgroundOption(*cmd, o->background);
  addEnvironmentOptions(*cmd, o->environment);
  addCameraOptions(*cmd, o->camera, /*withPose=*/true, /*withAnimation=*/false);
  cmd->add_option("--focus-distance", o->lens.focusDistance,
                  "put the plane of focus this far from the PRP (or infinity)")
      ->check(numberOrInfinity({.unit = "world units"}));
  addLensOverrideOptions(*cmd, o->lens);
  cmd->add_flag("--quiet,-q", o->quiet, "print nothing on success (no progress)");
  return [cmd, o]() {
    if (!cmd->parsed()) return -1;
    // A budget for a series that does not run would be ignored: refused instead.
    const auto runs = [&o](std::initializer_list<const char*> series) {
      for (const char* name : series)
        if (std::find(o->sweep.series.begin(), o->sweep.series.end(), name) != o->sweep.series.end()) return true;
      return false;
    };
    const auto refuseUnless = [&](const char* option, std::initializer_list<const char*> series, const char* what) {
      if (cmd->count(option) > 0 && !runs(series))
        throw InputError(
            cat(option, " sets ", what, ", which --methods leaves out; add it to --methods or drop ", option));
    };
    refuseUnless("--max-spp", {"raycast"}, "the raycast series' largest budget");
    refuseUnless("--target-psnr", {"adaptive"}, "the adaptive series' targets");
    refuseUnless("--max-views", {"concentric", "r2", "random", "sobol", "cells", "adaptive"},
                 "the raster series' largest budget");
    return runSweepCommand(*o);
  };
}

}  // namespace lenslab
