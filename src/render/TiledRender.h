#pragma once
// Runs a tile plan (plan/TilePlan.h): each tile is rendered by the ordinary renderer through its
// sub-window camera and handed on, cropped, in order, so that only one tile's pixels are held at
// a time.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "core/Image.h"
#include "plan/FramePlan.h"
#include "plan/TilePlan.h"
#include "render/Renderer.h"

#include <cstdint>
#include <functional>
#include <string>

namespace lenslab {

// The current context's render-target limits (plan/TilePlan.h), with the default memory budget.
RenderTargetLimits queryRenderTargetLimits();

// Called with each tile's rectangle in the image and its pixels (rect.size()), in plan order.
using TileSink = std::function<void(const PixelRect& rect, const Image& pixels)>;
// Called as the scene passes go: how many are done of all the tiles' (each tile draws the plan's
// aperture samples; a tile to a target error counts as one), and while a tile's lens tables are
// built a note saying how far ("tile 2 of 4: inverse lens table, 1200/2800 rows"; else empty).
using TileProgress = std::function<void(std::int64_t done, std::int64_t total, const std::string& note)>;

void renderTiles(Renderer& renderer, const Camera& camera, const FramePlan& plan, ImageSize size, const TilePlan& tiles,
                 const TileSink& sink, const TileProgress& progress = {});

// The whole image through the tiles, assembled in memory: for tests and small images.
Image renderTiled(Renderer& renderer, const Camera& camera, const FramePlan& plan, ImageSize size,
                  const TilePlan& tiles);

}  // namespace lenslab
