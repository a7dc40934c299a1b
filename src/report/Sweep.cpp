#include "report/Sweep.h"

#include "camera/ImageMap.h"
#include "camera/Projection.h"
#include "core/Clock.h"
#include "core/Error.h"
#include "core/Text.h"
#include "io/AtomicFile.h"
#include "io/ImageCompare.h"
#include "io/ImageFile.h"
#include "plan/FramePlan.h"
#include "plan/TileBudget.h"
#include "raycast/RayCaster.h"
#include "render/GatherDof.h"
#include "render/Renderer.h"
#include "render/VisibleBlurPass.h"
#include "report/ReferenceCache.h"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <set>
#include <stdexcept>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

std::vector<int> doublings(int max) {
  std::vector<int> n;
  for (int k = 1; k <= max; k *= 2) n.push_back(k);
  return n;
}

void say(const SweepOptions& o, const std::string& line) {
  if (o.log) o.log(line);
}

// Raster and post-process frames are short and the machine is noisy: each is timed three times
// and the median kept (the image is the same every time: fixed seeds).
double medianOf3(const std::function<Image()>& frame, Image& image) {
  double t[3];
  for (double& ti : t) {
    const auto start = std::chrono::steady_clock::now();
    image = frame();
    ti = secondsSince(start);
  }
  std::sort(std::begin(t), std::end(t));
  return t[1];
}

// Occlusion edges from the pinhole depth. With distortion the depth is looked up where each
// pixel's true perspective position is, in the overscanned pinhole view (nearest pixel: the mask
// only needs to find the edges).
std::vector<bool> pinholeEdges(Renderer& renderer, const Camera& camera, ImageSize size) {
  const ThinLensMap map = ThinLensMap(camera, size).overscanned();
  const Overscan& overscan = map.overscan();
  std::vector<float> zNdc = renderer.pinholeDepth(overscan.camera, overscan.size);
  std::vector<double> depth(static_cast<std::size_t>(size.widthPx) * static_cast<std::size_t>(size.heightPx));
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      const glm::dvec2 p = map.renderPixelFromOutput(glm::dvec2(x + 0.5, y + 0.5));
      const int px = std::clamp(static_cast<int>(p.x), 0, overscan.size.widthPx - 1);
      const int py = std::clamp(static_cast<int>(p.y), 0, overscan.size.heightPx - 1);
      depth[static_cast<std::size_t>(y * size.widthPx + x)] =
          depthFromReverseZ(camera.view, zNdc[static_cast<std::size_t>(py * overscan.size.widthPx + px)]);
    }
  return occlusionEdgeMask(camera, size, depth);
}

// One sweep in progress: what every series renders with, and the rows it records.
struct SweepRun {
  const Scene& scene;
  const Camera& camera;
  ImageSize size;
  const SweepOptions& o;
  SweepResult& result;
  Image reference;
  std::vector<bool> edges;
  Renderer renderer;
  GatherDof gather;
  fs::path imageDir;
  std::set<std::string> imageNames;
  // Why the cell-filter series cannot run on this camera (a lens that moves or warps each view as
  // it is summed, a barrel, ...: plan/FramePlan.cpp); empty where it can. Such a series is left out,
  // as the gather is, rather than refused after the reference.
  std::string cellsLeftOut;
  std::int64_t imagesPlanned = 0;

  bool wanted(const std::string& series) const {
    return std::find(o.series.begin(), o.series.end(), series) != o.series.end();
  }

  // Each series' budgets, an image each: views (lecture17 its own 17), spp or taps; none when it
  // does not run. The adaptive series runs to its targets instead (counted apart).
  std::vector<int> budgetsOf(const std::string& series) const {
    if (!wanted(series) || series == "adaptive") return {};
    if (series == "lecture17") return {17};
    if (series == "raycast") return doublings(o.maxSpp);
    if (series == "cells") {  // from 2: one view has no cells to spread over
      if (!cellsLeftOut.empty()) return {};
      std::vector<int> views = doublings(o.maxViews);
      views.erase(views.begin());
      return views;
    }
    // The gather baseline blurs the pinhole image with round disks and knows no lens effects:
    // comparing it with an exact distorted (or polygonal) reference would measure what it lacks,
    // not the method.
    if (series == "postprocess")
      return camera.lens.effects.isZero() && camera.lens.aperture.isRound() ? o.gatherTaps : std::vector<int>{};
    return doublings(o.maxViews);
  }

  // `target`: the adaptive row's target PSNR (its image's name), 0 for the others.
  SweepRow& record(const std::string& method, const std::string& pattern, int samples, double seconds,
                   const Image& image, double target = 0.0) {
    const ImageDifference d = compareImages(image, reference, 0.0);
    SweepRow row;
    row.method = method;
    row.pattern = pattern;
    row.samples = samples;
    row.seconds = seconds;
    row.rmse = d.rmse;
    row.psnr = d.psnrDb;
    row.maxError = d.maxAbs;
    row.edgeRmse = maskedRmse(image, reference, edges);
    row.targetPsnr = target;
    if (!imageDir.empty()) {
      row.image = sweepImageName(row);
      // Two rows with one name would leave fewer files than rows (and the report would lie). Cannot
      // happen from the command line, which refuses targets that share a name before any work.
      if (!imageNames.insert(row.image).second) throw std::logic_error(cat("sweep: two rows named ", row.image));
      writeImage(*o.outputs, imageDir / row.image, image);
    }
    result.rows.push_back(row);
    if (o.progress) o.progress("images", static_cast<std::int64_t>(result.rows.size()), imagesPlanned);
    return result.rows.back();
  }
};

void runRasterSeries(SweepRun& run) {
  const SweepOptions& o = run.o;
  for (AperturePattern pattern : {AperturePattern::Lecture17, AperturePattern::Concentric, AperturePattern::R2,
                                  AperturePattern::Random, AperturePattern::Sobol}) {
    if (!run.wanted(patternName(pattern))) continue;
    for (int n : run.budgetsOf(patternName(pattern))) {
      const FramePlan plan = makeFramePlan(run.scene, run.camera, run.size, PlanOptions{pattern, n, n, o.seed});
      Image image;
      const double seconds = medianOf3([&] { return run.renderer.render(run.camera, plan, run.size); }, image);
      run.record("raster", patternName(pattern), n, seconds, image);
    }
    say(o, cat("raster ", patternName(pattern), ": done"));
  }
  // The cell filter on sobol's own cells (powers of two); its pre-pass (the largest circle in view,
  // which bounds how far it gathers) is part of each frame's time.
  if (!run.wanted("cells")) return;
  if (!run.cellsLeftOut.empty()) {
    say(o, cat("cell filter: left out (", run.cellsLeftOut, ")"));
    return;
  }
  for (int n : run.budgetsOf("cells")) {
    PlanOptions options{AperturePattern::Sobol, n, n, o.seed};
    options.cellFilter = true;
    Image image;
    const double seconds = medianOf3(
        [&] {
          const VisibleBlur visible = measureVisibleBlur(run.renderer, run.camera, run.size);
          const FramePlan plan = makeFramePlan(run.scene, run.camera, run.size, options, &visible);
          if (!plan.cellFilter) throw InputError(cat("sweep: cells: ", plan.cellFilterWhy));
          return run.renderer.render(run.camera, plan, run.size);
        },
        image);
    run.record("cell-filter", "sobol", n, seconds, image);
  }
  say(o, "cell filter: done");
}

// The whole of an adaptive frame is timed: the pre-pass, the plan from it, and the rounds.
void runAdaptiveSeries(SweepRun& run) {
  const SweepOptions& o = run.o;
  if (!run.wanted("adaptive")) return;
  for (const double target : o.targetsDb) {
    PlanOptions options{AperturePattern::Sobol, 0, o.maxViews, o.seed};
    options.targetPsnrDb = target;
    FrameEstimate estimate;
    Image image;
    const double seconds = medianOf3(
        [&] {
          const VisibleBlur visible = measureVisibleBlur(run.renderer, run.camera, run.size);
          const FramePlan plan = makeFramePlan(run.scene, run.camera, run.size, options, &visible);
          Image frame = run.renderer.render(run.camera, plan, run.size);
          estimate = run.renderer.estimate();
          return frame;
        },
        image);
    SweepRow& row = run.record("adaptive", kAdaptivePattern, static_cast<int>(std::lround(estimate.meanSamples)),
                               seconds, image, target);
    row.estimatePsnr = estimate.psnrDb;
    row.maxTileSamples = estimate.maxSamples;
    row.meanSamples = estimate.meanSamples;
  }
  say(o, "adaptive: done");
}

// sweep --lens: the fitted camera with each effect left out, at the largest raster budget.
void runLensAblations(SweepRun& run) {
  const SweepOptions& o = run.o;
  for (const auto& [effect, without] : o.lensAblations) {
    const FramePlan plan = makeFramePlan(run.scene, without, run.size,
                                         PlanOptions{AperturePattern::Sobol, o.maxViews, o.maxViews, o.seed});
    Image image;
    const double seconds = medianOf3([&] { return run.renderer.render(without, plan, run.size); }, image);
    run.record("fitted-without", effect, o.maxViews, seconds, image);
  }
  if (!o.lensAblations.empty()) say(o, "fitted lens, each effect left out: done");
}

void runRaycastSeries(SweepRun& run, const RayCaster& caster) {
  const SweepOptions& o = run.o;
  for (int spp : run.budgetsOf("raycast")) {
    const auto t = std::chrono::steady_clock::now();
    const Image image = o.exactLens ? caster.render(*o.exactLens, RaycastOptions{spp, o.seed})
                                    : caster.render(run.camera, run.size, RaycastOptions{spp, o.seed});
    run.record("raycast", "stratified", spp, secondsSince(t), image);
  }
  if (run.wanted("raycast")) say(o, "raycast: done");
}

void runGatherSeries(SweepRun& run) {
  const SweepOptions& o = run.o;
  const std::vector<int> gatherTaps = run.budgetsOf("postprocess");
  if (gatherTaps.empty() && !o.gatherTaps.empty() && run.wanted("postprocess"))
    say(o, run.camera.lens.effects.isZero() ? "postprocess gather: left out (it blurs with round disks only)"
                                            : "postprocess gather: left out (it has no lens effects)");
  for (int taps : gatherTaps) {
    Image image;
    const double seconds = medianOf3(
        [&] { return run.gather.apply(run.camera, run.renderer.renderPinhole(run.camera, run.size), taps); }, image);
    run.record("postprocess", "gather", taps, seconds, image);
  }
  say(o, "postprocess: done");
}

}  // namespace

std::vector<bool> occlusionEdgeMask(const Camera& camera, ImageSize size, const std::vector<double>& depth) {
  const int w = size.widthPx, h = size.heightPx;
  const double pxPerUnit = w / camera.view.window.width();
  std::vector<bool> mask(depth.size(), false);
  auto depthAt = [&](int x, int y) { return depth[static_cast<std::size_t>(y * w + x)]; };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double d = depthAt(x, y);
      const double coc = std::isfinite(d) ? cocDiameterOnWindow(camera, d) : cocDiameterOnWindow(camera, 1e30);
      const int r = static_cast<int>(std::ceil(std::clamp(0.5 * coc * pxPerUnit, 1.0, 32.0)));
      bool edge = false;
      for (int dy = -r; dy <= r && !edge; ++dy)
        for (int dx = -r; dx <= r && !edge; ++dx) {
          const int qx = x + dx, qy = y + dy;
          if (qx < 0 || qy < 0 || qx >= w || qy >= h || dx * dx + dy * dy > r * r) continue;
          const double e = depthAt(qx, qy);
          if (std::isinf(d) != std::isinf(e))
            edge = true;
          else if (std::isfinite(d) && std::abs(d - e) > 0.05 * std::min(d, e))
            edge = true;
        }
      mask[static_cast<std::size_t>(y * w + x)] = edge;
    }
  return mask;
}

double maskedRmse(const Image& a, const Image& b, const std::vector<bool>& mask) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < mask.size(); ++i)
    if (mask[i]) {
      for (int k = 0; k < 3; ++k) {
        const double d = static_cast<double>(a.rgba[i * 4 + static_cast<std::size_t>(k)]) -
                         b.rgba[i * 4 + static_cast<std::size_t>(k)];
        sum += d * d;
      }
      n += 3;
    }
  return n ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

std::vector<std::string> sweepSeriesNames() {
  return {"lecture17", "concentric", "r2", "random", "sobol", "cells", "adaptive", "raycast", "postprocess"};
}

SweepResult runSweep(const Scene& scene, const Camera& camera, ImageSize size, const SweepOptions& o) {
  if (camera.lens.isPinhole())
    throw InputError(
        "sweep: the camera is a pinhole, so there is no depth of field to converge to; give a camera with "
        "f_number (physical form) or aperture_radius (lecture form), or --f-number N");
  SweepResult result;
  assert(o.outDir.empty() || o.outputs);
  // The reference: two independent halves of the samples, averaged. Their difference measures the
  // reference's own noise, which bounds every PSNR the sweep can show: the halves' difference has
  // twice a half's variance, and their mean half of it, so the reference's RMSE against its own
  // limit is RMSE(a, b) / 2.
  const RayCaster caster(scene);
  const fs::path imageDir = o.outDir.empty() ? fs::path() : o.outDir / "images";
  if (!imageDir.empty()) o.outputs->createFolders(imageDir);
  const ReferenceHalves halves = referenceHalves(caster, scene, camera, size, o);
  result.referenceSeconds = halves.seconds;
  result.referenceCached = halves.cached;
  Image reference(size.widthPx, size.heightPx);
  for (std::size_t i = 0; i < reference.rgba.size(); ++i)
    reference.rgba[i] = 0.5f * (halves.halves[0].rgba[i] + halves.halves[1].rgba[i]);
  result.referenceNoiseRmse = 0.5 * compareImages(halves.halves[0], halves.halves[1], 0.0).rmse;

  const auto setupStart = std::chrono::steady_clock::now();
  SweepRun run{scene,       camera,   size, o,  result, std::move(reference), {}, Renderer(scene),
               GatherDof(), imageDir, {},   {}, 0};
  run.edges = pinholeEdges(run.renderer, camera, size);
  result.edgeFraction =
      static_cast<double>(std::count(run.edges.begin(), run.edges.end(), true)) / static_cast<double>(run.edges.size());
  // A warm-up frame (first-frame shader JIT), of each renderer.
  run.renderer.render(camera,
                      makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, 2, 2, o.seed}), size);
  (void)run.gather.apply(camera, run.renderer.renderPinhole(camera, size), 8);
  result.setupSeconds = secondsSince(setupStart);

  {
    PlanOptions cells{AperturePattern::Sobol, 2, 2, o.seed};
    cells.cellFilter = true;
    const FramePlan plan = makeFramePlan(scene, camera, size, cells);
    if (!plan.cellFilter)
      run.cellsLeftOut = plan.cellFilterWhy.substr(plan.cellFilterWhy.rfind("off: ", 0) == 0 ? 5 : 0);
  }
  run.imagesPlanned = run.wanted("adaptive") ? static_cast<std::int64_t>(o.targetsDb.size()) : 0;
  for (const std::string& series : sweepSeriesNames())
    run.imagesPlanned += static_cast<std::int64_t>(run.budgetsOf(series).size());
  run.imagesPlanned += static_cast<std::int64_t>(o.lensAblations.size());
  runRasterSeries(run);
  runAdaptiveSeries(run);
  runLensAblations(run);
  runRaycastSeries(run, caster);
  runGatherSeries(run);
  return result;
}

}  // namespace lenslab
