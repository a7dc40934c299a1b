#pragma once
// A progressive sample order for the aperture and the pixel: Owen-scrambled Sobol' points in four
// dimensions, the lens from the first two and the sub-pixel offset from the next two.
//
// Every view integrates a pixel over four dimensions (lens 2-D × pixel 2-D), and a defocused
// pixel's value depends on them jointly (a point at circle of confusion c lands at pixel + c·lens),
// so one 4-D sequence is stratified where two separately stratified pairs are not: Sobol's first
// four dimensions (Joe and Kuo's direction numbers) are a (3, 4)-sequence — every 4-D box of
// volume 8/2^k, of any shape, holds exactly 8 of the first 2^k points; the pixel pair (dimensions
// 2 and 3) is a (2, 2)-sequence, and the lens pair (dimensions 0 and 1) a (0, 2)-sequence:
// every prefix of 2^k points puts exactly one point in each of the 2^k elementary boxes of any
// shape (2^a × 2^b). Stopping after any power of two costs no structure, and any prefix is
// low-discrepancy. Owen's nested uniform scrambling (hash-based, after Burley 2020, "Practical
// Hash-based Owen Scrambling"), one scramble per dimension, keeps all of that and makes each point
// uniform on its own, so a mean over the points is unbiased.
//
// One stream (sobolPoint) is what a frame of a fixed count uses: its N points are one net. An
// error estimate needs two interleaved streams, each scrambled independently: view i is point i/2
// of stream i mod 2 (sobolTwoStreamSample). The streams' means A and B are then independent
// estimates of the same converged image, and |A − B|²/4 is an unbiased estimate of the squared
// error of their mean (A + B)/2, whatever the stratification does to the rate. The price is that
// (A + B)/2 is two nets of N/2, not one of N (docs/sampling.md measures it).
//
// sobolSample is the two-stream order the per-tile budgets (render/AdaptiveRender, --target-psnr)
// draw today: in each stream the lens and the pixel are two separate (0, 2) pairs, paired by a
// scrambled index, so they are stratified in 2-D each but not jointly. Its estimate is what
// tests/render/estimate_test.cpp validates; sobolTwoStreamSample is the 4-D form for it to move to
// once that test holds with it (docs/sampling.md).
#include "lens/AperturePattern.h"

#include <cstdint>

namespace lenslab {

// Sobol's dimensions 0..3 of point `index`, in [0, 1), as 32-bit fractions.
std::uint32_t sobolDimension0(std::uint32_t index);  // van der Corput: the bits of index reversed
std::uint32_t sobolDimension1(std::uint32_t index);
std::uint32_t sobolDimension(int dimension, std::uint32_t index);  // dimension 0, 1, 2 or 3

// Owen's nested uniform scramble of a 32-bit fraction: flips each bit by a hash of the bits above it.
std::uint32_t owenScramble(std::uint32_t fraction, std::uint32_t seed);

// Point `index` of the one stream scrambled by `seed`: the aperture point (lens dimensions through
// the concentric disk map) and the sub-pixel offset. The first N of these are the pattern's N.
LensSample sobolPoint(std::uint32_t index, std::uint32_t seed);

// View `index` of the two-stream 4-D order: point index >> 1 of stream index & 1, the streams
// scrambled independently (seeds derived from `seed` and the stream).
LensSample sobolTwoStreamSample(std::uint32_t index, std::uint32_t seed);

// View `index` of the per-tile budgets' two-stream order (above): stream index & 1, point index >> 1
// of it; the lens from Sobol's dimensions 0 and 1 of the point, the pixel from the same two
// dimensions of a nested-scrambled index (pbrt's padding), so each 2^k prefix of a stream covers
// the lens's and the pixel's strata, each on its own.
LensSample sobolSample(std::uint32_t index, std::uint32_t seed);

int sobolStream(int viewIndex);  // 0 or 1

// The seed sobolTwoStreamSample scrambles stream 0 or 1 with: sobolTwoStreamSample(i, s) ==
// sobolPoint(i >> 1, sobolStreamSeed(s, i & 1)).
std::uint32_t sobolStreamSeed(std::uint32_t seed, int stream);

}  // namespace lenslab
