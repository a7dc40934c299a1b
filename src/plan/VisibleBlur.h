#pragma once
// The blur a frame will actually show, from a pinhole depth pre-pass, for planning samples.
//
// The scene's bounds say how blurred the scene *could* be (the floor's box runs under the camera);
// the pinhole depth of each pixel says how blurred what is seen *is*: each pixel's circle of
// confusion (Camera.h cocDiameterOnWindow) in image pixels. Blur also reaches a pixel from nearer
// surfaces whose larger circles spread over it (the lecture's partial obscuration: an out-of-focus
// foreground shows as a translucent fringe over what lies behind it), so each pixel's circle is
// dilated by every nearer circle that covers it. A farther circle does not reach over a nearer
// surface: the nearer surface hides it. The dilation is conservative (square neighbourhoods, and
// circles grouped in powers of two), which only ever asks for more samples.
#include "camera/Camera.h"
#include "camera/ImageSize.h"

#include <array>
#include <vector>

namespace lenslab {

struct VisibleBlur {
  ImageSize prepass;  // the depth map's size
  double imagePxPerPrepassPx = 1.0;
  std::vector<float> ownPx;       // each pre-pass pixel's own circle of confusion, image pixels (0: background)
  std::vector<float> reachingPx;  // the largest circle reaching it (own, or a nearer one's)

  // The distribution of reachingPx over the image: fractions of pixels with a circle ≤ 1 px,
  // 1–4, 4–16, 16–64 and > 64 px; and its percentiles.
  static constexpr std::array<double, 4> kBinEdgesPx = {1.0, 4.0, 16.0, 64.0};
  std::array<double, 5> fractions{};
  double p50Px = 0.0, p90Px = 0.0, p99Px = 0.0, maxPx = 0.0;
  double ownMinPx = 0.0;  // the smallest own circle over surfaces seen (0 if one is in focus)

  // The largest reaching circle over image pixels [x0, x1) × [y0, y1) (rows from the top).
  double maxOver(int x0, int y0, int x1, int y1) const;
};

// A pre-pass size for an image: about `targetWidthPx` wide, an integer fraction of the image.
ImageSize prepassSizeFor(ImageSize image, int targetWidthPx = 320);

// `depth`: the pinhole view's depth per pre-pass pixel (world units from the PRP along −n, rows
// from the top; +infinity where nothing is seen). The camera's axial colour and field curvature
// count as in the frame plan: the largest circle over the channels' and the corners' focus.
// `backgroundAtInfinity`: where nothing is seen an environment is (render/GpuEnvironment), whose
// circle is that of depth infinity (perspective cameras; else the background has no circle).
VisibleBlur visibleBlur(const Camera& camera, ImageSize image, ImageSize prepass, const std::vector<double>& depth,
                        bool backgroundAtInfinity = false);

}  // namespace lenslab
