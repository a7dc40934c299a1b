#include "scene/EnvironmentIntegral.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace lenslab {
namespace {

constexpr double kPi = std::numbers::pi;
// brdf.glsl's floor on perceptual roughness. Only the GGX strategy's shape uses it here (the BRDF
// itself is brdf.glsl's, floor included), so a mismatch would cost noise, never bias.
constexpr double kMinPerceptualRoughness = 0.045;

// splitmix64: a small, fast generator whose sequence is the same on every platform.
struct Random {
  std::uint64_t state;
  double next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;  // [0, 1)
  }
};

// An orthonormal frame around unit n (Duff et al. 2017).
void frameAround(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double c = n.x * n.y * a;
  t = {1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

// The GGX half-vector density D(h)·(n·h) carried to l = reflect(−v, h): D (n·h) / (4 v·h). D in
// the |n × h|² + (n·h)² α² form, as brdf.glsl, which stays accurate at α = 0.045².
double ggxPdf(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double alpha) {
  const glm::dvec3 sum = v + l;
  const double length = glm::length(sum);
  if (!(length > 0.0)) return 0.0;
  const glm::dvec3 h = sum / length;
  const double nh = glm::dot(n, h), vh = glm::dot(v, h);
  if (nh <= 0.0 || vh <= 0.0) return 0.0;
  const glm::dvec3 nxh = glm::cross(n, h);
  const double a2 = alpha * alpha;
  const double f = glm::dot(nxh, nxh) + nh * nh * a2;
  const double d = a2 / (kPi * f * f);
  return d * nh / (4.0 * vh);
}

// The centre direction convention of scene/Environment.h, in double: (u, v) to a unit direction.
glm::dvec3 directionFromUvDouble(double u, double cosTheta) {
  const double phi = (u - 0.5) * 2.0 * kPi;
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return {sinTheta * std::sin(phi), cosTheta, -sinTheta * std::cos(phi)};
}

// A GGX half vector h about n (frame t, b, n; a2 = α²) from (u1, u2), as the direction l that
// reflects v about it: the specular lobe's own importance sampling.
glm::dvec3 sampleGgxReflection(const glm::dvec3& n, const glm::dvec3& t, const glm::dvec3& b, const glm::dvec3& v,
                               double a2, double u1, double u2) {
  const double phi = 2.0 * kPi * u1;
  const double cosTheta = std::sqrt((1.0 - u2) / (1.0 + (a2 - 1.0) * u2));
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  const glm::dvec3 h = sinTheta * std::cos(phi) * t + sinTheta * std::sin(phi) * b + cosTheta * n;
  return 2.0 * glm::dot(v, h) * h - v;
}

// A cosine-distributed direction about n (frame t, b, n) from (u1, u2): the diffuse lobe's shape.
glm::dvec3 sampleCosine(const glm::dvec3& n, const glm::dvec3& t, const glm::dvec3& b, double u1, double u2) {
  const double phi = 2.0 * kPi * u1;
  const double r = std::sqrt(u2);
  return r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0, 1.0 - u2)) * n;
}

}  // namespace

double luminance(const glm::dvec3& rgb) { return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b; }

EnvironmentIntegral::EnvironmentIntegral(EnvironmentImage image) : image_(std::move(image)) {
  assert(image_.width == 2 * image_.height && image_.height >= 1);
  texelCdf_.resize(image_.rgb.size());
  double sum = 0.0;
  for (int y = 0; y < image_.height; ++y) {
    const double omega = texelSolidAngle(y, image_.width, image_.height);
    for (int x = 0; x < image_.width; ++x) {
      sum += luminance(glm::dvec3(image_.at(x, y))) * omega;
      texelCdf_[static_cast<std::size_t>(y) * image_.width + x] = sum;
    }
  }
  luminanceTimesSolidAngle_ = sum;
}

glm::dvec3 EnvironmentIntegral::radiance(const glm::dvec3& direction) const {
  return glm::dvec3(sampleBilinear(image_, uvFromDirection(glm::vec3(direction))));
}

double EnvironmentIntegral::environmentPdf(const glm::dvec3& direction) const {
  if (!(luminanceTimesSolidAngle_ > 0.0)) return 0.0;
  const glm::vec2 uv = uvFromDirection(glm::vec3(direction));
  const int x = std::clamp(static_cast<int>(uv.x * static_cast<float>(image_.width)), 0, image_.width - 1);
  const int y = std::clamp(static_cast<int>(uv.y * static_cast<float>(image_.height)), 0, image_.height - 1);
  // P(texel) / Ω(texel) = luminance × Ω / total / Ω.
  return luminance(glm::dvec3(image_.at(x, y))) / luminanceTimesSolidAngle_;
}

// A direction drawn in proportion to luminance × solid angle: u3 picks the texel by its running
// sum, (u1, u2) the point inside it, uniform in longitude and in cos θ (the texel's solid angle).
glm::dvec3 EnvironmentIntegral::sampleLuminance(double u1, double u2, double u3) const {
  const double pick = u3 * luminanceTimesSolidAngle_;
  const auto texel = static_cast<std::size_t>(
      std::min<std::ptrdiff_t>(std::upper_bound(texelCdf_.begin(), texelCdf_.end(), pick) - texelCdf_.begin(),
                               static_cast<std::ptrdiff_t>(texelCdf_.size()) - 1));
  const int x = static_cast<int>(texel % static_cast<std::size_t>(image_.width));
  const int y = static_cast<int>(texel / static_cast<std::size_t>(image_.width));
  const double cosTop = std::cos(kPi * y / image_.height), cosBottom = std::cos(kPi * (y + 1) / image_.height);
  return directionFromUvDouble((x + u1) / image_.width, cosTop + u2 * (cosBottom - cosTop));
}

RadianceEstimate EnvironmentIntegral::outgoingRadiance(const ShadingSurface& s, int samples, std::uint64_t seed) const {
  const glm::dvec3 n = glm::normalize(glm::dvec3(s.n));
  const glm::dvec3 v = glm::normalize(glm::dvec3(s.v));
  glm::dvec3 t, b;
  frameAround(n, t, b);
  const double roughness = std::clamp(static_cast<double>(s.perceptualRoughness), kMinPerceptualRoughness, 1.0);
  const double alpha = roughness * roughness, a2 = alpha * alpha;
  const bool withEnvironment = luminanceTimesSolidAngle_ > 0.0;

  // f · (n·l) from brdf.glsl itself: a directional light of 1 lux from l gives exactly that.
  // The specular lobe alone is the same surface as a metal of base colour F0 (brdf.glsl's
  // specularF0), which has no diffuse; the diffuse lobe is the rest. Each lobe gets its own
  // estimate with the strategies that follow it; should the split here differ from brdf.glsl's,
  // the two estimates would still sum to the whole integral.
  ShadingSurface surface = s;
  surface.n = glm::vec3(n);
  surface.v = glm::vec3(v);
  ShadingSurface specularOnly = surface;
  specularOnly.baseColor = glm::mix(glm::vec3(0.04f), s.baseColor, s.metallic);
  specularOnly.metallic = 1.0f;
  ShadingLight light;
  light.type = 0;
  light.intensity = glm::vec3(1.0f);
  const auto fTimesCos = [&](const ShadingSurface& at, const glm::dvec3& l) {
    light.direction = glm::vec3(-l);
    return glm::dvec3(punctualRadiance(at, light, glm::vec3(0.0f)));
  };
  const bool withDiffuse = glm::dot(s.baseColor * (1.0f - s.metallic), glm::vec3(1.0f)) > 0.0f;

  enum Strategy { Ggx, Cosine, Light };
  Random random{seed * 0x2545f4914f6cdd1dull + 1};
  const auto sampleDirection = [&](Strategy strategy) -> glm::dvec3 {
    const double u1 = random.next(), u2 = random.next();
    if (strategy == Ggx) return sampleGgxReflection(n, t, b, v, a2, u1, u2);
    if (strategy == Cosine) return sampleCosine(n, t, b, u1, u2);
    return sampleLuminance(u1, u2, random.next());
  };
  const auto pdfOf = [&](Strategy strategy, const glm::dvec3& l) {
    if (strategy == Ggx) return ggxPdf(n, v, l, alpha);
    if (strategy == Cosine) return std::max(0.0, glm::dot(n, l)) / kPi;
    return environmentPdf(l);
  };
  // One lobe's integral of lobe(l) · L(l) from `count` samples: the first strategy takes its
  // share, the second the rest (none when there is no luminance to follow), each sample weighted
  // by the balance heuristic with the shares actually taken.
  glm::dvec3 total(0.0), variance(0.0);
  const auto estimateLobe = [&](const auto& lobe, Strategy first, Strategy second, double secondShare, int count) {
    const int secondCount = withEnvironment || second != Light ? static_cast<int>(std::lround(secondShare * count)) : 0;
    const double c1 = static_cast<double>(count - secondCount) / count, c2 = static_cast<double>(secondCount) / count;
    glm::dvec3 sum(0.0), sumSquares(0.0);
    for (int i = 0; i < count; ++i) {
      const glm::dvec3 l = sampleDirection(i < count - secondCount ? first : second);
      const double pdf = c1 * pdfOf(first, l) + (c2 > 0.0 ? c2 * pdfOf(second, l) : 0.0);
      glm::dvec3 value(0.0);
      if (glm::dot(n, l) > 0.0 && pdf > 0.0) value = lobe(l) * radiance(l) / pdf;
      sum += value;
      sumSquares += value * value;
    }
    const glm::dvec3 mean = sum / double(count);
    total += mean;
    // Pooled over both strategies: at least the true variance of the mean of stratified turns.
    variance += glm::max(sumSquares / double(count) - mean * mean, glm::dvec3(0.0)) / std::max(1.0, count - 1.0);
  };
  samples = std::max(samples, 2);
  // The specular lobe: GGX, and the luminance as the lobe widens (a mirror's lobe is too narrow
  // for another strategy's samples to land in; they would only add noise).
  const int specularSamples = withDiffuse ? samples / 2 : samples;
  estimateLobe([&](const glm::dvec3& l) { return fTimesCos(specularOnly, l); }, Ggx, Light, std::min(1.0 / 3.0, alpha),
               specularSamples);
  // The diffuse lobe, the rest of f (Lambert's (1 − F) c_diff / π): the cosine and the luminance.
  if (withDiffuse)
    estimateLobe([&](const glm::dvec3& l) { return fTimesCos(surface, l) - fTimesCos(specularOnly, l); }, Cosine, Light,
                 0.5, samples - specularSamples);
  RadianceEstimate e;
  e.mean = total;
  e.standardError = glm::sqrt(variance);
  return e;
}

glm::vec3 splitSumRadiance(const EnvironmentLookup& lookup, const ShadingSurface& s) {
  const glm::vec3 diffuse = lookup.diffuse(s.n);
  const glm::vec3 specular =
      lookup.specular(specularDominantDirection(s.n, s.v, s.perceptualRoughness), s.perceptualRoughness);
  const glm::vec3 dfg = dfgLookup(glm::dot(s.n, s.v), s.perceptualRoughness);
  return imageLightRadiance(s, diffuse, specular, dfg);
}

}  // namespace lenslab
