// The lens barrel's module (LensEffectModule.h): cat's-eye vignetting; the model is
// lens/LensBarrel.h.
//
// Camera file: "barrel": {"distance_mm", "diameter_mm"}, both required (perspective only).
// Path: the barrel does not change along a shot: held from the segment's first key (the path
// reader refuses keys that differ). Plan: where the barrel clips the aperture seen from the
// farthest corner, the frame takes at least kBarrelMinSamples views.
#include "lens/effects/LensEffectModule.h"

#include <cmath>

namespace lenslab {
namespace {

const std::set<std::string> kKeys = {"distance_mm", "diameter_mm"};
constexpr double kMetresPerMillimetre = 1e-3;  // world units are metres

// Views a frame takes at least where the barrel clips it: the cat's eye is a share of the
// aperture, resolved to about 1/64 by as many aperture points, however sharp the scene is.
constexpr int kBarrelMinSamples = 64;

void read(const KeyReader& camera, const LensFrame& frame, Lens& lens) {
  if (!camera.has("barrel")) return;
  const std::unique_ptr<KeyReader> o = camera.object("barrel", kKeys);
  o->require("distance_mm", "barrel");
  o->require("diameter_mm", "barrel");
  const double distance = o->number("distance_mm"), diameter = o->number("diameter_mm");
  if (const std::optional<BarrelProblem> problem = barrelProblem(distance, diameter))
    o->fail(problem->field, problem->message);
  if (!frame.perspective) camera.fail("barrel", "needs a perspective projection");
  lens.barrel = barrelFromMillimetres(distance, diameter);
}

void write(const Lens& lens, const LensFrame&, KeyWriter& camera) {
  if (!lens.barrel.present()) return;
  KeyWriter& o = camera.object("barrel");
  o.number("distance_mm", lens.barrel.distance / kMetresPerMillimetre);
  o.number("diameter_mm", 2.0 * lens.barrel.radius / kMetresPerMillimetre);
}

void interpolate(const Lens& a, const Lens&, double, Lens& out) { out.barrel = a.barrel; }

// Whether the barrel hides part of the aperture from some pixel: from the window's farthest corner
// the aperture, seen in the opening's plane (radius R·|1 − L/z_f| about L·n), reaches past it.
void plan(const Lens& lens, const PlanView& view, EffectNeeds& needs) {
  const LensBarrel& b = lens.barrel;
  if (!lens.hasBarrel()) return;
  const double seen =
      lens.apertureRadius * apertureReach(lens.aperture) * std::abs(1.0 - b.distance * view.inverseFocus);
  if (!(b.distance * view.farthestCornerSlope + seen > b.radius)) return;
  needs.minApertureSamples = std::max(needs.minApertureSamples, kBarrelMinSamples);
  needs.minSamplesWhy =
      "the lens barrel hides part of the aperture toward the corners (cat's-eye vignetting), a share "
      "resolved by that many aperture points";
}

}  // namespace

extern const LensEffectModule kBarrelModule;
const LensEffectModule kBarrelModule{"barrel", "accumulate/accumulate.frag", read, write, interpolate, plan};

}  // namespace lenslab
