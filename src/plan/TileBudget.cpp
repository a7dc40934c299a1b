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
  struct Run {
    int first, last;
    PixelBox box;
  };
  std::vector<PixelBox> done;
  std::vector<Run> open;  // runs of the previous tile row, still growing upward
  for (int row = 0; row < grid.rows; ++row) {
    std::vector<Run> current;
    for (int column = 0; column < grid.columns;) {
      if (!selected[static_cast<std::size_t>(row * grid.columns + column)]) {
        ++column;
        continue;
      }
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

std::vector<PixelBox> coveringBoxes(const std::vector<PixelBox>& boxes, double pixelsPerBox) {
  std::vector<PixelBox> out = boxes;
  const auto area = [](const PixelBox& b) { return static_cast<double>(b.width) * b.height; };
  const auto bound = [](const PixelBox& a, const PixelBox& b) {
    const int x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
    const int x1 = std::max(a.x + a.width, b.x + b.width), y1 = std::max(a.y + a.height, b.y + b.height);
    return PixelBox{x0, y0, x1 - x0, y1 - y0};
  };
  while (out.size() > 1) {
    double cheapest = std::numeric_limits<double>::infinity();
    std::size_t bi = 0, bj = 0;
    for (std::size_t i = 0; i < out.size(); ++i)
      for (std::size_t j = i + 1; j < out.size(); ++j) {
        const double added = area(bound(out[i], out[j])) - area(out[i]) - area(out[j]);
        if (added < cheapest) {
          cheapest = added;
          bi = i;
          bj = j;
        }
      }
    if (cheapest >= pixelsPerBox) break;
    out[bi] = bound(out[bi], out[bj]);
    out.erase(out.begin() + static_cast<std::ptrdiff_t>(bj));
  }
  return out;
}

std::vector<double> pooledMse(const TileGrid& grid, const std::vector<int>& samples, const std::vector<double>& mse,
                              int radius) {
  std::vector<double> out(mse.size(), 0.0);
  for (int t = 0; t < grid.count(); ++t) {
    const int column = t % grid.columns, row = t / grid.columns;
    double c = 0.0, pixels = 0.0;
    for (int r = std::max(row - radius, 0); r <= std::min(row + radius, grid.rows - 1); ++r)
      for (int k = std::max(column - radius, 0); k <= std::min(column + radius, grid.columns - 1); ++k) {
        const std::size_t s = static_cast<std::size_t>(r * grid.columns + k);
        c += grid.pixels(static_cast<int>(s)) * mse[s] * samples[s];
        pixels += grid.pixels(static_cast<int>(s));
      }
    const std::size_t i = static_cast<std::size_t>(t);
    out[i] = samples[i] > 0 && pixels > 0.0 ? c / pixels / samples[i] : mse[i];
  }
  return out;
}

double frameMse(const TileGrid& grid, const std::vector<TileState>& tiles) {
  double sum = 0.0, pixels = 0.0;
  for (int t = 0; t < grid.count(); ++t) {
    sum += grid.pixels(t) * tiles[static_cast<std::size_t>(t)].mse;
    pixels += grid.pixels(t);
  }
  return pixels > 0.0 ? sum / pixels : 0.0;
}

std::vector<int> tilesToContinue(const TileGrid& grid, const std::vector<TileState>& tiles, double targetMse,
                                 int maxSamples) {
  const std::size_t n = static_cast<std::size_t>(grid.count());
  std::vector<int> go(n, 0);
  bool belowMinimum = false;
  for (std::size_t t = 0; t < n; ++t)
    if (tiles[t].samples < std::min(tiles[t].minSamples, maxSamples)) {
      go[t] = std::min(tiles[t].minSamples, maxSamples) - tiles[t].samples;
      belowMinimum = true;
    }
  if (belowMinimum) return go;  // every tile reaches its minimum before any estimate is trusted
  if (frameMse(grid, tiles) <= targetMse) return go;

  // c_t = mse_t · n_t; with λ, tile t ends at n_t(λ) = clamp(√(c_t / λ), n_t, max) samples and error
  // c_t / n_t(λ). The frame's final error falls as λ falls: bisect λ (in log) for the target.
  double pixels = 0.0;
  for (std::size_t t = 0; t < n; ++t) pixels += grid.pixels(static_cast<int>(t));
  const auto finalSamples = [&](std::size_t t, double lambda) {
    const double c = tiles[t].mse * tiles[t].samples;
    const double wanted = lambda > 0.0 ? std::sqrt(c / lambda) : std::numeric_limits<double>::infinity();
    return std::clamp(wanted, static_cast<double>(tiles[t].samples),
                      static_cast<double>(std::max(maxSamples, tiles[t].samples)));
  };
  const auto finalMse = [&](double lambda) {
    double sum = 0.0;
    for (std::size_t t = 0; t < n; ++t) {
      const double samples = finalSamples(t, lambda);
      sum +=
          grid.pixels(static_cast<int>(t)) * (samples > 0.0 ? tiles[t].mse * tiles[t].samples / samples : tiles[t].mse);
    }
    return sum / pixels;
  };
  double lo = 1e-30, hi = 1.0;  // λ: error per pixel per view; finalMse(hi) is the error now
  if (finalMse(lo) > targetMse) {
    // The cap stops it short of the target: every tile not at the cap goes on, but for those
    // whose error is nothing (a flat sky): they are done at any count.
    lo = 1e-300;
  } else {
    for (int i = 0; i < 100; ++i) {
      const double mid = std::sqrt(lo * hi);
      (finalMse(mid) > targetMse ? hi : lo) = mid;
    }
  }
  for (std::size_t t = 0; t < n; ++t) {
    const double more = finalSamples(t, lo) - tiles[t].samples;
    go[t] = tiles[t].samples < maxSamples && more > 0.5 ? static_cast<int>(std::ceil(more)) : 0;
  }
  return go;
}

int wholeFrameMoreSamples(const TileGrid& grid, const std::vector<TileState>& tiles, double targetMse, int maxSamples) {
  const double mse = frameMse(grid, tiles);
  int most = 0;
  for (const TileState& tile : tiles) most = std::max(most, tile.samples);
  if (mse <= targetMse || most >= maxSamples || tiles.empty()) return 0;
  // Frame error after n samples everywhere: Σ pixels · c_t / (pixels · n), c_t = mse_t · n_t.
  double sum = 0.0, pixels = 0.0;
  for (int t = 0; t < grid.count(); ++t) {
    const TileState& tile = tiles[static_cast<std::size_t>(t)];
    sum += grid.pixels(t) * tile.mse * tile.samples;
    pixels += grid.pixels(t);
  }
  const double wanted = sum / (pixels * targetMse);
  const double capped = std::min(wanted, static_cast<double>(maxSamples));
  return std::max(0, static_cast<int>(std::ceil(capped)) - most);
}

bool perTilePays(const TileGrid& grid, const std::vector<TileState>& tiles, double targetMse, int maxSamples,
                 double tileCostFactor) {
  const std::vector<int> more = tilesToContinue(grid, tiles, targetMse, maxSamples);
  double tilePixels = 0.0, framePixels = 0.0;
  for (int t = 0; t < grid.count(); ++t) {
    tilePixels += grid.pixels(t) * more[static_cast<std::size_t>(t)];
    framePixels += grid.pixels(t);
  }
  const double wholePixels = framePixels * wholeFrameMoreSamples(grid, tiles, targetMse, maxSamples);
  return tileCostFactor * tilePixels < wholePixels;
}

FrameEstimate estimateFrame(const TileGrid& grid, const std::vector<TileState>& tiles, double targetPsnrDb) {
  FrameEstimate e;
  if (tiles.empty()) return e;
  e.mse = frameMse(grid, tiles);
  e.rmse = std::sqrt(e.mse);
  e.psnrDb = psnrFromMse(e.mse);
  e.tiles = grid.count();
  e.minSamples = tiles.front().samples;
  double weighted = 0.0, pixels = 0.0;
  for (int t = 0; t < grid.count(); ++t) {
    const TileState& tile = tiles[static_cast<std::size_t>(t)];
    e.minSamples = std::min(e.minSamples, tile.samples);
    e.maxSamples = std::max(e.maxSamples, tile.samples);
    weighted += grid.pixels(t) * tile.samples;
    pixels += grid.pixels(t);
  }
  e.meanSamples = pixels > 0.0 ? weighted / pixels : 0.0;
  e.targetMet = e.psnrDb >= targetPsnrDb;
  return e;
}

double psnrFromMse(double mse) { return mse > 0.0 ? -10.0 * std::log10(mse) : std::numeric_limits<double>::infinity(); }
double mseFromPsnr(double psnrDb) { return std::pow(10.0, -psnrDb / 10.0); }

}  // namespace lenslab
