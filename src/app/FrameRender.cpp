#include "app/FrameRender.h"

#include "core/Clock.h"
#include "core/Text.h"
#include "render/VisibleBlurPass.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <optional>

namespace lenslab {

FramePlan planFrame(Renderer& renderer, const Scene& scene, const Camera& camera, ImageSize size,
                    const PlanOptions& options, RunStats& stats) {
  std::optional<VisibleBlur> visible;
  // The cell filter reads the largest circle in view for how far its images reach.
  if (!camera.lens.isPinhole() &&
      (options.apertureSamples == 0 || options.targetPsnrDb || options.cellFilter.value_or(false))) {
    const auto t = std::chrono::steady_clock::now();
    visible = measureVisibleBlur(renderer, camera, size);
    stats.prepassSeconds = secondsSince(t);
  }
  stats.plan = makeFramePlan(scene, camera, size, options, visible ? &*visible : nullptr);
  return stats.plan;
}

Image renderPlanned(Renderer& renderer, const Camera& camera, const FramePlan& plan, ImageSize size, RunStats& stats,
                    ProgressReporter* progress, bool quiet) {
  if (progress && plan.adaptive) progress->setUnit(kTilesAtTargetUnit);
  // Nothing to report to a silent reporter (--quiet): no callbacks, so that the lens tables are
  // built in one parallel pass rather than in slices that report between them.
  const bool shown = progress && progress->style() != ProgressReporter::Style::Silent;
  LensPass::TableProgress tables;
  if (shown)
    tables = [&, total = Renderer::progressTotal(plan, size)](const char* table, int rowsDone, int rows) {
      progress->update(0, total, cat(table, " lens table, ", rowsDone, "/", rows, " rows"));
    };
  renderer.begin(camera, plan, size, tables);
  std::function<void()> afterBatch;
  if (shown)
    afterBatch = [&] {
      const Renderer::Progress p = renderer.progress();
      if (!plan.adaptive) {
        progress->update(p.done, p.total);
        return;
      }
      const FrameEstimate e = renderer.estimate();
      progress->update(p.done, p.total,
                       cat(std::round(e.psnrDb * 10.0) / 10.0, " dB of ", plan.adaptive->targetPsnrDb, " (estimate), ",
                           std::round(e.meanSamples * 10.0) / 10.0, " samples per pixel"));
    };
  renderer.complete(afterBatch);
  Image image = renderer.resolve();
  if (!plan.adaptive) return image;
  stats.estimate = renderer.estimate();
  if (!quiet && !stats.estimate->targetMet) {
    const std::string warning =
        cat("lenslab: warning: the estimate reached ", stats.estimate->psnrDb, " dB, short of --target-psnr ",
            plan.adaptive->targetPsnrDb, ": the tiles still short of it are at the cap of ", plan.adaptive->maxSamples,
            " samples (--max-samples, an even count for the two streams)");
    if (progress)
      progress->note(warning);  // below the bar, not through it
    else
      std::cerr << warning << "\n";
  }
  return image;
}

void prepareForFile(const std::filesystem::path& path, Image& image, const DisplayEncoding& display,
                    const std::string& where, std::ostream& warnings) {
  if (const std::optional<std::string> overflow = radianceOverflowWarning(image))
    warnings << "lenslab: warning: " << where << *overflow << "\n";
  applyDisplayForFile(path, image, display);
}

}  // namespace lenslab
