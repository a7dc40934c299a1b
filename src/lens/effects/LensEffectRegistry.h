#pragma once
// Every lens effect's module, listed once (LensEffectModule.h). The order is the order in which a
// camera file's effect keys are read and in which the plan lists their variants.
#include "lens/effects/LensEffectModule.h"

#include "lens/effects/Vignetting.h"

#include <array>

namespace lenslab {

const std::array<const LensEffectModule*, 6>& lensEffectModules();

// Every module's camera-file key.
std::set<std::string> lensEffectKeys();

// Each module's interpolation between `a` (u = 0) and `b` (u = 1); the radius linearly (a camera
// path's comes from its interpolated f-number instead, camera/CameraPath.h).
Lens interpolateLens(const Lens& a, const Lens& b, double u);

// What a frame needs for every effect of `lens`.
EffectNeeds effectNeeds(const Lens& lens, const PlanView& view);

}  // namespace lenslab
