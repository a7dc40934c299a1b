#pragma once
// A progressive sample order for the aperture and the pixel: Owen-scrambled Sobol' points.
//
// The first two dimensions of Sobol's sequence form a (0, 2)-sequence: every prefix of 2^k points
// puts exactly one point in each of the 2^k elementary boxes of any shape (2^a × 2^b strata), so
// stopping after any power of two costs no structure, and any prefix is low-discrepancy. Owen's
// nested uniform scrambling (hash-based, after Burley 2020, "Practical Hash-based Owen Scrambling")
// keeps that and makes each point uniform on its own, so a mean over the points is unbiased.
//
// Views come in two interleaved streams, each scrambled independently: view i is point i/2 of
// stream i mod 2. The streams' means A and B are then independent estimates of the same converged
// image, and |A − B|²/4 is an unbiased estimate of the squared error of their mean (A + B)/2,
// whatever the stratification does to the rate: the error estimate of render/AdaptiveRender.
#include "lens/AperturePattern.h"

#include <cstdint>

namespace lenslab {

// Sobol's first two dimensions of point `index`, in [0, 1)², as 32-bit fractions.
std::uint32_t sobolDimension0(std::uint32_t index);  // van der Corput: the bits of index reversed
std::uint32_t sobolDimension1(std::uint32_t index);

// Owen's nested uniform scramble of a 32-bit fraction: flips each bit by a hash of the bits above it.
std::uint32_t owenScramble(std::uint32_t fraction, std::uint32_t seed);

// Aperture point (through the concentric disk map) and sub-pixel offset of view `index`: stream
// index & 1, point index >> 1 of that stream. The pixel offset uses the stream's points in a
// scrambled order (pbrt's padding), so lens and pixel are not paired by index yet each prefix of
// 2^k points still covers the pixel's strata.
LensSample sobolSample(std::uint32_t index, std::uint32_t seed);

int sobolStream(int viewIndex);  // 0 or 1

}  // namespace lenslab
