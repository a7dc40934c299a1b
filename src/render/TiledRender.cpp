#include "render/TiledRender.h"

#include "core/Text.h"
#include "gl/Object.h"

#include <algorithm>
#include <cstring>

namespace lenslab {
namespace {

int glInteger(GLenum name) {
  GLint value = 0;
  glGetIntegerv(name, &value);
  return value;
}

Image cropped(Image image, const PixelRect& rect) {
  if (rect == PixelRect{0, 0, image.width, image.height}) return image;  // moved, not copied
  Image out(rect.width(), rect.height());
  const std::size_t row = static_cast<std::size_t>(rect.width()) * 4;
  for (int y = 0; y < rect.height(); ++y)
    std::memcpy(&out.rgba[out.offset(0, y)], &image.rgba[image.offset(rect.x0, rect.y0 + y)], row * sizeof(float));
  return out;
}

}  // namespace

RenderTargetLimits queryRenderTargetLimits() {
  GLint viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  RenderTargetLimits limits;
  limits.maxSidePx = std::min({glInteger(GL_MAX_TEXTURE_SIZE), glInteger(GL_MAX_RENDERBUFFER_SIZE), viewport[0],
                               viewport[1], glInteger(GL_MAX_FRAMEBUFFER_WIDTH), glInteger(GL_MAX_FRAMEBUFFER_HEIGHT)});
  return limits;
}

void renderTiles(Renderer& renderer, const Camera& camera, const FramePlan& plan, ImageSize size, const TilePlan& tiles,
                 const TileSink& sink, const TileProgress& progress) {
  const std::int64_t count = static_cast<std::int64_t>(tiles.tiles.size());
  const std::int64_t perTile = plan.adaptive ? 1 : std::max(plan.apertureSamples, 1);
  for (std::int64_t i = 0; i < count; ++i) {
    const Tile& tile = tiles.tiles[static_cast<std::size_t>(i)];
    const TileView view = tileView(camera, size, plan, tile);
    // Progress within a tile too (a large tile with many samples takes minutes on a CPU renderer):
    // its lens tables, then its samples batch by batch; a tile to a target error counts when done.
    LensPass::TableProgress tables;
    std::function<void()> afterBatch;
    if (progress && !plan.adaptive) {
      tables = [&](const char* table, int rowsDone, int rows) {
        progress(i * perTile, count * perTile,
                 cat("tile ", i + 1, " of ", count, ": ", table, " lens table, ", rowsDone, "/", rows, " rows"));
      };
      afterBatch = [&] { progress(i * perTile + renderer.samplesDone(), count * perTile, {}); };
    }
    renderer.begin(view.camera, view.plan, view.size, tables);
    renderer.complete(afterBatch);
    sink(tile.rect, cropped(renderer.resolve(), view.crop));
    if (progress && plan.adaptive) progress(i + 1, count, {});
  }
}

Image renderTiled(Renderer& renderer, const Camera& camera, const FramePlan& plan, ImageSize size,
                  const TilePlan& tiles) {
  Image image(size.widthPx, size.heightPx);
  renderTiles(renderer, camera, plan, size, tiles, [&](const PixelRect& rect, const Image& pixels) {
    for (int y = 0; y < rect.height(); ++y)
      std::memcpy(&image.rgba[image.offset(rect.x0, rect.y0 + y)], &pixels.rgba[pixels.offset(0, y)],
                  static_cast<std::size_t>(rect.width()) * 4 * sizeof(float));
  });
  return image;
}

}  // namespace lenslab
