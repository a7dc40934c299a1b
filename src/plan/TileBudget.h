#pragma once
// Per-tile sample budgets: which tiles of the image still need samples, and where to draw them.
//
// The image is cut into square tiles (32 px by default). Each tile keeps its own count of samples
// and its own error estimate (render/Renderer's two-stream estimate): a tile in focus with no
// edge stops after a few samples, a blurred one goes on. A tile's mean uses its own count, so the
// image stays unbiased however the counts differ.
//
// Which tiles go on: the frame's error is the pixel-weighted mean of the tiles' errors, and a
// tile's error falls as c/n with its view count n (c = its error × n, measured). Reaching the
// target with the fewest samples is Lagrange's problem: n_t ∝ √c_t, i.e. every tile stops where one
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
  double pixels(int tile) const {
    const PixelBox b = box(tile);
    return static_cast<double>(b.width) * b.height;
  }
};

TileGrid makeTileGrid(ImageSize image, int tileSizePx);

// The selected tiles as few rectangles: runs along each row of tiles, merged with the same run in
// the rows above. Covers exactly the selected tiles.
std::vector<PixelBox> mergedBoxes(const TileGrid& grid, const std::vector<char>& selected);

// Fewer, larger rectangles covering `boxes`, for passes where each rectangle has a cost of its own
// (a scissored draw of the whole scene): two are merged into their bounding box while that adds
// fewer than `pixelsPerBox` pixels — the cost of one more pass, in pixels drawn.
std::vector<PixelBox> coveringBoxes(const std::vector<PixelBox>& boxes, double pixelsPerBox);

struct TileState {
  int samples = 0;     // samples drawn into the tile (both streams)
  int minSamples = 0;  // the plan's minimum (from the pre-pass's circle of confusion)
  double mse = 0.0;    // estimated squared error of its mean, per RGB value
};

// Which tiles draw more samples, to bring the frame's pixel-weighted mean squared error to
// `targetMse` with the fewest samples, none beyond `maxSamples`. Tiles under their minimum always go
// on. Returns, per tile, how many more samples the allocation expects it to need (0: it stops);
// all 0 when the target is met (or every tile is at the cap).
std::vector<int> tilesToContinue(const TileGrid& grid, const std::vector<TileState>& tiles, double targetMse,
                                 int maxSamples);

// Whether drawing the rest of the frame tile by tile is predicted to cost less than drawing whole
// views until the frame meets the target. Both predictions use the same c/n model as
// tilesToContinue: per tile, the pixels it still draws (Σ pixels · more samples, times
// `tileCostFactor`, what a pixel drawn in scissored tiles costs against one drawn in a whole
// view); whole views, the frame's pixels times the count n at which the frame's error
// Σ pixels·c_t / (pixels · n) meets the target, from the most any tile has now. When the tiles'
// errors are alike (a scene in focus, or blurred alike everywhere) the two allocations are nearly
// the same and the per-tile cost factor decides: whole views.
bool perTilePays(const TileGrid& grid, const std::vector<TileState>& tiles, double targetMse, int maxSamples,
                 double tileCostFactor);

// Whole views: how many more samples every tile needs for the frame to meet the target (0 when
// it does), counted from the most any tile has now, and capped at `maxSamples`.
int wholeFrameMoreSamples(const TileGrid& grid, const std::vector<TileState>& tiles, double targetMse, int maxSamples);

// Each tile's error estimate pooled with its neighbours' (the tiles within `radius` in the grid):
// the error × samples of each (its c, which the count does not change), pixel-weighted, over the
// tile's own count. One tile's two-stream estimate is a noisy draw; a tile whose draw came out low
// would stop early and keep it, and the frame's estimate would lean optimistic by the tiles it
// stopped. The neighbourhood's c is the same blur and texture, seen by several independent draws.
std::vector<double> pooledMse(const TileGrid& grid, const std::vector<int>& samples, const std::vector<double>& mse,
                              int radius);

// The frame's pixel-weighted mean squared error.
double frameMse(const TileGrid& grid, const std::vector<TileState>& tiles);

// What a per-tile frame reached: the estimate and the samples the tiles took.
struct FrameEstimate {
  double mse = 0.0, rmse = 0.0, psnrDb = 0.0;  // per RGB value, against the image's own converged limit (peak 1)
  int minSamples = 0, maxSamples = 0;          // over tiles
  double meanSamples = 0.0;                    // pixel-weighted: samples per pixel
  int tiles = 0, tilesActive = 0, rounds = 0;
  bool wholeFrame = false;  // after the first round, every tile went on together (Renderer::step)
  bool targetMet = false;
};
FrameEstimate estimateFrame(const TileGrid& grid, const std::vector<TileState>& tiles, double targetPsnrDb);

double psnrFromMse(double mse);  // peak 1, as io/ImageCompare; +inf for 0
double mseFromPsnr(double psnrDb);

}  // namespace lenslab
