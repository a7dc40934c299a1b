#pragma once
// The frame plan: per scene and camera, which passes run and how many aperture samples.
// The lens effects' part comes from their modules (lens/effects/LensEffectModule.h, EffectNeeds):
// the plan asks each, and names none.
// Nothing a scene does not need: a pinhole camera with no lens effects, or a scene wholly inside
// the depth of field (every circle of confusion ≤ 1 pixel), is only the jittered views its pixels'
// integral needs (kAntialiasSamples; one plain scene pass when one is asked for). Each lens effect adds its pass or shader variant only when its strength is not zero:
//   distortion, lateral colour → the "lens" post pass (and an overscanned scene render);
//   axial colour               → three views per aperture sample, one per colour channel;
//   field curvature            → the field-curvature variant: views summed through a warp;
//   vignetting                 → the resolve's "vignetting" variant (many views), else the
//                                "vignetting" pass: the image times its gain, once, at the end.
// The last two change nothing through a pinhole, and are left out for one.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "camera/ImageMap.h"
#include "camera/LensMap.h"
#include "lens/AperturePattern.h"
#include "plan/VisibleBlur.h"
#include "scene/Scene.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

struct PlanOptions {
  PlanOptions() = default;
  PlanOptions(AperturePattern pattern_, int apertureSamples_, int maxSamples_, std::uint32_t seed_)
      : pattern(pattern_), apertureSamples(apertureSamples_), maxSamples(maxSamples_), seed(seed_) {}

  AperturePattern pattern = AperturePattern::Sobol;
  int apertureSamples = 0;  // 0 = auto: from the largest circle of confusion in view
  int maxSamples = 256;     // the cap on auto, and on each tile's count with a target
  std::uint32_t seed = 1;
  // Render to a target error instead of a count: per-tile budgets (plan/TileBudget.h) in the
  // progressive 'sobol' order, stopping where the two-stream estimate says the frame's PSNR
  // against its own converged limit reaches this.
  std::optional<double> targetPsnrDb;
  int tileSizePx = 32;
  // Filter each view by its aperture cell's image (render/Accumulator.h): true asks for it, false
  // refuses it; not given, the plan leaves it off.
  std::optional<bool> cellFilter;
};

// Per-tile budgets, when a target error is asked for.
struct AdaptivePlan {
  double targetPsnrDb = 40.0;
  int tileSizePx = 32;
  int maxSamples = 256;         // per tile
  int samplesPerRound = 8;      // both streams: 4 each at first; rounds grow with the count (half of it)
  std::vector<int> minSamples;  // per tile (TileGrid's order: row 0 at the bottom), from the pre-pass
  int sharpTiles = 0;           // tiles whose largest reaching circle is ≤ 1 px
  float lodBias =
      0.0f;  // texture detail of every view (scene.frag): fixed, so the limit does not depend on where a tile stops
};

// The pre-pass's distribution of blur, as `info` and --stats show it.
struct VisibleBlurSummary {
  ImageSize prepass;
  std::array<double, 5> fractions{};  // circles ≤ 1, 1–4, 4–16, 16–64, > 64 px
  double p50Px = 0.0, p90Px = 0.0, p99Px = 0.0, maxPx = 0.0;
  double boundsCocMaxPx = 0.0;  // what the scene's bounds alone would say
  int boundsSamples = 1;        // and the auto count they would give
};

struct PlannedPass {
  std::string name;                   // "scene", "accumulate", "resolve", "lens"
  std::string why;                    // one line, shown by --stats and `lenslab info`
  std::vector<std::string> variants;  // shader variants in use, e.g. "field-curvature"
};

struct FramePlan {
  std::vector<PlannedPass> passes;
  int apertureSamples = 1;  // scene passes, one per point of the aperture
  std::string samplesWhy;   // why that many
  AperturePattern pattern = AperturePattern::Sobol;
  std::uint32_t seed = 1;
  double cocMinPx = 0.0;  // circle of confusion over the part of the scene in view, pixels
  double cocMaxPx = 0.0;
  double depthMin = 0.0;  // that part's depth range, world units from the PRP along −n
  double depthMax = 0.0;
  std::vector<std::string> warnings;  // what the plan could not honour, for stderr
  int viewsPerSample = 1;             // 3 with axial chromatic aberration: one per colour channel
  bool fieldCurvature = false;        // the views are summed through the curved focal surface's warp
  bool remap = false;                 // the lens post pass runs (distortion, lateral colour)
  int remapTables = 0;                // its inverse lookup tables: 1, or 3 with lateral colour (one per channel)
  bool vignetting = false;            // the image is multiplied by the vignetting gain (lens/LensEffects.h)
  Overscan overscan;                  // what the scene passes render: the image, or more for the lens pass
  std::optional<VisibleBlurSummary> visible;  // from a pinhole depth pre-pass, when one ran
  std::optional<AdaptivePlan> adaptive;       // per-tile budgets to a target error
  bool cellFilter = false;                    // each view filtered by its aperture cell's image ('rings' cells)
  std::string cellFilterWhy;                  // why it is on or off, for --stats

  bool accumulates() const { return apertureSamples > 1; }
};

// Auto sample count for a largest circle of confusion of `cocPx` pixels: enough aperture points
// that their copies of a point, spread over the circle's area π·c²/4, lie about a pixel apart.
int autoApertureSamples(double cocPx, int maxSamples);

// The fewest views auto gives any frame, a pinhole's included: each view is jittered within the
// pixel, so the frame is the box-filtered pixel integral (anti-aliased), not one point per pixel.
// 16 reach 41.7 dB against the ray cast on `rows` through the pinhole at 960 px (one view: 29.7 dB;
// 8: 37.9 dB; docs/sampling.md, Anti-aliasing). An explicit count, 1 included, is honoured as given.
constexpr int kAntialiasSamples = 16;

// `visible`: the pre-pass's blur (plan/VisibleBlur.h); without it the circle of confusion comes
// from the scene's bounds, which can only overstate it.
FramePlan makeFramePlan(const Scene& scene, const Camera& camera, ImageSize size, const PlanOptions& options = {},
                        const VisibleBlur* visible = nullptr);

// The tiles' minimum counts: a few for antialiasing where the largest reaching circle is ≤ 1 px,
// more where blur reaches (so the estimate has something to go on before it is trusted).
constexpr int kMinSamplesSharpTile = 8;
constexpr int kMinSamplesBlurredTile = 16;
constexpr int kLodSamples = 64;  // per-tile frames filter textures as for this many samples

}  // namespace lenslab
