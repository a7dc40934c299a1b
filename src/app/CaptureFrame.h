#pragma once
// capture's frames, one at a time, without the command-line library (the `capture` command and
// the Python package's lenslab.Sequence both go through it): each frame's camera written as text
// and read back through the camera-file parser `render --camera` uses, its seed a hash of the seed
// and the frame number, rendered by app/FrameRender.h with its AOVs and its exposure; then its
// image, AOV files, camera file and manifest line committed together.
#include "app/AovOutputs.h"
#include "app/FrameCameras.h"
#include "app/Stats.h"
#include "core/Image.h"
#include "io/EnvironmentFile.h"
#include "io/FrameSequence.h"
#include "io/ToneMap.h"
#include "plan/FramePlan.h"
#include "raycast/RayCaster.h"
#include "render/Renderer.h"
#include "render/TiledRender.h"
#include "scene/Scene.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace lenslab {

// Every output of the frames of `frames` (from `range`) checked before any work, the frames'
// folders made first (a cluster's shards start on an empty volume) and listed in `madeFolders`,
// removed again, when still empty, unless it is committed.
void checkCaptureOutputs(const CaptureOptions& o, const std::vector<int>& frames, const FrameRange& range,
                         const std::filesystem::path& manifest, const AovOutput& aovs, OutputSet& madeFolders);

// One frame rendered, not yet written.
struct CapturedFrame {
  int frame = 0;
  double timeSeconds = 0.0;
  FrameKey key;            // its physical description (where it has one) and size
  std::string cameraText;  // its camera file
  Camera camera;           // as read back from cameraText, near and far fitted to the scene
  std::uint32_t seed = 0;
  Image image;  // linear
  AovImages aovs;
  DisplaySettings display;  // metered
  RunStats stats;
  int apertureSamples = 0;
  double seconds = 0.0;  // rendering it
};

class CaptureFrames {
 public:
  // `note` gets each warning once, as a line "lenslab: warning: …" (none with o.quiet).
  CaptureFrames(const CaptureOptions& o, Scene& scene, const FrameCameras& cameras, AovOutput aovs,
                std::optional<EnvironmentSummary> environment, Shard shard, int firstFrame, int frameCount,
                std::function<void(const std::string&)> note);

  // `frame` rendered on `renderer` (which holds the scene; its context current). The scene is
  // posed at the frame's time. Throws InputError for a frame larger than one render target.
  CapturedFrame render(int frame, Renderer& renderer);

  // The frame's image as `imageFile` (.png exposed by its display, .exr linear), its AOV files
  // (and instances.json in its folder), its camera file beside it and its line appended to
  // `manifest`: together or not at all. The line.
  nlohmann::json commit(const CapturedFrame& frame, const std::filesystem::path& imageFile,
                        const std::filesystem::path& manifest);

  const AovOutput& aovs() const { return aovs_; }

 private:
  struct FrameSetup;
  FrameSetup setUp(int frame);
  Image renderImage(int frame, const FrameSetup& s, const LensOptions& lens, Renderer& renderer, RunStats& stats,
                    FramePlan& plan);
  void meter(DisplaySettings& display, const Image& image, int frame);
  void warnOnce(const std::string& w);

  const CaptureOptions& o_;
  Scene& scene_;
  const FrameCameras& cameras_;
  AovOutput aovs_;
  std::optional<EnvironmentSummary> environment_;
  Shard shard_;
  int firstFrame_;  // the range's: --exposure auto meters it
  int frameCount_;  // the sequence's: the last has no next frame for the flow AOV
  std::function<void(const std::string&)> note_;
  std::unique_ptr<RayCaster> caster_;  // the AOVs; rebuilt each frame when the scene moves
  std::optional<RenderTargetLimits> limits_;
  std::set<std::string> warned_;
  // The first frame's exposure as metered: --exposure auto holds its scale for every frame.
  std::optional<Exposure> held_;
};

}  // namespace lenslab
