#pragma once
// Runs a frame plan on the current GL context and returns the linear image.
// One aperture sample: one scene pass straight into the output. More: each sample renders the
// scene from its aperture point (the PRP moved across the lens, the window kept on the plane of
// focus, shifted by the sample's sub-pixel offset) and is added into the accumulator. Lens effects,
// when the plan has them: one view per colour channel, each focused for its colour (axial
// chromatic aberration); the views summed through the field-curvature warp; distortion and lateral
// colour applied to each overscanned view as it is summed into the output (a single view: remapped
// afterwards by the lens pass). Vignetting, last: the finished image times its gain (VignettePass).
#include "camera/Camera.h"
#include "camera/ImageMap.h"
#include "camera/ImageSize.h"
#include "core/Image.h"
#include "gl/Framebuffer.h"
#include "gl/FullScreenPass.h"
#include "lens/AperturePattern.h"
#include "plan/FramePlan.h"
#include "plan/TileBudget.h"
#include "render/Accumulator.h"
#include "render/GpuScene.h"
#include "render/LensPass.h"
#include "render/LensViews.h"
#include "render/ScenePass.h"
#include "render/VignettePass.h"

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace lenslab {

// The unit progress counts a frame with per-tile budgets in (Renderer::progress).
inline constexpr const char* kTilesAtTargetUnit = "tiles at the target";

class Renderer {
 public:
  // Uploads the scene and builds the programs; `scene` must outlive the renderer.
  explicit Renderer(const Scene& scene);
  const Scene& scene() const { return gpuScene_.scene(); }

  // The whole frame (begin, complete, resolve); waits for the GPU (glFinish), so wall time around
  // it is honest.
  Image render(const Camera& camera, const FramePlan& plan, ImageSize size);

  // The same in steps, for progressive rendering: begin, then addSamples until done (or
  // complete), resolve.
  // `tables`: progress while the lens pass builds its tables (LensPass::prepare).
  void begin(const Camera& camera, const FramePlan& plan, ImageSize size, const LensPass::TableProgress& tables = {});
  // The rest of the frame begun: per-tile rounds (step) until it is done, or the planned samples in
  // batches of about a fiftieth of them, so that a long frame can report as it goes; `afterBatch`
  // after each round or batch. The image does not depend on the batches.
  void complete(const std::function<void()>& afterBatch = {});
  int addSamples(int count);  // returns how many were added (stops at the plan's count)
  int samplesDone() const { return done_; }
  int samplesPlanned() const { return static_cast<int>(samples_.size()); }
  Image resolve();  // the mean so far, read back

  // Per-tile budgets (a plan with `adaptive`): after begin, each step draws one round of samples
  // into the tiles that still need them and updates every drawn tile's error estimate; false once
  // the frame is done (the estimate meets the target, or every tile still short of it is at the cap).
  //
  // The estimate: even and odd samples are two independently scrambled streams
  // (lens/SobolSequence.h), summed apart; with stream means a, b over equal weights, |a − b|²/4 is
  // an unbiased estimate of the squared error of their mean against the converged image — the
  // image's own limit, not the ray-cast truth (any bias between the two is not in it).
  bool step();
  FrameEstimate estimate() const;
  bool adaptive() const { return adaptive_; }
  // Whether the frame is complete: every planned sample added, or (per-tile) step() has ended it.
  bool done() const { return adaptive_ ? finished_ : done_ >= samplesPlanned(); }
  // How far the frame is, as progress reports say it: with per-tile budgets the tiles at the
  // target of all the tiles (kTilesAtTargetUnit), else the samples added of those planned.
  struct Progress {
    int done = 0;
    int total = 0;
  };
  Progress progress() const;
  // progress().total for `plan` before begin() has set it up: for the lens tables, which come first.
  static int progressTotal(const FramePlan& plan, ImageSize size);

  // Reverse-Z depth (z_ndc) of a pinhole view, rows from the top: for focusing on a pixel.
  std::vector<float> pinholeDepth(const Camera& camera, ImageSize size);

  // How many times the lens pass built its lookup tables (once per lens, window and size).
  int lensTablesBuilt() const { return lensPass_ ? lensPass_->tablesBuilt() : 0; }

  // The pinhole view from the PRP (colour and depth), drawn and finished; valid until the next call.
  const gl::RenderTarget& renderPinhole(const Camera& camera, ImageSize size);

  // For the interactive view (src/view): the mean so far left on the GPU (no read-back, no
  // glFinish), valid until the next call; and the aperture samples planned by begin().
  const gl::RenderTarget& resolveOnGpu();
  const std::vector<LensSample>& plannedSamples() const { return samples_; }

 private:
  const gl::RenderTarget& target(std::unique_ptr<gl::RenderTarget>& slot, ImageSize size);
  // One aperture sample's view(s) into `sum`, drawn in parts: each part its own sample, into its
  // own rectangles (nullptr: the whole view; only when the views and the sum share pixels — no
  // lens gather, no field-curvature warp — can a view be drawn in parts).
  struct SamplePart {
    LensSample sample;
    const std::vector<PixelBox>* boxes = nullptr;
    const ApertureCell* cell = nullptr;  // the sample's cell, for the cell filter
  };
  void drawSample(const std::vector<SamplePart>& parts, Accumulator& sum, float lodBias);
  int regionOf(int tile) const;
  int mostSamples() const;  // the most samples any tile has
  void beginAdaptive();
  // One round of step(): how many more samples each tile is to have, and a group of tiles (those
  // `selected`, each expected to need at most `wanted`) drawn from sample `first` on, each region of
  // tiles with its own scramble; the samples drawn (0: the group is at the cap).
  std::vector<int> samplesToAdd(double targetMse);
  int drawTileGroup(int first, const std::vector<char>& selected, int wanted);
  // The error pass over the tiles drawn this round (8 × 8 blocks, summed per tile here), into tiles_.
  void updateEstimates(const std::vector<char>& drawn);
  void bindStreams();        // the two sums and their weights, texture units 0–3
  void uploadTileWeights();  // each tile's count per stream, once a round
  const gl::Program& streamsProgram(bool errorPerBlock);

  GpuScene gpuScene_;
  ScenePass scenePass_;
  std::unique_ptr<Accumulator> accumulator_;       // made on first use: a pinhole frame needs none
  std::unique_ptr<gl::RenderTarget> view_;         // a pinhole view for focusing
  std::unique_ptr<gl::RenderTarget> output_;       // the resolved image
  std::unique_ptr<gl::RenderTarget> undistorted_;  // the overscanned image the lens pass reads
  std::unique_ptr<LensPass> lensPass_;             // made on first use
  std::unique_ptr<gl::RenderTarget> unvignetted_;  // the image before the vignetting pass, when it runs
  std::unique_ptr<VignettePass> vignettePass_;     // made on first use

  // The camera the scene passes use: the map's render (overscanned when the lens pass runs).
  const Camera& viewCamera() const { return views_->map().overscan().camera; }

  FramePlan plan_;
  // The frame's views and its image map, built once by begin(): the output image's camera (a
  // tile's own) and size, the render's, each view's clipFromWorld and the lens pass's tables.
  std::optional<LensViews> views_;
  ImageSize size_;     // the size the scene passes render at (the map's overscan().size)
  ImageSize outSize_;  // the image's size (the map's size())
  std::vector<LensSample> samples_;
  std::vector<ApertureCell> cells_;  // with the cell filter: samples_[i]'s cell
  int done_ = 0;

  // Per-tile budgets.
  bool adaptive_ = false;
  bool finished_ = false;
  bool scissorViews_ = false;
  bool wholeFrame_ = false;               // the rest of the frame in whole views (step())
  std::unique_ptr<Accumulator> streamB_;  // odd samples; accumulator_ holds the even ones
  TileGrid grid_;
  std::vector<TileState> tiles_;
  std::vector<double> rawMse_;  // each tile's own two-stream estimate, before pooling
  int rounds_ = 0;
  mutable int tilesAtTargetShown_ = 0;                         // progress(): the most tiles at the target so far
  int regionTiles_ = 1, regionColumns_ = 1, regionCount_ = 1;  // regions of tiles with their own scramble
  gl::Texture tileWeights_[2];  // per tile, per stream: RGBA32F, the samples each stream added
  gl::Texture blockError_;      // RG32F, one texel per 8 × 8 block: squared error, value count
  gl::Framebuffer blockErrorFramebuffer_;
  gl::Program streams_[4];  // [per-pixel weight · 2 + error per block]
  gl::FullScreenPass fullScreen_;
};

}  // namespace lenslab
