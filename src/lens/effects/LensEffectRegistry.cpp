#include "lens/effects/LensEffectRegistry.h"

#include "core/Error.h"
#include "core/Text.h"

#include <cmath>

namespace lenslab {

extern const LensEffectModule kDistortionModule;
extern const LensEffectModule kFieldCurvatureModule;
extern const LensEffectModule kChromaticModule;
extern const LensEffectModule kApertureModule;
extern const LensEffectModule kBarrelModule;

const std::array<const LensEffectModule*, 6>& lensEffectModules() {
  // Field curvature before chromatic: the scene pass lists "field-curvature" before "channel-focus".
  static const std::array<const LensEffectModule*, 6> modules = {&kDistortionModule, &kFieldCurvatureModule,
                                                                 &kChromaticModule,  &kVignettingModule,
                                                                 &kApertureModule,   &kBarrelModule};
  return modules;
}

std::set<std::string> lensEffectKeys() {
  std::set<std::string> keys;
  for (const LensEffectModule* m : lensEffectModules()) keys.insert(m->key);
  return keys;
}

Lens interpolateLens(const Lens& a, const Lens& b, double u) {
  Lens out;
  out.apertureRadius = lerpValue(a.apertureRadius, b.apertureRadius, u);
  for (const LensEffectModule* m : lensEffectModules()) m->interpolate(a, b, u, out);
  return out;
}

EffectNeeds effectNeeds(const Lens& lens, const PlanView& view) {
  EffectNeeds needs;
  for (const LensEffectModule* m : lensEffectModules()) m->plan(lens, view, needs);
  return needs;
}

double distanceForInverse(double inverse, const LensFrame& frame, const std::string& key) {
  if (inverse == 0.0) return std::numeric_limits<double>::infinity();
  if (inverse < 0.0)
    throw InputError(cat(frame.where, ": ", key, " lies beyond infinity (inverse distance ", inverse,
                         "); it cannot be written as a distance"));
  return 1.0 / inverse;
}

double inverseOfDistance(const KeyReader& r, const std::string& key) {
  const double distance = r.distance(key);
  if (!(distance > 0.0)) r.fail(key, cat("is ", distance, "; give a distance > 0 or \"infinity\""));
  return std::isinf(distance) ? 0.0 : 1.0 / distance;
}

}  // namespace lenslab
