#pragma once
// The depth under a pixel from the rasterizer's pinhole depth buffer, for focusOnPixel.
#include "camera/FocusOnPixel.h"

namespace lenslab {

class Renderer;

// `renderer` must outlive the returned function.
DepthAtPixel rasterDepth(Renderer& renderer);

}  // namespace lenslab
