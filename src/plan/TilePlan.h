#pragma once
// Images beyond one render target, by tiling. Each tile is a sub-window of the same view plane
// with the same PRP (camera/SubWindow.h): the same rays per pixel, the same aperture samples and
// sub-pixel jitter (the frame's plan, seed and sample count), so a tiled image equals the untiled
// one up to rounding.
//
// What a tile's pixels need from outside the tile is rendered with it, as margins, then dropped:
//   distortion, lateral colour: the pre-image of the tile under the inverse lens model (its
//     border's bounding box, per remapped channel) plus the gather's reach;
//   field curvature: each view is summed through a warp that reads up to δ·d·κ·r² pixels away,
//     plus the Catmull–Rom taps.
// Margins stop where the full frame's render stops (its own overscan), so a tile's scene passes
// render exactly the texels of the full frame's that its pixels read, and the edge clamping of
// the lens gather and the warp happens at the same place.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "camera/SubWindow.h"
#include "plan/FramePlan.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lenslab {

// What one render target may hold: the GL implementation's limits (the smallest of
// GL_MAX_TEXTURE_SIZE, GL_MAX_RENDERBUFFER_SIZE, GL_MAX_VIEWPORT_DIMS, GL_MAX_FRAMEBUFFER_WIDTH /
// HEIGHT) and a memory budget for one RGBA32F target.
struct RenderTargetLimits {
  int maxSidePx = 16384;
  std::int64_t maxPixels = kTargetBudgetBytes / 16;

  static constexpr std::int64_t kTargetBudgetBytes = std::int64_t{256} << 20;  // 256 MiB: 4096² RGBA32F
};

// What `render` lets one tile and the output's strip hold (bytes), so that a frame's peak memory is
// bounded by its tiles whatever its size: a frame whose render needs more than `tileBytes`
// (tileMemoryBytes) is tiled although one render target could hold it.
struct TileMemory {
  // One tile's render targets, lens tables and read-back as tileMemoryBytes models them; the process
  // peaks at about 1.6 times that (llvmpipe's staging and transient copies as targets are resolved
  // and read back), plus the strip and about 220 MB for the context, the scene and the programs.
  std::int64_t tileBytes = std::int64_t{320} << 20;
  std::int64_t stripBytes = std::int64_t{256} << 20;  // the writer's strip: image width × a tile row's height
  int fileBytesPerPixel = 16;                         // the strip's pixels: 16 (EXR, float RGBA), 3 (PNG)
};

struct Tile {
  PixelRect rect;      // the image's pixels it gives
  PixelRect rendered;  // the pixels its scene passes render: rect plus margins, within the full frame's render
};

struct TilePlan {
  bool tiled = false;   // false: one ordinary render of the whole frame
  int tileWidthPx = 0;  // the tiles' size (the last column and row may be smaller)
  int tileHeightPx = 0;
  std::vector<Tile> tiles;  // row by row from the top, left to right
  std::string why;          // one line, for --stats and the progress message
};

// Tiles when the frame's render (with the lens pass's overscan) exceeds `limits` or, given
// `memory`, its budget, or when `forcedTileSidePx` > 0 (at most that many pixels a side). Tiles are
// as large as the limits and the budget allow with their margins, and of nearly equal size. Throws
// InputError when even small tiles cannot hold their margins (a lens that moves pixels farther than
// a render target is wide); a budget that only tiny tiles would meet is given up instead.
TilePlan planTiles(const Camera& camera, ImageSize size, const FramePlan& plan, const RenderTargetLimits& limits,
                   int forcedTileSidePx = 0, const TileMemory* memory = nullptr);

// The memory the renderer holds while it renders `tile` with `plan` (GL memory is process memory
// on llvmpipe), modelled per pixel: the accumulator's view layers (at most 8, at most 256 MiB,
// render/Accumulator.cpp) and their depth at the rendered size; the sums, the output target and its
// read-back at the tile's; with the lens gather the forward tables (2 × RGBA32F) at the rendered
// size and the inverse tables (RG32F per remapped channel) at the tile's. What it leaves out (the
// scene, the programs, a table band) does not grow with the tile.
std::int64_t tileMemoryBytes(const FramePlan& plan, const Tile& tile);

// For the commands that render the whole image into one target (sweep, view): refuses, in one
// line naming `command`, an image that only tiles could hold (render tiles; they do not).
void requireOneTarget(ImageSize size, const RenderTargetLimits& limits, const std::string& command);

// What the renderer needs for one tile: the camera and size it renders, the plan with the tile's
// overscan, and which pixels of the result are the tile's.
struct TileView {
  Camera camera;   // with the lens pass: the tile's sub-window; without: the rendered rect's
  ImageSize size;  // the size of the image the renderer returns
  FramePlan plan;  // the frame's plan (same samples and seed), overscan replaced by the tile's
  PixelRect crop;  // the tile's pixels within the returned image
};
TileView tileView(const Camera& camera, ImageSize size, const FramePlan& plan, const Tile& tile);

// Largest shift of the field-curvature warp, in pixels of a `size` image (0 without curvature):
// aperture radius · d · |κ| · r² at the farthest corner of what is rendered, over the pixel pitch.
double curvatureShiftPx(const Camera& camera, ImageSize size, const FramePlan& plan);

}  // namespace lenslab
