// lenslab capture: a sequence of frames along a camera path, headless, with ground truth beside
// each image (its camera as a file `render --camera` reads, OpenCV intrinsics, optional AOVs:
// depth, normal, albedo, instance) and frame ranges that split over independent processes (Slurm
// job arrays, Kubernetes indexed Jobs).
//
// A frame's pixels depend only on the scene, the path, the frame number, the options and the
// seed: each frame's camera is written as text and read back through the camera-file parser that
// `render --camera` uses, its seed is a hash of --seed and the frame number, and it is rendered by
// the same code as `render` (app/FrameRender.h) on a renderer that starts every frame afresh.
#include "app/AovOption.h"
#include "app/CliOptions.h"
#include "app/EnvironmentOptions.h"
#include "app/ExposureOptions.h"
#include "app/Commands.h"
#include "app/CaptureColmap.h"
#include "app/CaptureFrame.h"
#include "app/CaptureManifest.h"
#include "app/FrameCameras.h"
#include "app/FrameRender.h"
#include "camera/CameraPath.h"
#include "camera/DepthRange.h"
#include "camera/ImageSize.h"
#include "camera/Intrinsics.h"
#include "core/Clock.h"
#include "core/Error.h"
#include "core/Text.h"
#include "gl/GlContext.h"
#include "io/AtomicFile.h"
#include "io/AovChannels.h"
#include "io/CameraJson.h"
#include "io/CameraPathJson.h"
#include "plan/CameraSelection.h"
#include "io/ColmapExport.h"
#include "io/FrameSequence.h"
#include "io/ImageFile.h"
#include "io/Interrupt.h"
#include "io/JsonLines.h"
#include "io/OutputPath.h"
#include "io/Progress.h"
#include "plan/TilePlan.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "render/TiledRender.h"
#include "scene/GltfLoader.h"
#include "scene/SceneAnimation.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

int runCapture(const CaptureOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  // Without --path the scene's animation gives the frame count: the scene is read first.
  if (o.pathFile.empty() && o.camerasFile.empty() && o.camera.colmapDir.empty() && o.cameraFile.empty() &&
      o.scene.empty())
    throw InputError(
        "--path: give a camera path (or --cameras, --colmap, --camera), or a SCENE whose own camera (or automatic "
        "framing) is captured over its animation");
  const auto [scenePath, unusedCamera] = resolveSceneAndCamera(o.scene, "", "");
  Scene scene = loadGltf(scenePath);
  applyBackground(scene, o.background);
  const std::optional<EnvironmentSummary> environmentSummary = applyEnvironment(scene, o.environment, std::cerr);
  if (scene.triangleCount() == 0) throw InputError(cat(scenePath.string(), ": the scene has no triangles to render"));
  selectAnimation(scene, o.camera.animation);
  const FrameCameras cameras(o, scene, o.width && o.height ? static_cast<double>(*o.width) / *o.height : 0.0);
  const int frameCount = cameras.frameCount(scene);
  const FrameRange range = o.frames.empty() ? FrameRange{0, frameCount - 1} : parseFrameRange(o.frames, frameCount);
  const Shard shard = parseShard(o.shard);
  const std::vector<int> frames = shardFrames(range, shard);
  checkFramePattern(o.out, "--out");
  const AovOutput aovs = parseAovRequest(o.aovs, true);
  const fs::path manifest = o.manifest.empty() ? defaultManifest(o.out) : fs::path(o.manifest);
  OutputSet madeFolders;
  checkCaptureOutputs(o, frames, range, manifest, aovs, madeFolders);
  // The frames already done, for --skip-existing: those with a line in the manifest.
  const std::set<std::string> framesInManifest = o.skipExisting ? manifestFiles(manifest) : std::set<std::string>{};
  // Every frame's camera checked for what COLMAP can hold before any work, the model streamed
  // into temporary files; they appear before the first frame (whole: io/AtomicFile.h).
  OutputSet colmapModel;
  if (!o.colmapOut.empty()) {
    ProgressReporter modelProgress("capture: --colmap-out", "frames", o.quiet);
    writeColmapModel(o, cameras, scene, range, o.colmapOut, colmapModel, modelProgress);
  }

  const std::unique_ptr<GlContext> context = createHeadlessContext(o.backend == "egl" ? Backend::Egl : Backend::OSMesa);
  Renderer renderer(scene);
  colmapModel.commit();

  // One line a frame where nobody watches a bar (a cluster job's log), unless
  // LENSLAB_PROGRESS_SECONDS asks for fewer.
  ProgressReporter progress("capture", "frames", o.quiet, 0.0);
  CaptureFrames run(o, scene, cameras, aovs, environmentSummary, shard, range.first, frameCount,
                    [&progress](const std::string& line) { progress.note(line); });
  int rendered = 0, skipped = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const int frame = frames[i];
    const fs::path imageFile = formatFramePath(o.out, frame);
    // A frame is done when its image (whole: io/AtomicFile.h) and its manifest line both exist;
    // an image without a line (a kill between the two) is rendered again.
    if (o.skipExisting && fs::exists(imageFile) && framesInManifest.count(relativeTo(imageFile, manifest))) {
      ++skipped;
      continue;
    }
    const nlohmann::json line = run.commit(run.render(frame, renderer), imageFile, manifest);
    ++rendered;
    progress.update(static_cast<std::int64_t>(i) + 1, static_cast<std::int64_t>(frames.size()),
                    cat("frame ", frame, ": ", std::round(line["samples"].get<double>() * 10.0) / 10.0, " samples, ",
                        std::round(line["seconds"].get<double>() * 100.0) / 100.0, " s"));
  }
  progress.finish();
  madeFolders.commit();
  if (!o.quiet)
    std::cerr << "lenslab: captured " << rendered << " frame" << (rendered == 1 ? "" : "s")
              << (skipped ? cat(" (", skipped, " already there, left alone)") : std::string()) << " of frames "
              << range.first << ".." << range.last << (range.step > 1 ? cat(" step ", range.step) : std::string())
              << (shard.count > 1 ? cat(", shard ", shard.index, "/", shard.count) : std::string()) << " to " << o.out
              << ", manifest " << manifest.string() << " (" << std::round(secondsSince(start) * 10.0) / 10.0 << " s)\n";
  return 0;
}

}  // namespace

std::function<int()> addCaptureCommand(CLI::App& app) {
  auto o = std::make_shared<CaptureOptions>();
  CLI::App* cmd = app.add_subcommand(
      "capture",
      "Render a sequence of frames along a camera path, headless, with each frame's camera (and AOVs) beside it");
  cmd->add_option("scene", o->scene, "glTF 2.0 scene (.gltf or .glb); default: the bundled 'rows' scene");
  cmd->add_option(
      "--path", o->pathFile,
      "camera path JSON: {\"fps\": F, \"keys\": [{\"time\": t, <a camera in any form>}, ...]}: physical keys "
      "interpolated as a photographer's settings, OpenCV or lecture keys as a pinhole's pose and K (see "
      "docs/capture.md); without it, --cameras, --colmap, --camera, or the scene's glTF camera (--camera-node; else "
      "automatic framing) over its animation at --fps");
  cmd->add_option("--camera", o->cameraFile,
                  "a camera file in any form (lecture, physical, OpenCV K/R/t or intrinsics) held for every frame, "
                  "over the animation at --fps")
      ->type_name("FILE");
  cmd->add_option("--cameras", o->camerasFile,
                  "a camera list, one camera a line (JSON lines: camera files' objects with an optional \"time\"), or "
                  "a previous capture's manifest.jsonl: frame N is its N-th camera (docs/capture.md)")
      ->type_name("FILE");
  cmd->add_option("--colmap", o->camera.colmapDir,
                  "a COLMAP model's folder (text or binary): a frame for every image, in IMAGE_ID order, through its "
                  "camera's intrinsics and distortion; with --image NAME, that one image's camera held")
      ->type_name("DIR");
  cmd->add_option("--image", o->camera.colmapImage, "with --colmap: one photograph's NAME")->type_name("NAME");
  cmd->add_option("--fps", o->fps,
                  "without --path: frames per second over the playing animation, or of a camera list's frames "
                  "(default 24)")
      ->check(numberIn(kFramesPerSecondRange))
      ->type_name("F");
  cmd->add_option(
         "--out,-o", o->out,
         "frame files, a pattern with one %d (e.g. frames/frame_%04d.exr): .png (8-bit sRGB) or .exr (linear float); "
         "each frame's camera goes beside it as frame_NNNN.camera.json")
      ->capture_default_str();
  cmd->add_option(
      "--frames", o->frames,
      "frames A to B, inclusive (A:B, A:, :B or one frame N), every STEP-th with A:B:STEP (A::STEP, :B:STEP); "
      "default: all of the path's frames (or, without --path, of the animation at --fps)");
  cmd->add_option("--shard", o->shard,
                  "I/N: this is process I (0 to N-1) of N; it renders every N-th frame of the range from its I-th "
                  "(Slurm: $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT; Kubernetes: $JOB_COMPLETION_INDEX/N)")
      ->capture_default_str();
  cmd->add_flag("--skip-existing", o->skipExisting,
                "leave frames alone whose image exists and whose line the manifest holds (a frame with an image but no "
                "line is rendered again)");
  addAovOptions(*cmd, o->aovs);
  cmd->add_option(
      "--manifest", o->manifest,
      "the JSON-lines file each rendered frame appends one line to (default: manifest.jsonl beside the frames)");
  cmd->add_option("--width", o->width, "image width in pixels (default 960; height follows the window's aspect)");
  cmd->add_option("--height", o->height, "image height in pixels");
  cmd->add_option("--backend", o->backend, "osmesa (CPU, anywhere) or egl (GPU device, else Mesa surfaceless)")
      ->check(CLI::IsMember({"osmesa", "egl"}))
      ->capture_default_str();
  addSamplingOptions(*cmd, o->lens);
  addSeedOption(*cmd, o->lens);
  cmd->get_option("--seed")->description(
      "seed for the aperture and sub-pixel samples: each frame's seed is a hash of this and the frame number "
      "(the manifest's seed; render --seed with it reproduces the frame)");
  addTargetOption(*cmd, o->lens);
  addLensOverrideOptions(*cmd, o->lens);
  addCameraOptions(*cmd, o->camera);
  cmd->add_option("--colmap-out", o->colmapOut,
                  "also write the cameras of every frame of --frames as a COLMAP model in DIR (cameras, images with "
                  "the frames' names relative to --out's folder, an empty points3D); every shard writes the same "
                  "files (docs/capture.md)")
      ->type_name("DIR");
  cmd->add_option("--colmap-format", o->colmapFormat,
                  "with --colmap-out: text (cameras.txt, images.txt, points3D.txt) or binary (cameras.bin, ...), as "
                  "COLMAP writes either")
      ->check(CLI::IsMember({"text", "binary"}))
      ->capture_default_str();
  addBackgroundOption(*cmd, o->background);
  addExposureOptions(*cmd, o->exposure);
  addEnvironmentOptions(*cmd, o->environment);
  cmd->add_flag("--quiet,-q", o->quiet, "print nothing on success");
  return [cmd, o]() { return cmd->parsed() ? runCapture(*o) : -1; };
}

}  // namespace lenslab
