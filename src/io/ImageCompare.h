#pragma once
// Differences between two images of the same size, over the RGB channels.
#include "core/Image.h"

namespace lenslab {

struct ImageDifference {
  double maxAbs = 0.0;        // largest channel difference
  double rmse = 0.0;          // root mean square over all RGB values
  double psnrDb = 0.0;        // 10·log10(peak² / mse), peak = 1; +inf when identical
  double fractionOver = 0.0;  // fraction of pixels with any channel differing by more than threshold
};

// Throws std::invalid_argument when the sizes differ.
ImageDifference compareImages(const Image& a, const Image& b, double threshold);

// The image as an 8-bit display would show it: sRGB-encoded and quantised, in [0, 1].
Image displayEncoded(const Image& linear);

// |a − b| per channel, scaled by `gain`, alpha 1: for eyes, written beside failing tests.
Image differenceImage(const Image& a, const Image& b, float gain);

}  // namespace lenslab
