#include "app/CaptureFrame.h"

#include "app/CaptureManifest.h"
#include "app/ExposureSettings.h"
#include "app/FrameRender.h"
#include "camera/DepthRange.h"
#include "core/Clock.h"
#include "core/Error.h"
#include "core/Text.h"
#include "io/AtomicFile.h"
#include "io/CameraJson.h"
#include "io/ImageFile.h"
#include "io/JsonLines.h"
#include "io/OutputPath.h"
#include "plan/CameraSelection.h"
#include "plan/TilePlan.h"
#include "scene/SceneAnimation.h"

#include <iostream>
#include <sstream>

namespace lenslab {
namespace fs = std::filesystem;

void checkCaptureOutputs(const CaptureOptions& o, const std::vector<int>& frames, const FrameRange& range,
                         const fs::path& manifest, const AovOutput& aovs, OutputSet& madeFolders) {
  std::set<fs::path> folders;
  for (const int f : frames) folders.insert(fs::path(formatFramePath(o.out, f)).parent_path());
  folders.insert(manifest.parent_path());
  for (const fs::path& folder : folders)
    if (!folder.empty()) madeFolders.createFolders(folder);
  const fs::path firstImage = formatFramePath(o.out, frames.empty() ? range.first : frames.front());
  checkOutputPath(firstImage, OutputKind::Image, "--out");
  checkOutputPath(frameCameraPath(firstImage), OutputKind::Any, "--out");  // its name is longer than the image's
  checkAovOutput(aovs, firstImage, "--out");
  checkOutputPath(manifest, OutputKind::JsonLines, "--manifest");
  checkNotInput(manifest, "--manifest", o.pathFile, "--path");
  checkNotInput(manifest, "--manifest", o.camerasFile, "--cameras");  // a replayed manifest is not appended to
  // Nor one of the range's frame camera files (f_0002.camera.json), which the manifest's lines would
  // be appended to; nor may the COLMAP model's folder be a frame's file or the manifest.
  const std::string cameraPattern = frameCameraPath(o.out).string();
  if (const std::optional<int> f = frameNamedBy(cameraPattern, manifest); f && inRange(range, *f))
    throw InputError(cat("--manifest ", manifest.string(), ": is frame ", *f, "'s camera file; give another name"));
  checkAppendable(manifest, "--manifest");
  if (!o.colmapOut.empty()) {
    for (const auto& [pattern, what] : {std::pair{o.out, "image"}, std::pair{cameraPattern, "camera file"}})
      if (const std::optional<int> f = frameNamedBy(pattern, o.colmapOut); f && inRange(range, *f))
        throw InputError(cat("--colmap-out ", o.colmapOut, ": is frame ", *f, "'s ", what, " (--out ", o.out,
                             "); give the model a folder of its own"));
    if (fs::absolute(o.colmapOut).lexically_normal() == fs::absolute(manifest).lexically_normal())
      throw InputError(cat("--colmap-out ", o.colmapOut, ": is the manifest; give the model a folder of its own"));
    madeFolders.createFolders(o.colmapOut);
    checkOutputPath(fs::path(o.colmapOut) / (o.colmapFormat == "binary" ? "cameras.bin" : "cameras.txt"),
                    OutputKind::Any, "--colmap-out");
  }
}

// A frame made ready to render: the scene posed at its time, its camera as written (and as
// `render --camera` reads that text back), its display.
struct CaptureFrames::FrameSetup {
  double time = 0.0;
  FrameKey f;
  std::string cameraText;
  Camera camera;
  DisplaySettings display;
};

CaptureFrames::CaptureFrames(const CaptureOptions& o, Scene& scene, const FrameCameras& cameras, AovOutput aovs,
                             std::optional<EnvironmentSummary> environment, Shard shard, int firstFrame, int frameCount,
                             std::function<void(const std::string&)> note)
    : o_(o),
      scene_(scene),
      cameras_(cameras),
      aovs_(std::move(aovs)),
      environment_(std::move(environment)),
      shard_(shard),
      firstFrame_(firstFrame),
      frameCount_(frameCount),
      note_(std::move(note)) {}

void CaptureFrames::warnOnce(const std::string& w) {
  if (!o_.quiet && warned_.insert(w).second) note_("lenslab: warning: " + w);
}

CaptureFrames::FrameSetup CaptureFrames::setUp(int frame) {
  FrameSetup s;
  s.time = cameras_.timeOf(frame);
  if (!scene_.animation.empty()) poseScene(scene_, s.time);  // glTF node animations at the frame's time
  s.f = frameKey(cameras_, scene_, o_, frame);
  if (const std::string shape = pixelShapeWarning(s.f.camera, o_.width, o_.height, s.f.size); !shape.empty())
    warnOnce(shape);
  // A physical frame as the photographer's description; any other as OpenCV's K, R and t.
  s.cameraText =
      s.f.key
          ? toIntrinsicsCameraJson(s.f.key->camera, s.f.key->lens, s.f.size, cameras_.nearGiven(), cameras_.farGiven())
          : toOpenCvCameraJson(s.f.camera, s.f.size, !s.f.camera.nearFromScene, !s.f.camera.farFromScene);
  s.camera = withDepthRangeFitted(parseCameraJson(s.cameraText, s.f.where).camera, scene_.bounds);
  // Each frame's own f-number for a physical exposure (a path may change it from key to key).
  s.display = resolveDisplay(
      o_.exposure, SelectedCamera{s.camera, s.f.key ? std::optional<PhysicalCamera>(s.f.key->camera) : std::nullopt});
  return s;
}

Image CaptureFrames::renderImage(int frame, const FrameSetup& s, const LensOptions& lens, Renderer& renderer,
                                 RunStats& stats, FramePlan& plan) {
  plan = planFrame(renderer, scene_, s.camera, s.f.size, toPlanOptions(lens), stats);
  for (const std::string& w : plan.warnings) warnOnce(w);
  for (const std::string& w : focusWarnings(s.camera, o_.lens)) warnOnce(w);
  if (!limits_) limits_ = queryRenderTargetLimits();
  if (const TilePlan tiles = planTiles(s.camera, s.f.size, plan, *limits_, 0); tiles.tiled)
    throw InputError(cat("--width/--height: frame ", frame, ": ", tiles.why,
                         "; capture renders each frame in one render "
                         "target: give a smaller size (render tiles a single large image)"));
  return renderPlanned(renderer, s.camera, plan, s.f.size, stats, nullptr, true);
}

// The frame's meter reading in `display` (for --exposure auto and a physical exposure); for
// --exposure auto the exposure held from the range's first frame. The first reading's warnings
// only: a sequence is exposed as one.
void CaptureFrames::meter(DisplaySettings& display, const Image& image, int frame) {
  const std::vector<std::string> warnings = meterForFile(display, image, o_.out, false, held_);
  if (display.exposure.meterReading && !held_) {
    held_ = display.exposure;
    for (const std::string& w : warnings) warnOnce(cat("frame ", frame, ": ", w));
  }
}

CapturedFrame CaptureFrames::render(int frame, Renderer& renderer) {
  const auto frameStart = std::chrono::steady_clock::now();
  // One exposure for the whole range, whichever shard or rerun renders a frame: --exposure auto
  // on a process whose first frame is not the range's first (another shard's, or one
  // --skip-existing leaves alone) renders and meters that frame here, without writing it.
  if (o_.exposure.request.meter && !held_ && frame != firstFrame_) {
    const FrameSetup first = setUp(firstFrame_);
    LensOptions lens = o_.lens;
    lens.seed = frameSeed(o_.lens.seed, firstFrame_);
    RunStats stats;
    FramePlan plan;
    DisplaySettings display = first.display;
    meter(display, renderImage(firstFrame_, first, lens, renderer, stats, plan), firstFrame_);
  }
  FrameSetup s = setUp(frame);
  CapturedFrame c;
  c.frame = frame;
  c.timeSeconds = s.time;
  LensOptions lens = o_.lens;
  lens.seed = c.seed = frameSeed(o_.lens.seed, frame);
  FramePlan plan;
  c.image = renderImage(frame, s, lens, renderer, c.stats, plan);
  c.apertureSamples = plan.apertureSamples;
  if (aovs_.selection.any()) {
    if (!caster_ || !scene_.animation.empty()) caster_ = std::make_unique<RayCaster>(scene_);
    const AovSelection& asked = aovs_.selection;
    // The flow starts from each pixel's surface: its depth and node.
    AovSelection cast = asked;
    cast.depth = cast.depth || asked.flow, cast.instance = cast.instance || asked.flow, cast.flow = false;
    c.aovs = caster_->aovImages(s.camera, s.f.size, cast);
    if (asked.flow) {
      c.aovs.flow = flowToNextFrame(cameras_, scene_, o_, frame, frameCount_, s.camera, s.f.size, c.aovs);
      if (!asked.depth) c.aovs.depth.clear();
      if (!asked.instance) c.aovs.instance.clear();
    }
  }
  c.display = s.display;
  meter(c.display, c.image, frame);
  c.key = std::move(s.f);
  c.cameraText = std::move(s.cameraText);
  c.camera = std::move(s.camera);
  c.seconds = secondsSince(frameStart);
  return c;
}

nlohmann::json CaptureFrames::commit(const CapturedFrame& c, const fs::path& imageFile, const fs::path& manifest) {
  const auto writeStart = std::chrono::steady_clock::now();
  const fs::path cameraFile = frameCameraPath(imageFile);
  OutputSet outputs;  // renamed into place with the frame's manifest line (commitFrame)
  outputs.add(cameraFile, c.cameraText);
  Image image = c.image;  // the frame keeps its linear pixels
  std::ostringstream warnings;
  prepareForFile(imageFile, image, c.display.encoding, cat("frame ", c.frame, ": "), warnings);
  if (!warnings.str().empty()) note_(warnings.str().substr(0, warnings.str().size() - 1));
  // The instance ids' names once for the frames' folder (every frame writes the same bytes).
  const auto warn = [&](const std::string& w) { warnOnce(cat("frame ", c.frame, ": ", w)); };
  writeImage(
      outputs, imageFile, image,
      addAovOutputs(outputs, imageFile, c.aovs, aovs_, scene_, warn, imageFile.parent_path() / "instances.json"));
  const ManifestFrame entry{c.frame,
                            c.timeSeconds,
                            imageFile,
                            cameraFile,
                            c.seed,
                            c.stats.estimate ? c.stats.estimate->meanSamples : static_cast<double>(c.apertureSamples),
                            c.stats.estimate ? std::optional<double>(c.stats.estimate->psnrDb) : std::nullopt,
                            c.seconds + secondsSince(writeStart),
                            c.key.size,
                            c.key.key ? &c.key.key->camera : nullptr,
                            c.camera,
                            aovs_,
                            c.display,
                            environment_,
                            shard_};
  const nlohmann::json line = manifestLine(entry, manifest);
  std::vector<fs::path> files = aovFilePaths(aovs_, imageFile);
  files.insert(files.begin(), {cameraFile, imageFile});
  commitFrame(outputs, files, manifest, line.dump());
  return line;
}

}  // namespace lenslab
