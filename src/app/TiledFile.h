#pragma once
// `render` of an image larger than what one render target or the memory budget holds: its tile
// plan, and the frame rendered tile by tile into the output file, written a strip at a time
// (io/StripImageWriter.h), so that memory is bounded by the tile, not the frame.
#include "app/Stats.h"
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "io/Progress.h"
#include "io/ToneMap.h"
#include "plan/FramePlan.h"
#include "plan/TilePlan.h"
#include "render/Renderer.h"

#include <filesystem>

namespace lenslab {

class OutputSet;

// The tile plan for writing `out`: a frame whose render would hold more than a tile's budget is
// tiled, and a tile row is no taller than the writer's strip budget allows (which depends on the
// file's format). `tileSizePx` 0: tile only when it must.
TilePlan tilesForFile(const Camera& camera, ImageSize size, const FramePlan& plan, const std::filesystem::path& out,
                      int tileSizePx);

// Renders `plan` in `tiles` and writes them to `out`'s temporary file in `outputs`, each through
// `display`. Sets stats' render and write times and adds the "tiles" pass to stats.plan. Throws
// InputError for --exposure auto before any tile: no whole frame is there to meter.
void renderTiledToFile(Renderer& renderer, const Camera& camera, const FramePlan& plan, ImageSize size,
                       const TilePlan& tiles, OutputSet& outputs, const std::filesystem::path& out,
                       const DisplaySettings& display, RunStats& stats, ProgressReporter& progress);

}  // namespace lenslab
