// The progressive order of lens/SobolSequence.h: every power-of-two prefix is a net on the lens
// square, on the pixel and in all four dimensions together; the two streams are independent
// scrambles; and a smooth defocused integrand converges faster than with independent samples.
// The per-tile budgets' padded order (sobolSample) keeps its own 2-D strata and independent streams.
#include "lens/SobolSequence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <vector>

namespace lenslab {
namespace {

constexpr double kQuarterPi = std::numbers::pi / 4.0;

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

// The t of a (t, k, D)-net: the smallest t for which every elementary box of volume 2^(t−k)
// (2^a × 2^b × … boxes, a + b + … = k − t) holds exactly 2^t of the 2^k points.
template <int D>
bool boxesHold(const std::vector<glm::vec<D, double>>& points, int bitsLeft, int dim, int (&bits)[D], int each) {
  if (dim == D - 1) {
    bits[dim] = bitsLeft;
    std::map<std::uint64_t, int> count;
    for (const auto& p : points) {
      std::uint64_t key = 0;
      for (int j = 0; j < D; ++j) key = (key << 16) | static_cast<std::uint64_t>(std::floor(p[j] * (1 << bits[j])));
      ++count[key];
    }
    for (const auto& [key, n] : count)
      if (n != each) return false;
    return true;
  }
  for (int b = 0; b <= bitsLeft; ++b) {
    bits[dim] = b;
    if (!boxesHold<D>(points, bitsLeft - b, dim + 1, bits, each)) return false;
  }
  return true;
}

template <int D>
int netQuality(const std::vector<glm::vec<D, double>>& points, int k) {
  int bits[D] = {};
  for (int t = 0; t < k; ++t)
    if (boxesHold<D>(points, k - t, 0, bits, 1 << t)) return t;
  return k;
}

// The inverse of concentricDisk: the square point a lens sample came from.
glm::dvec2 squareFromDisk(glm::dvec2 p) {
  const double r = glm::length(p);
  if (r == 0.0) return {0.5, 0.5};
  double phi = std::atan2(p.y, p.x);
  if (phi < -kQuarterPi) phi += 2.0 * std::numbers::pi;  // [−π/4, 7π/4)
  glm::dvec2 offset;
  if (phi < kQuarterPi)
    offset = {r, r * phi / kQuarterPi};
  else if (phi < 3.0 * kQuarterPi)
    offset = {r * (2.0 * kQuarterPi - phi) / kQuarterPi, r};
  else if (phi < 5.0 * kQuarterPi)
    offset = {-r, -r * (phi - 4.0 * kQuarterPi) / kQuarterPi};
  else
    offset = {-r * (6.0 * kQuarterPi - phi) / kQuarterPi, -r};
  return (offset + 1.0) / 2.0;
}

glm::dvec4 squareOf(const LensSample& s) { return glm::dvec4(squareFromDisk(s.lens), s.pixel + 0.5); }

// The first `count` points of the single stream (stream < 0) or of one of the two 4-D streams.
std::vector<glm::dvec4> prefix(std::uint32_t seed, int stream, int count) {
  std::vector<glm::dvec4> points;
  for (int i = 0; i < count; ++i) {
    const auto index = static_cast<std::uint32_t>(i);
    points.push_back(squareOf(stream < 0 ? sobolPoint(index, seed)
                                         : sobolTwoStreamSample(2 * index + static_cast<std::uint32_t>(stream), seed)));
  }
  return points;
}

std::vector<glm::dvec2> pair(const std::vector<glm::dvec4>& points, int first) {
  std::vector<glm::dvec2> out;
  for (const glm::dvec4& p : points) out.emplace_back(p[first], p[first + 1]);
  return out;
}

TEST(Sobol, TheDiskMapsInverseRoundTrips) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 1000; ++i) {
    const glm::dvec2 square(u(rng), u(rng));
    EXPECT_NEAR(glm::length(squareFromDisk(concentricDisk(square)) - square), 0.0, 1e-9);
  }
}

TEST(Sobol, UnscrambledPrefixesAreOnePointPerElementaryBox) {
  for (int k = 0; k <= 8; ++k) {
    std::vector<glm::dvec2> points;
    for (std::uint32_t i = 0; i < (1u << k); ++i)
      points.push_back(glm::dvec2(sobolDimension0(i), sobolDimension1(i)) * 0x1p-32);
    EXPECT_TRUE(oneInEachBox(points, k)) << "2^" << k << " points";
  }
}

TEST(Sobol, DimensionsTwoAndThreeAreJoeKuos) {
  // The direction numbers (the points at index 2^k) of new-joe-kuo-6.21201's third and fourth
  // dimensions, as pbrt's and every other Sobol' table gives them.
  const std::uint32_t third[8] = {0x80000000u, 0xc0000000u, 0x60000000u, 0x90000000u,
                                  0xe8000000u, 0x5c000000u, 0x8e000000u, 0xc5000000u};
  const std::uint32_t fourth[8] = {0x80000000u, 0xc0000000u, 0x20000000u, 0x50000000u,
                                   0xf8000000u, 0x74000000u, 0xa2000000u, 0x93000000u};
  for (int k = 0; k < 8; ++k) {
    EXPECT_EQ(sobolDimension(2, 1u << k), third[k]) << k;
    EXPECT_EQ(sobolDimension(3, 1u << k), fourth[k]) << k;
  }
  EXPECT_EQ(sobolDimension(2, 3), third[0] ^ third[1]);  // a digital sequence: XOR of the set bits'
  EXPECT_EQ(sobolDimension(0, 6), sobolDimension0(6));
  EXPECT_EQ(sobolDimension(1, 6), sobolDimension1(6));
}

TEST(Sobol, OwenScramblingKeepsTheBoxesAndMovesThePoints) {
  for (std::uint32_t seed : {1u, 7u, 12345u}) {
    std::vector<glm::dvec2> points;
    bool moved = false;
    for (std::uint32_t i = 0; i < 256; ++i) {
      const glm::dvec2 plain = glm::dvec2(sobolDimension0(i), sobolDimension1(i)) * 0x1p-32;
      const glm::dvec2 p =
          glm::dvec2(owenScramble(sobolDimension0(i), seed), owenScramble(sobolDimension1(i), seed + 1)) * 0x1p-32;
      moved |= p != plain;
      points.push_back(p);
      if (i + 1 == 16 || i + 1 == 64 || i + 1 == 256) {
        EXPECT_TRUE(oneInEachBox(points, static_cast<int>(std::log2(i + 1))));
      }
    }
    EXPECT_TRUE(moved);
  }
}

// The lens pair is a (0, 2)-sequence: every 2^k prefix, of the one stream and of each of the two,
// one point in each elementary box of the lens square (recovered through the disk map's inverse).
TEST(Sobol, EveryPowerOfTwoPrefixIsOneLensPointPerElementaryBox) {
  for (std::uint32_t seed : {1u, 3u, 99u})
    for (int stream : {-1, 0, 1})
      for (int k = 0; k <= 10; ++k)
        EXPECT_TRUE(oneInEachBox(pair(prefix(seed, stream, 1 << k), 0), k))
            << "seed " << seed << ", stream " << stream << ", 2^" << k;
}

// Joe and Kuo's dimensions 2 and 3 as a pair are a (2, 2)-sequence: every box of area 4/2^k holds
// exactly four of a 2^k prefix. And all four dimensions together are a (3, 4)-sequence: each box
// of volume 8/2^k, of any shape, holds exactly eight — the joint stratification that two pairs
// paired at random (each a net of its own) do not have.
TEST(Sobol, EveryPowerOfTwoPrefixIsANetOnThePixelAndInFourDimensions) {
  for (int stream : {-1, 1}) {
    for (int k = 2; k <= 10; ++k) {
      const std::vector<glm::dvec4> points = prefix(5, stream, 1 << k);
      EXPECT_LE(netQuality(pair(points, 2), k), 2) << "pixel pair, stream " << stream << ", 2^" << k;
      EXPECT_LE(netQuality(points, k), 3) << "4-D, stream " << stream << ", 2^" << k;
    }
  }
}

// The same point of the two streams over many seeds: different points, and uncorrelated in every
// coordinate (one scramble shared, or derived from the other, would correlate them).
void expectIndependentStreams(LensSample (*sample)(std::uint32_t, std::uint32_t)) {
  constexpr int kSeeds = 4000;
  for (std::uint32_t point : {0u, 1u, 5u}) {
    double sum[4][3] = {};  // per coordinate: Σa, Σb, Σab
    int same = 0;
    for (std::uint32_t seed = 0; seed < kSeeds; ++seed) {
      const glm::dvec4 a = squareOf(sample(2 * point, seed)), b = squareOf(sample(2 * point + 1, seed));
      same += a == b;
      for (int j = 0; j < 4; ++j) {
        sum[j][0] += a[j];
        sum[j][1] += b[j];
        sum[j][2] += a[j] * b[j];
      }
    }
    EXPECT_EQ(same, 0);
    for (int j = 0; j < 4; ++j) {
      // Uniform coordinates: covariance / variance (1/12); its sampling spread is about 1/√kSeeds.
      const double covariance = sum[j][2] / kSeeds - sum[j][0] / kSeeds * sum[j][1] / kSeeds;
      EXPECT_LT(std::abs(covariance * 12.0), 4.0 / std::sqrt(kSeeds)) << "point " << point << ", coordinate " << j;
    }
  }
}

TEST(Sobol, TheTwoStreamsAreIndependentScrambles) {
  expectIndependentStreams(sobolTwoStreamSample);
  expectIndependentStreams(sobolSample);
  EXPECT_EQ(sobolStream(6), 0);
  EXPECT_EQ(sobolStream(7), 1);
  EXPECT_EQ(sobolTwoStreamSample(7, 2).pixel, sobolPoint(3, sobolStreamSeed(2, 1)).pixel);
  EXPECT_EQ(sobolTwoStreamSample(6, 2).lens, sobolPoint(3, sobolStreamSeed(2, 0)).lens);
}

// The per-tile budgets' order: each stream's lens and pixel pairs are one point per elementary box
// at every power of two, each on its own.
TEST(Sobol, ThePaddedOrdersStreamsStratifyLensAndPixelEachPowerOfTwo) {
  for (int stream : {0, 1})
    for (int k = 0; k <= 8; ++k) {
      std::vector<glm::dvec4> points;
      for (int i = 0; i < (1 << k); ++i)
        points.push_back(squareOf(sobolSample(static_cast<std::uint32_t>(2 * i + stream), 3)));
      EXPECT_TRUE(oneInEachBox(pair(points, 0), k)) << "lens, stream " << stream << ", 2^" << k;
      EXPECT_TRUE(oneInEachBox(pair(points, 2), k)) << "pixel, stream " << stream << ", 2^" << k;
    }
}

// A defocused pixel: cos(ω·(pixel.x + c·lens.x) + φ) over the pixel box and the unit disk. Its
// mean is known: cos φ · sin(ω/2)/(ω/2) · 2J₁(ωc)/(ωc). RMSE over integrands and seeds.
double smoothRmse(int count, bool sobol) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double squared = 0.0;
  int n = 0;
  for (std::uint32_t seed = 1; seed <= 16; ++seed) {
    std::vector<LensSample> samples;
    std::mt19937 pointRng(seed);
    for (int i = 0; i < count; ++i)
      samples.push_back(
          sobol ? sobolPoint(static_cast<std::uint32_t>(i), seed)
                : LensSample{concentricDisk({u(pointRng), u(pointRng)}), {u(pointRng) - 0.5, u(pointRng) - 0.5}});
    for (int f = 0; f < 20; ++f) {
      const double omega = 1.0 + 2.0 * u(rng), c = 0.2 + 3.0 * u(rng), phi = 6.0 * u(rng);
      double mean = 0.0;
      for (const LensSample& s : samples) mean += std::cos(omega * (s.pixel.x + c * s.lens.x) + phi) / count;
      const double truth =
          std::cos(phi) * std::sin(omega / 2.0) / (omega / 2.0) * 2.0 * std::cyl_bessel_j(1.0, omega * c) / (omega * c);
      squared += (mean - truth) * (mean - truth);
      ++n;
    }
  }
  return std::sqrt(squared / n);
}

TEST(Sobol, ASmoothDefocusedIntegrandConvergesFasterThanIndependentSamples) {
  const double sobol16 = smoothRmse(16, true), sobol256 = smoothRmse(256, true);
  const double random256 = smoothRmse(256, false);
  // Independent samples: RMSE ∝ N^−0.5. The 4-D net: about N^−1 here (−1.06 measured, and a
  // twelfth of the independent samples' RMSE at 256).
  const double slope = std::log(sobol256 / sobol16) / std::log(16.0);
  EXPECT_LT(slope, -0.8) << sobol16 << " → " << sobol256;
  EXPECT_LT(sobol256, random256 / 4.0);
}

}  // namespace
}  // namespace lenslab
