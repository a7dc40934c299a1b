#include "lens/SobolSequence.h"

#include <cassert>

namespace lenslab {
namespace {

std::uint32_t reverseBits(std::uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

// A hash whose bit k depends only on bits 0..k of x (multiplication by an even constant carries
// upward only) — applied to the reversed fraction, each bit depends on the bits above it, which is
// Owen's nesting. Constants from Laine and Karras (2011), as used by Burley (2020).
std::uint32_t laineKarras(std::uint32_t x, std::uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

std::uint32_t mix(std::uint32_t x) {  // a 32-bit integer hash (lowbias32), for per-stream seeds
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

double toUnit(std::uint32_t fraction) { return fraction * 0x1p-32; }

// Direction numbers of dimensions 2 and 3 (Joe and Kuo 2008, new-joe-kuo-6.21201: primitive
// polynomials x² + x + 1 and x³ + x + 1, initial m = 1, 3 and 1, 3, 1), as 32-bit fractions:
// v_k = m_k / 2^(k+1) for the first s, then v_k = v_{k−s} ^ (v_{k−s} >> s) ^ Σ a_j v_{k−j}.
struct Directions {
  std::uint32_t v[2][32];
};

constexpr Directions makeDirections() {
  Directions d{};
  struct Polynomial {
    int degree;
    std::uint32_t inner;  // the coefficients between the leading and the constant one
    std::uint32_t m[3];
  };
  constexpr Polynomial polynomials[2] = {{2, 1, {1, 3, 0}}, {3, 1, {1, 3, 1}}};
  for (int p = 0; p < 2; ++p) {
    const Polynomial& poly = polynomials[p];
    std::uint32_t* v = d.v[p];
    for (int k = 0; k < poly.degree; ++k) v[k] = poly.m[k] << (31 - k);
    for (int k = poly.degree; k < 32; ++k) {
      v[k] = v[k - poly.degree] ^ (v[k - poly.degree] >> poly.degree);
      for (int j = 1; j < poly.degree; ++j)
        if ((poly.inner >> (poly.degree - 1 - j)) & 1u) v[k] ^= v[k - j];
    }
  }
  return d;
}

constexpr Directions kDirections = makeDirections();

}  // namespace

std::uint32_t sobolDimension0(std::uint32_t index) { return reverseBits(index); }

std::uint32_t sobolDimension1(std::uint32_t index) {
  // Direction numbers of the second dimension: v_k = v_{k−1} ^ (v_{k−1} >> 1), v_0 = 1 << 31.
  std::uint32_t result = 0;
  for (std::uint32_t v = 1u << 31; index != 0; index >>= 1, v ^= v >> 1)
    if (index & 1u) result ^= v;
  return result;
}

std::uint32_t sobolDimension(int dimension, std::uint32_t index) {
  assert(dimension >= 0 && dimension < 4);
  if (dimension == 0) return sobolDimension0(index);
  if (dimension == 1) return sobolDimension1(index);
  const std::uint32_t* v = kDirections.v[dimension - 2];
  std::uint32_t result = 0;
  for (int k = 0; index != 0; index >>= 1, ++k)
    if (index & 1u) result ^= v[k];
  return result;
}

std::uint32_t owenScramble(std::uint32_t fraction, std::uint32_t seed) {
  return reverseBits(laineKarras(reverseBits(fraction), seed));
}

int sobolStream(int viewIndex) { return viewIndex & 1; }

std::uint32_t sobolStreamSeed(std::uint32_t seed, int stream) {
  return mix(seed * 2u + static_cast<std::uint32_t>(stream) + 0x9e3779b9u);
}

LensSample sobolPoint(std::uint32_t index, std::uint32_t seed) {
  // One scramble per dimension: Owen scrambling each coordinate with its own seed keeps every
  // projection's boxes (the scramble permutes a coordinate's elementary intervals among themselves).
  double u[4];
  for (int d = 0; d < 4; ++d)
    u[d] =
        toUnit(owenScramble(sobolDimension(d, index), mix(seed ^ (0x632be5abu * static_cast<std::uint32_t>(d + 1)))));
  return {concentricDisk({u[0], u[1]}), glm::dvec2(u[2], u[3]) - 0.5};
}

LensSample sobolTwoStreamSample(std::uint32_t index, std::uint32_t seed) {
  const int stream = static_cast<int>(index & 1u);
  return sobolPoint(index >> 1, sobolStreamSeed(seed, stream));
}

LensSample sobolSample(std::uint32_t index, std::uint32_t seed) {
  const std::uint32_t stream = index & 1u, point = index >> 1;
  const std::uint32_t base = mix(seed * 2u + stream + 0x9e3779b9u);
  const std::uint32_t s[5] = {mix(base ^ 1u), mix(base ^ 2u), mix(base ^ 3u), mix(base ^ 4u), mix(base ^ 5u)};
  const glm::dvec2 lensU(toUnit(owenScramble(sobolDimension0(point), s[0])),
                         toUnit(owenScramble(sobolDimension1(point), s[1])));
  // The pixel's points in another order: the index's bits scrambled from the top (nested), which
  // maps each aligned block of 2^k indices onto an aligned block — and every aligned block of 2^k
  // points of a (0, 2)-sequence is itself one point per stratum.
  const std::uint32_t shuffled = reverseBits(laineKarras(reverseBits(point), s[2]));
  const glm::dvec2 pixelU(toUnit(owenScramble(sobolDimension0(shuffled), s[3])),
                          toUnit(owenScramble(sobolDimension1(shuffled), s[4])));
  return {concentricDisk(lensU), pixelU - 0.5};
}

}  // namespace lenslab
