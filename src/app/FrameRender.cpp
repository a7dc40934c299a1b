#include "app/FrameRender.h"

#include "core/Clock.h"
#include "io/Progress.h"
#include "render/VisibleBlurPass.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>

namespace lenslab {

FramePlan planFrame(Renderer& renderer, const Scene& scene, const Camera& camera, ImageSize size,
                    const PlanOptions& options, RunStats& stats) {
  std::optional<VisibleBlur> visible;
  if (!camera.isPinhole() && (options.apertureSamples == 0 || options.targetPsnrDb)) {
    const auto t = std::chrono::steady_clock::now();
    visible = measureVisibleBlur(renderer, camera, size);
    stats.prepassSeconds = secondsSince(t);
  }
  stats.plan = makeFramePlan(scene, camera, size, options, visible ? &*visible : nullptr);
  return stats.plan;
}

Image renderPlanned(Renderer& renderer, const Camera& camera, const FramePlan& plan, ImageSize size, RunStats& stats,
                    bool showProgress, bool quiet) {
  const auto t = std::chrono::steady_clock::now();
  renderer.begin(camera, plan, size);
  if (plan.adaptive) {
    while (renderer.step()) {
      const FrameEstimate e = renderer.estimate();
      if (showProgress)
        std::fprintf(stderr, "\r%5.1f dB of %.1f (estimate), %.1f samples per pixel, %d of %d tiles going, %.1f s   ",
                     e.psnrDb, plan.adaptive->targetPsnrDb, e.meanSamples, e.tilesActive, e.tiles, secondsSince(t));
    }
    Image image = renderer.resolve();
    stats.estimate = renderer.estimate();
    if (showProgress) std::cerr << "\n";
    if (!quiet && !stats.estimate->targetMet)
      std::cerr << "lenslab: warning: the estimate reached " << stats.estimate->psnrDb << " dB, short of --target-psnr "
                << plan.adaptive->targetPsnrDb << ": the tiles still short of it are at the cap of " << plan.adaptive->maxSamples
                << " samples (--max-samples, an even count for the two streams)\n";
    return image;
  }
  const bool samplesProgress = showProgress && plan.apertureSamples > 1;
  // Samples in batches, so that long renders report progress on a terminal.
  const int batch = std::max(1, plan.apertureSamples / 50);
  while (renderer.samplesDone() < renderer.samplesPlanned()) {
    renderer.addSamples(batch);
    if (samplesProgress) printProgress(renderer.samplesDone(), renderer.samplesPlanned(), secondsSince(t));
  }
  Image image = renderer.resolve();
  if (samplesProgress) std::cerr << "\n";
  return image;
}

}  // namespace lenslab
