#pragma once
// The frame plan's pre-pass: a pinhole depth map at low resolution, turned into the blur the frame
// will show (plan/VisibleBlur.h).
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "plan/VisibleBlur.h"

namespace lenslab {

class Renderer;

// One pinhole view of depth at prepassSizeFor(image) (about 320 px wide), read back.
VisibleBlur measureVisibleBlur(Renderer& renderer, const Camera& camera, ImageSize image);

}  // namespace lenslab
