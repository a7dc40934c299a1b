// Field curvature's module (LensEffectModule.h); the model, the Petzval surface's r² sag in
// inverse distance, is FieldCurvature.h.
//
// Camera file: "field_curvature": {"corner_focus_distance"}: where the image's farthest corner is
// in focus (perspective only). Path: the curvature linear in inverse distance. Plan: the views are
// summed through the curved focal surface's warp (the "field-curvature" variant).
#include "lens/effects/FieldCurvature.h"

#include "core/Text.h"
#include "lens/effects/LensEffectModule.h"

namespace lenslab {
namespace {

const std::set<std::string> kKeys = {"corner_focus_distance"};

void read(const KeyReader& camera, const LensFrame& frame, Lens& lens) {
  if (!camera.has("field_curvature")) return;
  const std::unique_ptr<KeyReader> o = camera.object("field_curvature", kKeys);
  o->require("corner_focus_distance", "field_curvature");
  if (!frame.perspective) camera.fail("field_curvature", "needs a perspective projection");
  const double corner = frame.cornerRadius;
  lens.effects.fieldCurvature.inverseFocusPerRadius2 =
      (inverseOfDistance(*o, "corner_focus_distance") - frame.inverseFocus) / (corner * corner);
}

void write(const Lens& lens, const LensFrame& frame, KeyWriter& camera) {
  const FieldCurvature& f = lens.effects.fieldCurvature;
  if (f.isZero()) return;
  const double corner = frame.cornerRadius;
  camera.object("field_curvature")
      .distance("corner_focus_distance",
                distanceForInverse(frame.inverseFocus + f.inverseFocusPerRadius2 * corner * corner, frame,
                                   "field_curvature.corner_focus_distance"));
}

void interpolate(const Lens& a, const Lens& b, double u, Lens& out) {
  out.effects.fieldCurvature.inverseFocusPerRadius2 =
      lerpValue(a.effects.fieldCurvature.inverseFocusPerRadius2, b.effects.fieldCurvature.inverseFocusPerRadius2, u);
}

void plan(const Lens& lens, const PlanView&, EffectNeeds& needs) {
  if (lens.effects.fieldCurvature.isZero()) return;
  needs.sceneVariants.push_back("field-curvature");
  needs.fieldCurvatureWarp = true;
  needs.idleThroughPinhole = true;
}

}  // namespace

extern const LensEffectModule kFieldCurvatureModule;
const LensEffectModule kFieldCurvatureModule{
    "field_curvature", "accumulate/accumulate.frag", read, write, interpolate, plan};

}  // namespace lenslab
