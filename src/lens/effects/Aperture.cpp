// The aperture shape's module (LensEffectModule.h); the model, blades, roundness and the
// anamorphic squeeze as an area-preserving map of the unit disk, is lens/ApertureShape.h.
//
// Camera file: "aperture": {"blades", "rotation_deg", "roundness", "anamorphic_squeeze"}.
// Path: the iris does not change along a shot: held from the segment's first key (the path
// reader refuses keys that differ). Plan: no pass of its own; its reach widens the circles of
// confusion the sample count is sized by (camera/Camera.h, cocDiameterOnWindow).
#include "lens/effects/LensEffectModule.h"

namespace lenslab {
namespace {

const std::set<std::string> kKeys = {"blades", "rotation_deg", "roundness", "anamorphic_squeeze"};

void read(const KeyReader& camera, const LensFrame&, Lens& lens) {
  if (!camera.has("aperture")) return;
  const std::unique_ptr<KeyReader> o = camera.object("aperture", kKeys);
  ApertureShape& a = lens.aperture;
  if (o->has("blades")) a.blades = o->integer("blades");
  if (o->has("rotation_deg")) a.rotationDeg = o->number("rotation_deg");
  if (o->has("roundness")) a.roundness = o->number("roundness");
  if (o->has("anamorphic_squeeze")) a.anamorphicSqueeze = o->number("anamorphic_squeeze");
  if (const std::optional<ApertureProblem> problem = apertureShapeProblem(a)) o->fail(problem->field, problem->message);
}

void write(const Lens& lens, const LensFrame&, KeyWriter& camera) {
  const ApertureShape& a = lens.aperture;
  if (a == ApertureShape{}) return;
  KeyWriter& o = camera.object("aperture");
  if (a.blades != 0) o.integer("blades", a.blades);
  if (a.rotationDeg != 0.0) o.number("rotation_deg", a.rotationDeg);
  if (a.roundness != 0.0) o.number("roundness", a.roundness);
  if (a.anamorphicSqueeze != 1.0) o.number("anamorphic_squeeze", a.anamorphicSqueeze);
}

void interpolate(const Lens& a, const Lens&, double, Lens& out) { out.aperture = a.aperture; }

void plan(const Lens&, const PlanView&, EffectNeeds&) {}

}  // namespace

extern const LensEffectModule kApertureModule;
const LensEffectModule kApertureModule{"aperture", "", read, write, interpolate, plan};

}  // namespace lenslab
