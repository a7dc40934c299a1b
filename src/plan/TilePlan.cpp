#include "plan/TilePlan.h"

#include "camera/ImageMap.h"
#include "camera/LensMap.h"
#include "core/Error.h"
#include "core/Text.h"
#include "lens/LensEffects.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lenslab {
namespace {

bool fits(const PixelRect& r, const RenderTargetLimits& limits) {
  return r.width() <= limits.maxSidePx && r.height() <= limits.maxSidePx &&
         std::int64_t{r.width()} * r.height() <= limits.maxPixels;
}

bool fits(const FramePlan& plan, const Tile& tile, const RenderTargetLimits& limits, const TileMemory* memory) {
  return fits(tile.rendered, limits) && (!memory || tileMemoryBytes(plan, tile) <= memory->tileBytes);
}

std::int64_t area(const PixelRect& r) { return std::int64_t{r.width()} * r.height(); }

// What the full frame renders, in its pixels: the image, plus the lens pass's overscan or the cell
// filter's margin.
PixelRect fullRender(ImageSize size, const FramePlan& plan) {
  const glm::ivec2 pad = plan.remap || plan.cellFilter ? plan.overscan.padPx : glm::ivec2(0);
  return {-pad.x, -pad.y, size.widthPx + pad.x, size.heightPx + pad.y};
}

int ceilDiv(int a, int b) { return (a + b - 1) / b; }

// GL rasterizes in 2 x 2 quads from the framebuffer's bottom-left corner, and takes texture
// derivatives (so the mip level) as differences within a quad. A tile's render starting on an odd
// column or row of the full frame's render would pair pixels differently and pick slightly
// different mip levels: its render is grown by a pixel where needed so that its bottom-left corner
// sits on an even column and row of the frame's (GL rows count up from the frame's bottom edge).
PixelRect quadAligned(PixelRect r, const PixelRect& frame) {
  if ((r.x0 - frame.x0) % 2 != 0) --r.x0;
  if ((frame.y1 - r.y1) % 2 != 0) ++r.y1;
  return r;
}

// The pixels of the true perspective image that pixels `rect` of the distorted image show, for
// every remapped channel: the bounding box of the pre-image of the rect's border under the inverse
// lens model (validateLensEffects rules out folds, so the border's pre-image bounds the inside's),
// on the full image's pixel grid, plus the gather's footprint (ThinLensMap::overscanned's 2 pixels and 2 more,
// as the gather's reach grows where the lens magnifies), and the rect itself. Unlike overscanned()'s
// symmetric padding, a corner tile's margin lies on the side the lens pulls from.
PixelRect preImage(const ThinLensMap& map, const PixelRect& rect) {
  constexpr int kFootprintPx = 4;
  const std::vector<Channel> channels = remappedChannels(map.camera().lens.effects);
  glm::dvec2 lo(rect.x0, rect.y0), hi(rect.x1, rect.y1);
  const auto visit = [&](glm::dvec2 pixel) {
    for (const Channel c : channels) {
      const glm::dvec2 p = map.undistorted(c, pixel).pixel;
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  };
  for (int i = 0; i <= 2 * rect.width(); ++i) {
    visit({rect.x0 + 0.5 * i, rect.y0});
    visit({rect.x0 + 0.5 * i, rect.y1});
  }
  for (int j = 0; j <= 2 * rect.height(); ++j) {
    visit({rect.x0, rect.y0 + 0.5 * j});
    visit({rect.x1, rect.y0 + 0.5 * j});
  }
  return {static_cast<int>(std::floor(lo.x)) - kFootprintPx, static_cast<int>(std::floor(lo.y)) - kFootprintPx,
          static_cast<int>(std::ceil(hi.x)) + kFootprintPx, static_cast<int>(std::ceil(hi.y)) + kFootprintPx};
}

// Tiles of nearly equal size, at most `side` a side, with their margins; empty when one does not fit.
// With `memory`, also within its tile budget, and no taller than its strip allows.
std::vector<Tile> layout(const Camera& camera, ImageSize size, const FramePlan& plan, const RenderTargetLimits& limits,
                         const TileMemory* memory, int side, int& tileWidth, int& tileHeight) {
  const int columns = ceilDiv(size.widthPx, side);
  int rows = ceilDiv(size.heightPx, side);
  if (memory) {
    const std::int64_t stripRow = std::int64_t{size.widthPx} * std::max(memory->fileBytesPerPixel, 1);
    const int stripRows = static_cast<int>(std::max<std::int64_t>(memory->stripBytes / stripRow, 16));
    rows = std::max(rows, ceilDiv(size.heightPx, stripRows));
  }
  tileWidth = ceilDiv(size.widthPx, columns);
  tileHeight = ceilDiv(size.heightPx, rows);
  const PixelRect frame = fullRender(size, plan);
  const double shift = curvatureShiftPx(camera, size, plan);
  const int curvature = shift > 0.0 ? static_cast<int>(std::ceil(shift)) + 2 : 0;  // + the Catmull–Rom taps
  // The cell filter gathers images from as far as its margin: a tile renders that much around it.
  const glm::ivec2 margin = glm::ivec2(curvature) + (plan.cellFilter ? plan.overscan.padPx : glm::ivec2(0));
  const ThinLensMap map(camera, size);
  std::vector<Tile> tiles;
  for (int y0 = 0; y0 < size.heightPx; y0 += tileHeight)
    for (int x0 = 0; x0 < size.widthPx; x0 += tileWidth) {
      const PixelRect rect{x0, y0, std::min(x0 + tileWidth, size.widthPx), std::min(y0 + tileHeight, size.heightPx)};
      // With the lens pass: the tile's pre-image (where its pixels' samples come from), else the tile.
      const PixelRect source = plan.remap ? preImage(map, rect) : rect;
      const Tile tile{rect, quadAligned(intersect(grown(source, margin.x, margin.y), frame), frame)};
      if (!fits(plan, tile, limits, memory)) return {};
      tiles.push_back(tile);
    }
  return tiles;
}

}  // namespace

double curvatureShiftPx(const Camera& camera, ImageSize size, const FramePlan& plan) {
  if (!plan.fieldCurvature) return 0.0;
  const Camera& rendered = plan.remap ? plan.overscan.camera : camera;
  const double corner = normalisedWindow(rendered.view).cornerRadius();
  const Window& w = camera.view.window;
  const double pitch = std::min(w.width() / size.widthPx, w.height() / size.heightPx);
  // Renderer::addSamples: the shift at r = 1 is lensOffset·d·κ / pitch, |lensOffset| ≤ aperture radius.
  return camera.lens.apertureRadius * camera.view.prp.z *
         std::abs(camera.lens.effects.fieldCurvature.inverseFocusPerRadius2) * corner * corner / pitch;
}

void requireOneTarget(ImageSize size, const RenderTargetLimits& limits, const std::string& command) {
  if (size.widthPx <= limits.maxSidePx && size.heightPx <= limits.maxSidePx && size.pixelCount() <= limits.maxPixels)
    return;
  throw InputError(cat("--width/--height: ", command, " renders the whole ", size.widthPx, "x", size.heightPx,
                       " image into one render target, which holds at most ", limits.maxPixels, " pixels and ",
                       limits.maxSidePx, " a side; give a smaller size (render draws larger images in tiles)"));
}

std::int64_t tileMemoryBytes(const FramePlan& plan, const Tile& tile) {
  constexpr std::int64_t kRgba32f = 16, kDepth32f = 4, kRg32f = 8;
  constexpr std::int64_t kViewLayers = 8, kViewLayerBytes = std::int64_t{256} << 20;  // Accumulator.cpp's batch
  const std::int64_t rendered = area(tile.rendered);
  // The image the renderer returns: with the lens pass the tile itself, else its whole render.
  const std::int64_t out = plan.remap ? area(tile.rect) : rendered;
  const bool views = plan.apertureSamples > 1;
  const bool gather = plan.remap && views;
  std::int64_t bytes = 0;
  if (views) {
    bytes += std::min(kViewLayers * kRgba32f * rendered, kViewLayerBytes) + kDepth32f * rendered;
    bytes += kRgba32f * out * (gather ? 2 : 1);  // the sum (and the gather's weights)
  } else if (plan.remap) {
    bytes += (kRgba32f + kDepth32f) * rendered;  // the one view the lens pass remaps
  }
  if (gather) bytes += 2 * kRgba32f * rendered;  // forward position and Jacobian
  if (plan.remap) bytes += kRg32f * plan.remapTables * out;
  bytes += (kRgba32f + kDepth32f) * out + kRgba32f * out;  // the output target and its read-back
  // The image before the vignetting pass, where no resolve of many views multiplies the gain in.
  if (plan.vignetting && (!views || plan.adaptive)) bytes += (kRgba32f + kDepth32f) * out;
  if (!plan.remap && tile.rendered != tile.rect) bytes += kRgba32f * area(tile.rect);  // the crop
  return bytes;
}

TilePlan planTiles(const Camera& camera, ImageSize size, const FramePlan& plan, const RenderTargetLimits& limits,
                   int forcedTileSidePx, const TileMemory* memory) {
  TilePlan out;
  const PixelRect frame = fullRender(size, plan);
  const Tile whole{{0, 0, size.widthPx, size.heightPx}, frame};
  const std::int64_t wholeBytes = tileMemoryBytes(plan, whole);
  if (forcedTileSidePx <= 0 && fits(plan, whole, limits, memory)) {
    out.tileWidthPx = size.widthPx;
    out.tileHeightPx = size.heightPx;
    out.tiles = {Tile{{0, 0, size.widthPx, size.heightPx}, frame}};
    out.why = cat("one render target holds the whole ", frame.width(), "x", frame.height(), " render");
    return out;
  }
  out.tiled = true;
  const int budgetSide = static_cast<int>(std::sqrt(static_cast<double>(limits.maxPixels)));
  const int largestSide = forcedTileSidePx > 0 ? std::min({limits.maxSidePx, budgetSide, forcedTileSidePx})
                                               : std::min(limits.maxSidePx, budgetSide);
  int side = largestSide;
  const TileMemory* active = memory;
  constexpr int kSmallestTilePx = 16;
  for (;; side = side * 7 / 8) {  // steps of 1/8: tiles within a budget as large as it allows
    if (side < kSmallestTilePx && active) {
      // Only tiles too small to be worth their margins would meet the budget: the render-target
      // limits alone decide.
      side = largestSide;
      active = nullptr;
    }
    if (side < kSmallestTilePx)
      throw InputError(cat(camera.source, ": the lens moves pixels so far that even ", kSmallestTilePx,
                           "-pixel tiles need a "
                           "render larger than ",
                           limits.maxSidePx, " px a side or ", limits.maxPixels,
                           " pixels; render a smaller image or use weaker lens effects"));
    out.tiles = layout(camera, size, plan, limits, active, side, out.tileWidthPx, out.tileHeightPx);
    if (!out.tiles.empty()) break;
  }
  const std::string reason =
      forcedTileSidePx > 0 ? cat("--tile-size ", forcedTileSidePx)
      : fits(frame, limits)
          ? cat("the ", frame.width(), "x", frame.height(), " render needs about ", (wholeBytes + (1 << 19)) >> 20,
                " MiB, over the ", (memory ? memory->tileBytes : 0) >> 20, " MiB a tile may hold")
          : cat("the ", frame.width(), "x", frame.height(), " render exceeds one render target (", limits.maxSidePx,
                " px a side, ", limits.maxPixels, " pixels)");
  out.why = cat(out.tiles.size(), " tiles of up to ", out.tileWidthPx, "x", out.tileHeightPx, " (", reason,
                "), each a sub-window of the same view plane with the same PRP");
  return out;
}

TileView tileView(const Camera& camera, ImageSize size, const FramePlan& plan, const Tile& tile) {
  TileView v{camera, size, plan, {}};
  if (plan.remap) {
    // The lens pass writes the tile itself; its scene passes render the margins around it.
    v.camera = subWindowCamera(camera, size, tile.rect);
    v.size = tile.rect.size();
    v.plan.overscan = {subWindowCamera(camera, size, tile.rendered),
                       tile.rendered.size(),
                       {tile.rect.x0 - tile.rendered.x0, tile.rect.y0 - tile.rendered.y0}};
    v.crop = {0, 0, v.size.widthPx, v.size.heightPx};
  } else {
    // The margins (field curvature's warp, the cell filter's reach) are rendered and resolved with
    // the tile, then cut off.
    v.camera = subWindowCamera(camera, size, tile.rendered);
    v.size = tile.rendered.size();
    v.plan.overscan = {v.camera, v.size, {0, 0}};
    v.crop = {tile.rect.x0 - tile.rendered.x0, tile.rect.y0 - tile.rendered.y0, tile.rect.x1 - tile.rendered.x0,
              tile.rect.y1 - tile.rendered.y0};
  }
  return v;
}

}  // namespace lenslab
