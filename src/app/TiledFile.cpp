#include "app/TiledFile.h"

#include "core/Clock.h"
#include "core/Error.h"
#include "core/Text.h"
#include "io/ImageFile.h"
#include "io/StripImageWriter.h"
#include "render/TiledRender.h"

#include <chrono>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace lenslab {

TilePlan tilesForFile(const Camera& camera, ImageSize size, const FramePlan& plan, const std::filesystem::path& out,
                      int tileSizePx) {
  TileMemory memory;
  memory.fileBytesPerPixel = lowerExtension(out) == ".png" ? 3 : 16;  // StripImageWriter: 8-bit RGB, or float RGBA
  return planTiles(camera, size, plan, queryRenderTargetLimits(), tileSizePx, &memory);
}

void renderTiledToFile(Renderer& renderer, const Camera& camera, const FramePlan& plan, ImageSize size,
                       const TilePlan& tiles, OutputSet& outputs, const std::filesystem::path& out,
                       const DisplaySettings& settings, RunStats& stats, ProgressReporter& progress) {
  if (settings.exposure.source == "--exposure auto")
    throw InputError(cat("--exposure auto: ", tiles.why,
                         "; each is written as it is rendered, so no whole frame is there to meter: give --exposure "
                         "EV, or a smaller --width (and no --tile-size)"));
  const DisplayEncoding& display = settings.encoding;
#ifdef __GLIBC__
  // The tiles' buffers (tables, targets, read-backs) are 5 to 30 MB each and differ a little in
  // size from tile to tile; glibc's dynamic mmap threshold would put them on the heap after the
  // first is freed, where they fragment and the resident size grows tile by tile (8000 px,
  // camera-lens.json: 670 MB after one tile, 1080 MB after 16). Kept at 1 MiB, each is mapped
  // and given back whole.
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
  stats.plan.passes.push_back({"tiles", tiles.why, {}});
  progress.setUnit(cat("samples over ", tiles.tiles.size(), " tiles"));
  const auto t = std::chrono::steady_clock::now();
  double writeSeconds = 0.0;
  StripImageWriter writer(outputs, out, size);
  const std::string writing = cat("writing ", out.string());
  // None for a silent reporter (--quiet): the lens tables are then built in one parallel pass.
  TileProgress tileProgress;
  if (progress.style() != ProgressReporter::Style::Silent)
    tileProgress = [&](std::int64_t done, std::int64_t total, const std::string& note) {
      progress.update(done, total, note);
    };
  renderTiles(
      renderer, camera, plan, size, tiles,
      [&](const PixelRect& rect, const Image& pixels) {
        // Said at every tile: the writer takes it, and one that completes a strip of rows
        // has it written now (seconds for a large PNG).
        progress.setDetail(writing);
        const auto w = std::chrono::steady_clock::now();
        if (display.isIdentity()) {
          writer.add(rect.x0, rect.y0, pixels);
        } else {
          Image shown = pixels;
          applyDisplayForFile(out, shown, display);
          writer.add(rect.x0, rect.y0, shown);
        }
        writeSeconds += secondsSince(w);
      },
      tileProgress);
  const auto w = std::chrono::steady_clock::now();
  writer.finish();
  stats.writeSeconds = writeSeconds + secondsSince(w);
  stats.renderSeconds = secondsSince(t) - stats.writeSeconds;
}

}  // namespace lenslab
