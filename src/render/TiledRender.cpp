#include "render/TiledRender.h"

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
  limits.maxSidePx = std::min({glInteger(GL_MAX_TEXTURE_SIZE), glInteger(GL_MAX_RENDERBUFFER_SIZE), viewport[0], viewport[1],
                               glInteger(GL_MAX_FRAMEBUFFER_WIDTH), glInteger(GL_MAX_FRAMEBUFFER_HEIGHT)});
  return limits;
}

void renderTiles(Renderer& renderer, const Camera& camera, const FramePlan& plan, ImageSize size, const TilePlan& tiles,
                 const TileSink& sink, const TileProgress& progress) {
  const int total = static_cast<int>(tiles.tiles.size());
  for (int i = 0; i < total; ++i) {
    const Tile& tile = tiles.tiles[static_cast<std::size_t>(i)];
    const TileView view = tileView(camera, size, plan, tile);
    sink(tile.rect, cropped(renderer.render(view.camera, view.plan, view.size), view.crop));
    if (progress) progress(i + 1, total);
  }
}

Image renderTiled(Renderer& renderer, const Camera& camera, const FramePlan& plan, ImageSize size, const TilePlan& tiles) {
  Image image(size.widthPx, size.heightPx);
  renderTiles(renderer, camera, plan, size, tiles, [&](const PixelRect& rect, const Image& pixels) {
    for (int y = 0; y < rect.height(); ++y)
      std::memcpy(&image.rgba[image.offset(rect.x0, rect.y0 + y)], &pixels.rgba[pixels.offset(0, y)],
                  static_cast<std::size_t>(rect.width()) * 4 * sizeof(float));
  });
  return image;
}

}  // namespace lenslab
