#pragma once
// The flow AOV (core/Aovs.h, `capture --aov flow`): for each pixel, where the surface it shows at
// frame t lands at frame t + 1, minus where it is at t, in output pixels (x right, y down): the
// camera's motion and the motion of the glTF node that carries the surface, each frame seen
// through its own lens (distortion included). Per pixel, the surface point P along the pixel
// centre's ray (the ray the other AOVs follow) at the depth AOV's distance, carried by its node
// from t to t + 1, projected through both frames' cameras (ThinLensMap::pixelOfPoint). NaN where
// nothing is hit, where P is not in front of the next frame's lens, or where there is no next
// frame. Occlusion is not tested: a point hidden at t + 1 still gets the motion of its surface
// (as Blender's vector pass and the usual flow datasets' "occluded" pixels do).
#include "camera/ImageMap.h"
#include "core/Aovs.h"

#include <glm/glm.hpp>

#include <map>
#include <vector>

namespace lenslab {

// Each glTF node's motion from t to t + 1 as a world transform: worldFromNode(t + 1) ·
// worldFromNode(t)⁻¹. A node not listed does not move.
using NodeMotion = std::map<int, glm::dmat4>;

// The flow of `now`'s image (2 values a pixel) from its depth and instance AOVs (`surfaces`, of
// `now`'s size) to `next` (nullptr: no next frame, all NaN).
std::vector<float> opticalFlow(const ThinLensMap& now, const AovImages& surfaces, const ThinLensMap* next,
                               const NodeMotion& motion);

}  // namespace lenslab
