// The progressive order of lens/SobolSequence.h: every power-of-two prefix of each stream is one
// point per elementary box, on the lens square and the pixel; the streams are not the same points.
#include "lens/SobolSequence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

namespace lenslab {
namespace {

// Does each of the 2^k boxes 2^a × 2^(k−a) hold exactly one of the points?
bool oneInEachBox(const std::vector<glm::dvec2>& points, int k) {
  for (int a = 0; a <= k; ++a) {
    const int nx = 1 << a, ny = 1 << (k - a);
    std::set<int> seen;
    for (const glm::dvec2& p : points) {
      const int cell = static_cast<int>(std::floor(p.x * nx)) + nx * static_cast<int>(std::floor(p.y * ny));
      if (!seen.insert(cell).second) return false;
    }
  }
  return true;
}

// The disk map's inverse is not needed: the square points are recovered from the scrambled
// dimensions directly, and the pixel offsets are in the square already.
std::vector<glm::dvec2> pixelPrefix(std::uint32_t seed, int stream, int count) {
  std::vector<glm::dvec2> points;
  for (int i = 0; i < count; ++i) points.push_back(sobolSample(static_cast<std::uint32_t>(2 * i + stream), seed).pixel + 0.5);
  return points;
}

TEST(Sobol, UnscrambledPrefixesAreOnePointPerElementaryBox) {
  for (int k = 0; k <= 8; ++k) {
    std::vector<glm::dvec2> points;
    for (std::uint32_t i = 0; i < (1u << k); ++i) points.push_back(glm::dvec2(sobolDimension0(i), sobolDimension1(i)) * 0x1p-32);
    EXPECT_TRUE(oneInEachBox(points, k)) << "2^" << k << " points";
  }
}

TEST(Sobol, OwenScramblingKeepsTheBoxesAndMovesThePoints) {
  for (std::uint32_t seed : {1u, 7u, 12345u}) {
    std::vector<glm::dvec2> points;
    bool moved = false;
    for (std::uint32_t i = 0; i < 256; ++i) {
      const glm::dvec2 plain = glm::dvec2(sobolDimension0(i), sobolDimension1(i)) * 0x1p-32;
      const glm::dvec2 p = glm::dvec2(owenScramble(sobolDimension0(i), seed), owenScramble(sobolDimension1(i), seed + 1)) * 0x1p-32;
      moved |= p != plain;
      points.push_back(p);
      if (i + 1 == 16 || i + 1 == 64 || i + 1 == 256) {
        EXPECT_TRUE(oneInEachBox(points, static_cast<int>(std::log2(i + 1))));
      }
    }
    EXPECT_TRUE(moved);
  }
}

TEST(Sobol, EachStreamsPixelOffsetsStratifyEveryPowerOfTwoPrefix) {
  for (int stream : {0, 1})
    for (int k = 1; k <= 8; ++k) EXPECT_TRUE(oneInEachBox(pixelPrefix(3, stream, 1 << k), k)) << "stream " << stream << ", 2^" << k;
}

TEST(Sobol, LensPrefixesCoverTheDiskEvenlyInEachStream) {
  // Uniform disk: mean 0, E[r²] = 1/2. A scrambled (0, 2)-sequence prefix of 64 gets both closely.
  for (int stream : {0, 1}) {
    glm::dvec2 mean(0.0);
    double r2 = 0.0;
    for (int i = 0; i < 64; ++i) {
      const glm::dvec2 lens = sobolSample(static_cast<std::uint32_t>(2 * i + stream), 9).lens;
      mean += lens / 64.0;
      r2 += glm::dot(lens, lens) / 64.0;
    }
    EXPECT_LT(glm::length(mean), 0.03);
    EXPECT_NEAR(r2, 0.5, 0.02);
  }
}

TEST(Sobol, TheTwoStreamsAreDifferentPoints) {
  int same = 0;
  for (int i = 0; i < 64; ++i) same += sobolSample(static_cast<std::uint32_t>(2 * i), 5).lens == sobolSample(static_cast<std::uint32_t>(2 * i + 1), 5).lens;
  EXPECT_EQ(same, 0);
  EXPECT_EQ(sobolStream(6), 0);
  EXPECT_EQ(sobolStream(7), 1);
}

}  // namespace
}  // namespace lenslab
