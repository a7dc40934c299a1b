#include "plan/FramePlan.h"

#include "camera/DepthRange.h"
#include "core/Error.h"
#include "core/Text.h"
#include "lens/ApertureCells.h"
#include "lens/effects/LensEffectRegistry.h"
#include "plan/TileBudget.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace lenslab {

int autoApertureSamples(double cocPx, int maxSamples) {
  if (!(cocPx > 1.0)) return 1;
  const double n = std::ceil(std::numbers::pi / 4.0 * cocPx * cocPx);
  return static_cast<int>(std::clamp(n, 2.0, static_cast<double>(std::max(maxSamples, 1))));
}

namespace {

// The fewest views auto gives (kAntialiasSamples), within --max-samples.
int antialiasSamples(const PlanOptions& options) {
  return std::min(kAntialiasSamples, std::max(options.maxSamples, 1));
}

// Depth range of the scene's bounds seen from the PRP, clipped to [near, far].
void depthRange(const Scene& scene, const Camera& camera, FramePlan& plan) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  if (!scene.bounds.empty()) {
    const DepthInterval d = depthIntervalOf(camera.view, scene.bounds);
    lo = d.nearest;
    hi = d.farthest;
  }
  plan.depthMin = std::max(lo, camera.view.nearDistance);
  plan.depthMax = std::min(hi, camera.view.farDistance);
  // An environment is seen wherever nothing else is, at infinity (beyond any far plane).
  if (scene.environment && camera.view.projection == Projection::Perspective)
    plan.depthMax = std::numeric_limits<double>::infinity();
}

// What the lens-effect modules are told of `camera` (lens/effects/LensEffectModule.h).
PlanView planViewOf(const Camera& camera) {
  const ViewSpec& v = camera.view;
  PlanView view;
  view.inverseFocus = camera.inverseFocusDistance();
  for (const double u : {v.window.umin, v.window.umax})
    for (const double w : {v.window.vmin, v.window.vmax})
      view.farthestCornerSlope =
          std::max(view.farthestCornerSlope, glm::length(glm::dvec2(u - v.prp.x, w - v.prp.y)) / v.prp.z);
  return view;
}

// The raster draws a lens's image from one undistorted render that holds the true perspective
// position of each of its pixels. Toward 90° from the axis (a fisheye's field) that position runs
// off as tan θ and the render with it: beyond this many times the image's side it is refused,
// naming the ray caster, which casts each pixel's ray itself.
constexpr double kMaxOverscanPerSide = 8.0;

void checkOverscan(const Camera& camera, ImageSize size, const Overscan& overscan) {
  const double factor = std::max(static_cast<double>(overscan.size.widthPx) / size.widthPx,
                                 static_cast<double>(overscan.size.heightPx) / size.heightPx);
  if (factor <= kMaxOverscanPerSide) return;
  throw InputError(cat(camera.source, ": the raster would draw this ", size.widthPx, "x", size.heightPx,
                       " image from an undistorted render of ", overscan.size.widthPx, "x", overscan.size.heightPx,
                       " pixels (", std::lround(factor), " times a side, at most ", kMaxOverscanPerSide,
                       "): the lens (", distortionTermsText(camera.lens.effects.distortion),
                       ") shows directions far from the axis, where a perspective view stretches without bound; "
                       "ray cast it (lenslab raycast), or narrow its field"));
}

}  // namespace

namespace {

// Views of a pinhole: every view is the same view and only the sub-pixel jitter differs, so views
// are anti-aliasing (the box-filtered pixel integral): auto gives kAntialiasSamples of them, an
// explicit count that many (1: one view from the PRP).
void planPinholeSamples(const PlanOptions& options, FramePlan& plan) {
  if (options.pattern == AperturePattern::Lecture17) {
    plan.apertureSamples = 17;
    plan.samplesWhy = "pinhole camera: the lecture's 17-point pattern as 17 sub-pixel-jittered views (anti-aliasing)";
  } else if (options.apertureSamples > 1) {
    plan.apertureSamples = options.apertureSamples;
    plan.samplesWhy =
        cat("pinhole camera: ", options.apertureSamples, " sub-pixel-jittered views as asked (anti-aliasing)");
  } else if (options.apertureSamples == 1) {
    plan.apertureSamples = 1;
    plan.samplesWhy = "pinhole camera: one view from the PRP, as asked (not anti-aliased)";
  } else {
    plan.apertureSamples = antialiasSamples(options);
    plan.samplesWhy = cat("pinhole camera: auto, ", plan.apertureSamples,
                          " sub-pixel-jittered views (anti-aliasing: the pixel integral; --aperture-samples 1 for "
                          "one view)");
  }
}

// The circle of confusion over the scene's depths (cocMinPx, cocMaxPx), or over what the pre-pass
// saw; returns the range in words for samplesWhy.
std::string planCircles(const Camera& camera, ImageSize size, const PlanOptions& options, const VisibleBlur* visible,
                        FramePlan& plan) {
  const double pxPerWindowUnit = size.widthPx / camera.view.window.width();
  if (plan.depthMax >= plan.depthMin && plan.depthMax > 0.0) {
    // Axial colour and field curvature move the plane of focus per channel and toward the
    // corners: the largest circle is the largest over each of those planes.
    plan.cocMaxPx = 0.0;
    plan.cocMinPx = std::numeric_limits<double>::infinity();
    for (const double shift : extremeFocusShifts(camera)) {
      const double atNear = cocDiameterOnWindow(camera, plan.depthMin, shift) * pxPerWindowUnit;
      const double atFar = cocDiameterOnWindow(camera, plan.depthMax, shift) * pxPerWindowUnit;
      plan.cocMaxPx = std::max({plan.cocMaxPx, atNear, atFar});
      // The circle shrinks to nothing on the plane of focus, and grows away from it on both sides.
      const double inverse = camera.inverseFocusDistance() + shift;
      const double focus = inverse > 0.0 ? 1.0 / inverse : std::numeric_limits<double>::infinity();
      plan.cocMinPx =
          std::min(plan.cocMinPx, (focus >= plan.depthMin && focus <= plan.depthMax) ? 0.0 : std::min(atNear, atFar));
    }
  }
  if (!visible)
    return cat("circle of confusion ", plan.cocMinPx, " to ", plan.cocMaxPx, " px over depths ", plan.depthMin, " to ",
               plan.depthMax);
  // What is seen, not what the bounds could hold.
  VisibleBlurSummary v;
  v.prepass = visible->prepass;
  v.fractions = visible->fractions;
  v.p50Px = visible->p50Px;
  v.p90Px = visible->p90Px;
  v.p99Px = visible->p99Px;
  v.maxPx = visible->maxPx;
  v.boundsCocMaxPx = plan.cocMaxPx;
  v.boundsSamples = autoApertureSamples(plan.cocMaxPx, options.maxSamples);
  plan.visible = v;
  plan.cocMinPx = visible->ownMinPx;
  plan.cocMaxPx = visible->maxPx;
  return cat("circle of confusion seen ", plan.cocMinPx, " to ", plan.cocMaxPx, " px (pinhole depth pre-pass at ",
             v.prepass.widthPx, "x", v.prepass.heightPx, ", dilated by nearer circles; the bounds would say ",
             v.boundsCocMaxPx, " px)");
}

// Views through an aperture: the pattern's, the count asked, or as many as the largest circle
// needs — and at least what an effect needs however sharp the scene is (`least`: the barrel's cat's eye).
void planLensSamples(const PlanOptions& options, const std::string& range, const EffectNeeds& least, FramePlan& plan) {
  if (options.pattern == AperturePattern::Lecture17) {
    plan.apertureSamples = 17;
    plan.samplesWhy = cat("the lecture's 17-point pattern (", range, ")");
    return;
  }
  if (options.apertureSamples > 0) {
    plan.apertureSamples = options.apertureSamples;
    plan.samplesWhy = cat("as asked (", range, ")");
    return;
  }
  plan.apertureSamples = autoApertureSamples(plan.cocMaxPx, options.maxSamples);
  const int antialias = antialiasSamples(options);
  if (plan.apertureSamples < antialias) {
    plan.apertureSamples = antialias;
    plan.samplesWhy =
        cat("auto: ", antialias, " views for anti-aliasing, which the blur does not need more than (", range, ")");
  } else
    plan.samplesWhy =
        cat("auto: ceil(pi/4 x ", plan.cocMaxPx, "^2)",
            plan.apertureSamples == options.maxSamples ? cat(" capped at --max-samples ", options.maxSamples)
                                                       : std::string(),
            " (", range, ")");
  if (plan.apertureSamples < std::min(least.minApertureSamples, options.maxSamples)) {
    plan.apertureSamples = std::min(least.minApertureSamples, options.maxSamples);
    plan.samplesWhy = cat(plan.apertureSamples, ": ", least.minSamplesWhy, " (", range, ")");
  }
}

// Per-tile budgets (--target-psnr): the count is each tile's own, up to the cap; the order progressive.
void planAdaptive(const Camera& camera, ImageSize size, const PlanOptions& options, const VisibleBlur* visible,
                  FramePlan& plan) {
  AdaptivePlan a;
  a.targetPsnrDb = *options.targetPsnrDb;
  a.tileSizePx = options.tileSizePx;
  a.maxSamples = std::max(options.maxSamples / 2 * 2, 2);  // even: the two streams stay equal
  // Each view's textures are filtered over 1/64 of the pixel (or 1/max, if less): finer than the
  // strata of any count up to 64, and beyond that the filter's own blur is under 1/8 pixel. One
  // fixed filter for all counts keeps the converged image the same wherever a tile stops.
  a.lodBias = -0.5f * std::log2(static_cast<float>(std::min(a.maxSamples, kLodSamples)));
  const TileGrid grid = makeTileGrid(size, a.tileSizePx);
  for (int t = 0; t < grid.count(); ++t) {
    const PixelBox b = grid.box(t);
    // The pre-pass's rows run from the top.
    const double coc = camera.lens.isPinhole() ? 0.0
                       : visible
                           ? visible->maxOver(b.x, size.heightPx - b.y - b.height, b.x + b.width, size.heightPx - b.y)
                           : plan.cocMaxPx;
    a.sharpTiles += coc <= 1.0;
    a.minSamples.push_back(std::min(coc <= 1.0 ? kMinSamplesSharpTile : kMinSamplesBlurredTile, a.maxSamples));
  }
  plan.pattern = AperturePattern::Sobol;
  plan.apertureSamples = a.maxSamples;
  plan.samplesWhy = cat("to ", a.targetPsnrDb, " dB: ", grid.count(), " tiles of ", a.tileSizePx, " px, each from ",
                        kMinSamplesSharpTile, " (", a.sharpTiles, " tiles in focus) or ", kMinSamplesBlurredTile,
                        " samples (blurred) up to ", a.maxSamples,
                        ", in sobol order, stopping where the two streams' "
                        "estimate says one more sample gains least (",
                        camera.lens.isPinhole() ? std::string("pinhole camera") : plan.samplesWhy, ")");
  plan.adaptive = std::move(a);
}

// Whether each view is filtered by its aperture cell's image: only where asked, and only for a thin
// lens's plain views, of any aperture shape (the filter knows the thin lens's spread and the
// shape's map, not the lens effects' warps).
void planCellFilter(const ThinLensMap& map, const PlanOptions& options, FramePlan& plan) {
  const Camera& camera = map.camera();
  if (!options.cellFilter.value_or(false)) {
    // Auto leaves it off: measured on llvmpipe, the filtered frame of fewer views never took less
    // time than the plain frame of the same PSNR (docs/performance.md, "Fewer views: the cell filter").
    plan.cellFilterWhy = options.cellFilter
                             ? "off (--cell-filter off)"
                             : "off (auto: measured on llvmpipe, a filtered frame took 2.5-4.1x the time of a "
                               "plain frame of the same PSNR; --cell-filter on asks for it)";
    return;
  }
  const char* against = !plan.accumulates() || camera.lens.isPinhole() ? "a pinhole or a single view has no cells"
                        : plan.adaptive ? "per-tile budgets (--target-psnr) draw views in parts"
                        : plan.remap    ? "distortion and lateral colour move each view's samples as they are summed"
                        : plan.fieldCurvature     ? "field curvature warps each view as it is summed"
                        : camera.lens.hasBarrel() ? "the barrel masks each view per pixel"
                        : camera.view.projection != Projection::Perspective ? "a parallel projection"
                                                                            : nullptr;
  if (against) {
    plan.cellFilterWhy = cat("off: ", against);
    plan.warnings.push_back(cat("--cell-filter on is not used: ", against));
    return;
  }
  plan.cellFilter = true;
  // Views rendered with a margin as wide as the images reach, so that those reaching in from beyond
  // the frame's edge are there to gather.
  const int margin = std::min(kCellFilterMaxReachPx,
                              static_cast<int>(std::ceil(plan.cocMaxPx * apertureReach(camera.lens.aperture))) + 1);
  plan.overscan = map.paddedBy({margin, margin}).overscan();
  // The pattern's own cells where it has them (sobol at a power of two), else rings of equal cells.
  if (!hasCells(plan.pattern, plan.apertureSamples)) plan.pattern = AperturePattern::Rings;
  plan.cellFilterWhy =
      cat("on: each of the ", plan.apertureSamples, " views spread over its cell of the aperture (",
          plan.pattern == AperturePattern::Sobol ? "sobol's elementary boxes" : "rings of equal-area cells", ")");
}

// The passes that run, each with why, from the views planned and what the effects need.
void planPasses(const Camera& camera, std::size_t triangles, const EffectNeeds& needs,
                const std::vector<std::string>& sceneVariants, FramePlan& plan) {
  const ImageSize rendered = plan.overscan.size;
  const std::string where = plan.remap
                                ? cat(" at ", rendered.widthPx, "x", rendered.heightPx, " (", plan.overscan.padPx.x,
                                      "+", plan.overscan.padPx.y, " px overscan for the lens pass)")
                                : std::string();
  if (plan.apertureSamples == 1) {
    plan.passes.push_back({"scene", cat("one view of ", triangles, " triangles into a float target", where), {}});
  } else if (plan.adaptive) {
    PlannedPass scenePass{"scene",
                          cat("up to ", plan.apertureSamples * plan.viewsPerSample, " views per tile of ", triangles,
                              " triangles, in rounds of ", plan.adaptive->samplesPerRound,
                              " samples drawn only into the tiles that still need them (scissor rectangles)", where),
                          {}};
    scenePass.variants = sceneVariants;
    plan.passes.push_back(scenePass);
    plan.passes.push_back(
        {"accumulate",
         "adds each view into one of two float sums (even samples, odd samples: two independent streams)",
         {}});
    plan.passes.push_back(
        {"estimate", "after each round, each tile's squared error from the difference of its two streams' means", {}});
    plan.passes.push_back({"resolve", "divides the two sums by each tile's own weight", {"two-streams"}});
  } else {
    PlannedPass scenePass{"scene",
                          cat(plan.apertureSamples * plan.viewsPerSample, " views of ", triangles, " triangles, ",
                              plan.viewsPerSample == 3 ? "one per colour channel (axial chromatic aberration) at each "
                                                       : "one from each ",
                              patternName(plan.pattern), camera.lens.isPinhole() ? " sample" : " aperture point",
                              ", with sub-pixel jitter", where),
                          {}};
    scenePass.variants = sceneVariants;
    plan.passes.push_back(scenePass);
    plan.passes.push_back(
        {"accumulate",
         plan.cellFilter
             ? cat("spreads each view over its aperture cell's image at each pixel's depth and adds it into a float "
                   "sum (",
                   plan.apertureSamples * plan.viewsPerSample, " times)")
             : cat("adds each view into a float sum (", plan.apertureSamples * plan.viewsPerSample, " times)"),
         plan.cellFilter ? std::vector<std::string>{"cell-filter"} : std::vector<std::string>{}});
    plan.passes.push_back({"resolve",
                           plan.viewsPerSample == 3 ? "divides each channel's sum by its view count"
                                                    : "divides the sum by the sample count",
                           {}});
  }
  if (plan.remap) {
    PlannedPass lens{
        "lens",
        plan.apertureSamples > 1
            ? cat("carries each view's samples to where the lens puts them as the views are summed (forward table with "
                  "Jacobian; inverse table per ",
                  plan.remapTables == 3 ? "colour channel" : "image",
                  "); each pixel the mean of the samples landing in it")
            : cat("remaps the image through the inverse lens model (a lookup table per ",
                  plan.remapTables == 3 ? "colour channel" : "image", ", bilinear)"),
        {}};
    lens.variants = needs.lensVariants;
    plan.passes.push_back(lens);
  }
  plan.vignetting = !needs.finalGain.empty();
  if (plan.vignetting) {
    const std::string& gain = needs.finalGain;
    // A resolve of many views ends the frame and multiplies the gain in; else a pass of its own.
    const auto resolve =
        std::find_if(plan.passes.begin(), plan.passes.end(), [](const PlannedPass& p) { return p.name == "resolve"; });
    if (resolve != plan.passes.end() && !plan.adaptive) {
      resolve->why += cat(", times ", gain);
      resolve->variants.push_back("vignetting");
    } else {
      plan.passes.push_back({"vignetting", cat("multiplies the image by ", gain), {}});
    }
  }
}

}  // namespace

FramePlan makeFramePlan(const Scene& scene, const Camera& camera, ImageSize size, const PlanOptions& options,
                        const VisibleBlur* visible) {
  FramePlan plan;
  // The frame's image map, built once, and its render for the lens pass (the image itself without one).
  const ThinLensMap map(camera, size);
  const ThinLensMap rendered = map.overscanned();
  checkOverscan(camera, size, rendered.overscan());
  plan.pattern = options.pattern;
  plan.seed = options.seed;
  depthRange(scene, camera, plan);
  if (camera.lens.isPinhole()) {
    planPinholeSamples(options, plan);
  } else {
    const std::string range = planCircles(camera, size, options, visible, plan);
    // With distortion the barrel clips at the undistorted field, which the overscan's window holds.
    planLensSamples(options, range, effectNeeds(camera.lens, planViewOf(rendered.overscan().camera)), plan);
  }
  if (options.targetPsnrDb) planAdaptive(camera, size, options, visible, plan);

  // What each lens effect asks of the frame (lens/effects/); per-view effects only with many views
  // through an aperture.
  const EffectNeeds needs = effectNeeds(camera.lens, planViewOf(camera));
  std::vector<std::string> sceneVariants;
  if (plan.apertureSamples > 1 && !camera.lens.isPinhole()) {
    plan.viewsPerSample = needs.viewsPerSample;
    plan.fieldCurvature = needs.fieldCurvatureWarp;
    sceneVariants = needs.sceneVariants;
  }
  plan.remap = !needs.lensVariants.empty();
  plan.remapTables = needs.remapTables;
  if (plan.remap) map.validateForwardLinearisation();
  plan.overscan = rendered.overscan();
  planCellFilter(map, options, plan);
  planPasses(camera, scene.triangleCount(), needs, sceneVariants, plan);
  if (camera.lens.isPinhole() && needs.idleThroughPinhole)
    plan.warnings.push_back(
        "axial chromatic aberration and field curvature blur out-of-focus points; a pinhole camera "
        "has none, so they change nothing here (give an aperture)");
  return plan;
}

}  // namespace lenslab
