#include "plan/TileBudget.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lenslab {

PixelBox TileGrid::box(int tile) const {
  const int column = tile % columns, row = tile / columns;
  const int x = column * tileSizePx, y = row * tileSizePx;
  return {x, y, std::min(tileSizePx, image.widthPx - x), std::min(tileSizePx, image.heightPx - y)};
}

TileGrid makeTileGrid(ImageSize image, int tileSizePx) {
  TileGrid g;
  g.image = image;
  g.tileSizePx = std::max(tileSizePx, 1);
  g.columns = (image.widthPx + g.tileSizePx - 1) / g.tileSizePx;
  g.rows = (image.heightPx + g.tileSizePx - 1) / g.tileSizePx;
  return g;
}

std::vector<PixelBox> mergedBoxes(const TileGrid& grid, const std::vector<char>& selected) {
  struct Run { int first, last; PixelBox box; };
  std::vector<PixelBox> done;
  std::vector<Run> open;  // runs of the previous tile row, still growing upward
  for (int row = 0; row < grid.rows; ++row) {
    std::vector<Run> current;
    for (int column = 0; column < grid.columns;) {
      if (!selected[static_cast<std::size_t>(row * grid.columns + column)]) { ++column; continue; }
      int last = column;
      while (last + 1 < grid.columns && selected[static_cast<std::size_t>(row * grid.columns + last + 1)]) ++last;
      const PixelBox first = grid.box(row * grid.columns + column), end = grid.box(row * grid.columns + last);
      current.push_back({column, last, {first.x, first.y, end.x + end.width - first.x, first.height}});
      column = last + 1;
    }
    // A run with the same columns as one below extends it.
    for (Run& run : current)
      for (auto it = open.begin(); it != open.end(); ++it)
        if (it->first == run.first && it->last == run.last) {
          run.box.y = it->box.y;
          run.box.height += it->box.height;
          open.erase(it);
          break;
        }
    for (const Run& ended : open) done.push_back(ended.box);
    open = std::move(current);
  }
  for (const Run& ended : open) done.push_back(ended.box);
  return done;
}

double frameMse(const TileGrid& grid, const std::vector<TileState>& tiles) {
  double sum = 0.0, pixels = 0.0;
  for (int t = 0; t < grid.count(); ++t) {
    sum += grid.pixels(t) * tiles[static_cast<std::size_t>(t)].mse;
    pixels += grid.pixels(t);
  }
  return pixels > 0.0 ? sum / pixels : 0.0;
}

std::vector<char> tilesToContinue(const TileGrid& grid, const std::vector<TileState>& tiles, double targetMse, int maxViews) {
  const std::size_t n = static_cast<std::size_t>(grid.count());
  std::vector<char> go(n, 0);
  bool belowMinimum = false;
  for (std::size_t t = 0; t < n; ++t)
    if (tiles[t].views < std::min(tiles[t].minViews, maxViews)) go[t] = belowMinimum = 1;
  if (belowMinimum) return go;  // every tile reaches its minimum before any estimate is trusted
  if (frameMse(grid, tiles) <= targetMse) return go;

  // c_t = mse_t · n_t; with λ, tile t ends at n_t(λ) = clamp(√(c_t / λ), n_t, max) views and error
  // c_t / n_t(λ). The frame's final error falls as λ falls: bisect λ (in log) for the target.
  double pixels = 0.0;
  for (std::size_t t = 0; t < n; ++t) pixels += grid.pixels(static_cast<int>(t));
  const auto finalViews = [&](std::size_t t, double lambda) {
    const double c = tiles[t].mse * tiles[t].views;
    const double wanted = lambda > 0.0 ? std::sqrt(c / lambda) : std::numeric_limits<double>::infinity();
    return std::clamp(wanted, static_cast<double>(tiles[t].views), static_cast<double>(std::max(maxViews, tiles[t].views)));
  };
  const auto finalMse = [&](double lambda) {
    double sum = 0.0;
    for (std::size_t t = 0; t < n; ++t) {
      const double views = finalViews(t, lambda);
      sum += grid.pixels(static_cast<int>(t)) * (views > 0.0 ? tiles[t].mse * tiles[t].views / views : tiles[t].mse);
    }
    return sum / pixels;
  };
  double lo = 1e-30, hi = 1.0;  // λ: error per pixel per view; finalMse(hi) is the error now
  if (finalMse(lo) > targetMse) {
    lo = 0.0;  // the cap stops it short of the target: every tile not at the cap goes on
  } else {
    for (int i = 0; i < 100; ++i) {
      const double mid = std::sqrt(lo * hi);
      (finalMse(mid) > targetMse ? hi : lo) = mid;
    }
  }
  for (std::size_t t = 0; t < n; ++t) go[t] = tiles[t].views < maxViews && finalViews(t, lo) > tiles[t].views + 0.5;
  return go;
}

double psnrFromMse(double mse) { return mse > 0.0 ? -10.0 * std::log10(mse) : std::numeric_limits<double>::infinity(); }
double mseFromPsnr(double psnrDb) { return std::pow(10.0, -psnrDb / 10.0); }

}  // namespace lenslab
