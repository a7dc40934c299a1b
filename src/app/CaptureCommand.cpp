// lenslab capture: a sequence of frames along a camera path, headless, with ground truth beside
// each image (its camera as a file `render --camera` reads, OpenCV intrinsics, optional depth) and
// frame ranges that split over independent processes (Slurm job arrays, Kubernetes indexed Jobs).
//
// A frame's pixels depend only on the scene, the path, the frame number, the options and the
// seed: each frame's camera is written as text and read back through the camera-file parser that
// `render --camera` uses, its seed is a hash of --seed and the frame number, and it is rendered by
// the same code as `render` (app/FrameRender.h) on a renderer that starts every frame afresh.
#include "app/CliOptions.h"
#include "app/Commands.h"
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
#include "io/CameraJson.h"
#include "io/CameraPathJson.h"
#include "io/CameraSelection.h"
#include "io/FrameSequence.h"
#include "io/ImageFile.h"
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
#include <memory>
#include <optional>
#include <set>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

struct CaptureOptions {
  std::string scene;
  std::string pathFile;
  std::string out = "frames/frame_%04d.png";
  std::string manifest;  // default: manifest.jsonl beside the frames
  std::optional<int> width;
  std::optional<int> height;
  std::string backend = "osmesa";
  std::string frames;    // "A:B"; empty = all
  std::string shard = "0/1";
  bool skipExisting = false;
  std::vector<std::string> aovs;
  bool quiet = false;
  LensOptions lens;
  std::optional<glm::vec3> background;
};


// The manifest's default place: beside the frames, when the pattern's folder has no frame number.
fs::path defaultManifest(const std::string& pattern) {
  const fs::path folder = fs::path(pattern).parent_path();
  if (folder.string().find('%') != std::string::npos)
    throw InputError(cat("--out ", pattern, ": the frame number is in the folder; give --manifest FILE for the manifest"));
  return folder / "manifest.jsonl";
}

// A file named in the manifest relative to the manifest's folder when it lies there.
std::string relativeTo(const fs::path& file, const fs::path& manifest) {
  const fs::path folder = manifest.parent_path().empty() ? fs::path(".") : manifest.parent_path();
  const fs::path rel = fs::absolute(file).lexically_normal().lexically_relative(fs::absolute(folder).lexically_normal());
  if (!rel.empty() && rel.begin()->string() != "..") return rel.string();
  return file.string();
}

nlohmann::json distanceJson(double d) { return std::isinf(d) ? nlohmann::json("infinity") : nlohmann::json(d); }

// K, distCoeffs, R and t of the frame's camera in OpenCV's conventions, for vision tools that read
// the manifest rather than the camera files (distCoeffs only where the lens is all OpenCV's).
nlohmann::json openCvJson(const Camera& camera, ImageSize size) {
  const OpenCvIntrinsics k = intrinsicsOf(camera.view, size);
  const OpenCvPose pose = poseOf(camera.view);
  nlohmann::json j;
  j["K"] = {{k.fx, 0.0, k.cx}, {0.0, k.fy, k.cy}, {0.0, 0.0, 1.0}};
  const Distortion& d = camera.effects.distortion;
  if (d.alpha == 0.0 && d.beta == 0.0 && d.gamma == 0.0) j["dist"] = {d.k1, d.k2, d.p1, d.p2, d.k3};
  j["R"] = nlohmann::json::array();
  for (const glm::dvec3& row : pose.rows) j["R"].push_back({row.x, row.y, row.z});
  j["t"] = {pose.translation.x, pose.translation.y, pose.translation.z};
  j["width"] = size.widthPx;
  j["height"] = size.heightPx;
  return j;
}

int runCapture(const CaptureOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const CameraPath path = loadCameraPath(o.pathFile);
  const int frameCount = path.frameCount();
  const FrameRange range = o.frames.empty() ? FrameRange{0, frameCount - 1} : parseFrameRange(o.frames, frameCount);
  const Shard shard = parseShard(o.shard);
  const std::vector<int> frames = shardFrames(range, shard);
  checkFramePattern(o.out, "--out");
  const bool depthAov = !o.aovs.empty();
  const fs::path manifest = o.manifest.empty() ? defaultManifest(o.out) : fs::path(o.manifest);

  // Every output checked before any work (the frames' folders made first: a cluster's shards
  // start on an empty volume).
  std::set<fs::path> folders;
  for (const int f : frames) folders.insert(fs::path(formatFramePath(o.out, f)).parent_path());
  folders.insert(manifest.parent_path());
  for (const fs::path& folder : folders) {
    if (folder.empty()) continue;
    std::error_code error;
    fs::create_directories(folder, error);
    if (error) throw InputError(cat(folder.string(), ": cannot make the output folder: ", error.message()));
  }
  const fs::path firstImage = formatFramePath(o.out, frames.empty() ? range.first : frames.front());
  checkOutputPath(firstImage, OutputKind::Image, "--out");
  if (depthAov && firstImage.extension() != ".exr")
    throw InputError(cat("--aov depth: ", o.out, ": depth goes in an EXR's Z channel; give an --out ending in .exr"));
  checkOutputPath(manifest, OutputKind::Any, "--manifest");

  const auto [scenePath, unusedCamera] = resolveSceneAndCamera(o.scene, "", "camera.json");
  Scene scene = loadGltf(scenePath);
  applyBackground(scene, o.background);
  if (scene.triangleCount() == 0) throw InputError(cat(scenePath.string(), ": the scene has no triangles to render"));
  const bool animated = !scene.animation.empty();

  const std::unique_ptr<GlContext> context = createHeadlessContext(o.backend == "egl" ? Backend::Egl : Backend::OSMesa);
  Renderer renderer(scene);
  std::unique_ptr<RayCaster> caster;  // the depth AOV; rebuilt each frame when the scene moves
  const RenderTargetLimits limits = queryRenderTargetLimits();

  // One line a frame where nobody watches a bar (a cluster job's log), unless
  // LENSLAB_PROGRESS_SECONDS asks for fewer.
  ProgressReporter progress("capture", "frames", o.quiet, 0.0);
  std::set<std::string> warned;
  int rendered = 0, skipped = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const int frame = frames[i];
    const fs::path imageFile = formatFramePath(o.out, frame);
    const fs::path cameraFile = frameCameraPath(imageFile);
    // Outputs appear whole (io/AtomicFile.h), the image last: an image that exists is a whole frame.
    if (o.skipExisting && fs::exists(imageFile)) {
      ++skipped;
      continue;
    }
    const auto frameStart = std::chrono::steady_clock::now();
    const double time = path.frameTimeSeconds(frame);
    if (animated) poseScene(scene, time);  // glTF node animations at the frame's time
    const PathKey key = cameraAt(path, time);
    const std::string where = cat(o.pathFile, ": frame ", frame, " (", time, " s)");
    validate(key.camera, where);
    Camera keyCamera = toCamera(key.camera, where);
    keyCamera.effects = key.effects;
    const ImageSize size = resolveImageSize(keyCamera, o.width, o.height);
    if (const std::string shape = pixelShapeWarning(keyCamera, o.width, o.height, size);
        !shape.empty() && !o.quiet && warned.insert(shape).second)
      progress.note("lenslab: warning: " + shape);
    const std::string cameraText =
        toIntrinsicsCameraJson(key.camera, key.effects, size, !path.nearFromScene, !path.farFromScene);
    // The frame's camera as `render --camera` will read it, from the very text written.
    const Camera camera = withDepthRangeFitted(parseCameraJson(cameraText, where).camera, scene.bounds);

    LensOptions lens = o.lens;
    lens.seed = frameSeed(o.lens.seed, frame);
    RunStats stats;
    const FramePlan plan = planFrame(renderer, scene, camera, size, toPlanOptions(lens), stats);
    for (const std::string& w : plan.warnings)
      if (!o.quiet && warned.insert(w).second) progress.note("lenslab: warning: " + w);
    if (const TilePlan tiles = planTiles(camera, size, plan, limits, 0); tiles.tiled)
      throw InputError(cat("--width/--height: frame ", frame, ": ", tiles.why, "; capture renders each frame in one render "
                           "target: give a smaller size (render tiles a single large image)"));
    const Image image = renderPlanned(renderer, camera, plan, size, stats, nullptr, true);
    std::vector<float> depth;
    if (depthAov) {
      if (!caster || animated) caster = std::make_unique<RayCaster>(scene);
      depth = caster->depthImage(camera, size);
    }

    OutputSet outputs;
    outputs.add(cameraFile, cameraText);
    writeImage(outputs, imageFile, image, depthAov ? &depth : nullptr);
    outputs.commit();
    const double seconds = secondsSince(frameStart);
    ++rendered;

    nlohmann::json line;
    line["frame"] = frame;
    line["time"] = time;
    line["file"] = relativeTo(imageFile, manifest);
    line["camera"] = relativeTo(cameraFile, manifest);
    line["seed"] = lens.seed;
    line["samples"] = stats.estimate ? stats.estimate->meanSamples : static_cast<double>(plan.apertureSamples);
    if (stats.estimate) line["psnr_estimate_db"] = stats.estimate->psnrDb;
    line["seconds"] = seconds;
    line["width"] = size.widthPx;
    line["height"] = size.heightPx;
    line["focal_length_mm"] = key.camera.focalLengthMm;
    line["f_number"] = distanceJson(key.camera.fNumber);
    line["focus_distance"] = distanceJson(key.camera.focusDistance);
    if (depthAov) line["aov"] = {"depth"};
    line["opencv"] = openCvJson(camera, size);
    line["shard"] = cat(shard.index, "/", shard.count);
    appendLine(manifest, line.dump());

    progress.update(static_cast<std::int64_t>(i) + 1, static_cast<std::int64_t>(frames.size()),
                    cat("frame ", frame, ": ", std::round(line["samples"].get<double>() * 10.0) / 10.0, " samples, ",
                        std::round(seconds * 100.0) / 100.0, " s"));
  }
  progress.finish();
  if (!o.quiet)
    std::cerr << "lenslab: captured " << rendered << " frame" << (rendered == 1 ? "" : "s")
              << (skipped ? cat(" (", skipped, " already there, left alone)") : std::string()) << " of frames " << range.first
              << ".." << range.last << (range.step > 1 ? cat(" step ", range.step) : std::string())
              << (shard.count > 1 ? cat(", shard ", shard.index, "/", shard.count) : std::string())
              << " to " << o.out << ", manifest " << manifest.string() << " (" << std::round(secondsSince(start) * 10.0) / 10.0
              << " s)\n";
  return 0;
}

}  // namespace

std::function<int()> addCaptureCommand(CLI::App& app) {
  auto o = std::make_shared<CaptureOptions>();
  CLI::App* cmd = app.add_subcommand(
      "capture", "Render a sequence of frames along a camera path, headless, with each frame's camera (and depth) beside it");
  cmd->add_option("scene", o->scene, "glTF 2.0 scene (.gltf or .glb); default: the bundled 'rows' scene");
  cmd->add_option("--path", o->pathFile,
                  "camera path JSON: {\"fps\": F, \"keys\": [{\"time\": t, <a camera in the physical form>}, ...]} "
                  "(see docs/capture.md)")
      ->required();
  cmd->add_option("--out,-o", o->out,
                  "frame files, a pattern with one %d (e.g. frames/frame_%04d.exr): .png (8-bit sRGB) or .exr (linear float); "
                  "each frame's camera goes beside it as frame_NNNN.camera.json")
      ->capture_default_str();
  cmd->add_option("--frames", o->frames,
                  "frames A to B, inclusive (A:B, A:, :B or one frame N), every STEP-th with A:B:STEP (A::STEP, :B:STEP); "
                  "default: all of the path's");
  cmd->add_option("--shard", o->shard,
                  "I/N: this is process I (0 to N-1) of N; it renders every N-th frame of the range from its I-th "
                  "(Slurm: $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT; Kubernetes: $JOB_COMPLETION_INDEX/N)")
      ->capture_default_str();
  cmd->add_flag("--skip-existing", o->skipExisting,
                "leave frames whose image exists alone (files are written atomically: one that exists is complete)");
  cmd->add_option("--aov", o->aovs,
                  "extra outputs: depth = a Z channel in the EXR, the distance from the lens centre along the optical axis "
                  "(world units, +inf where nothing is hit)")
      ->check(CLI::IsMember({"depth"}));
  cmd->add_option("--manifest", o->manifest,
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
  addBackgroundOption(*cmd, o->background);
  cmd->add_flag("--quiet,-q", o->quiet, "print nothing on success");
  return [cmd, o]() { return cmd->parsed() ? runCapture(*o) : -1; };
}

}  // namespace lenslab
