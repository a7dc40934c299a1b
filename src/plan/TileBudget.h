#pragma once
// Per-tile sample budgets: which tiles of the image still need views, and where to draw them.
//
// The image is cut into square tiles (32 px by default). Each tile keeps its own count of views
// and its own error estimate (render/Renderer's two-stream estimate): a tile in focus with no
// edge stops after a few views, a blurred one goes on. A tile's mean uses its own count, so the
// image stays unbiased however the counts differ.
//
// Which tiles go on: the frame's error is the pixel-weighted mean of the tiles' errors, and a
// tile's error falls as c/n with its view count n (c = its error × n, measured). Reaching the
// target with the fewest views is Lagrange's problem: n_t ∝ √c_t, i.e. every tile stops where one
// more view would lower the frame's error by less than λ per pixel. λ is solved for each round
// from the errors measured so far, so the rule sharpens as the estimates do.
#include "camera/ImageSize.h"

#include <vector>

namespace lenslab {

// A rectangle of pixels in GL's orientation: x to the right, y up from the bottom row.
struct PixelBox {
  int x = 0, y = 0, width = 0, height = 0;
  bool operator==(const PixelBox&) const = default;
};

struct TileGrid {
  ImageSize image;
  int tileSizePx = 32;
  int columns = 0, rows = 0;

  int count() const { return columns * rows; }
  PixelBox box(int tile) const;  // tile = row * columns + column, row 0 at the bottom; clipped to the image
  double pixels(int tile) const { const PixelBox b = box(tile); return static_cast<double>(b.width) * b.height; }
};

TileGrid makeTileGrid(ImageSize image, int tileSizePx);

// The selected tiles as few rectangles: runs along each row of tiles, merged with the same run in
// the rows above. Covers exactly the selected tiles.
std::vector<PixelBox> mergedBoxes(const TileGrid& grid, const std::vector<char>& selected);

struct TileState {
  int views = 0;         // views drawn into the tile (both streams)
  int minViews = 0;      // the plan's minimum (from the pre-pass's circle of confusion)
  double mse = 0.0;      // estimated squared error of its mean, per RGB value
};

// Which tiles draw more views, to bring the frame's pixel-weighted mean squared error to
// `targetMse` with the fewest views, none beyond `maxViews`. Tiles under their minimum always go
// on. Returns one flag per tile; all false when the target is met (or every tile is at the cap).
std::vector<char> tilesToContinue(const TileGrid& grid, const std::vector<TileState>& tiles, double targetMse, int maxViews);

// The frame's pixel-weighted mean squared error.
double frameMse(const TileGrid& grid, const std::vector<TileState>& tiles);

double psnrFromMse(double mse);  // peak 1, as io/ImageCompare; +inf for 0
double mseFromPsnr(double psnrDb);

}  // namespace lenslab
