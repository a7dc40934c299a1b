#pragma once
// Focus on what a pixel shows: the lecture's plane of focus moved to the depth of the surface
// under it (--focus-at, the view's click).
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "camera/PhysicalCamera.h"

#include <glm/glm.hpp>

#include <functional>
#include <string>

namespace lenslab {

// Depth (world units from the PRP along −n; +infinity for the background) of pixel (x, y) of a
// pinhole view of `camera` at `size`: the rasterizer's depth buffer or the ray caster provide it.
using DepthAtPixel = std::function<double(const Camera&, ImageSize, int x, int y)>;

// Focuses on the depth under pixel (x, y); throws InputError when nothing is there or the pixel
// is outside the image, naming `asked` — how the user asked: "--focus-at", "--click", "click at
// image pixel" — before the pixel. With distortion or lateral colour the pixel is first taken back to the
// true perspective image (green's), which is looked up in the overscanned pinhole view the lens
// pass would sample. The depth found is applied as --focus-distance is (refocused(SelectedCamera)):
// a physical camera's field of view follows its image distance. Near/far are the converted
// camera's: fit them to the scene again (camera/DepthRange.h) before rendering.
SelectedCamera focusOnPixel(const SelectedCamera& camera, ImageSize size, glm::dvec2 pixel, const DepthAtPixel& depthAt,
                            const std::string& asked);

}  // namespace lenslab
