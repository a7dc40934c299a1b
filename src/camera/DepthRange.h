#pragma once
// Depth precision chosen from the scene. Reverse-Z float depth resolves distances to about
// z·6e-8 when far is at infinity; a telephoto whose subject is 1e9 away would then merge surfaces
// 60 units apart. When the camera leaves near or far open (the file did not give them), they are
// fitted to the scene's bounds as seen along the view direction, so that the depth buffer spends
// its precision on the interval where the scene is. Fitting never clips the scene: the bounds are
// conservative and a margin is added on both sides.
#include "camera/Camera.h"
#include "core/Bounds.h"

namespace lenslab {

// Nearest and farthest depth (along −n from the PRP, world units) of the corners of `bounds`.
struct DepthInterval {
  double nearest;
  double farthest;
};
DepthInterval depthIntervalOf(const ViewSpec& view, const Bounds& bounds);

// The camera with its open near/far fitted to `bounds` (perspective only: a parallel projection's
// depth is linear and needs no fitting). A given near or far is kept; an open near is never brought
// nearer than the camera's default, nor than 1e-6 of the scene's farthest depth (float clipping).
Camera withDepthRangeFitted(const Camera& camera, const Bounds& bounds);

}  // namespace lenslab
