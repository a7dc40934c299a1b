#include "scene/EnvironmentPrefilter.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace lenslab {
namespace {

constexpr double kPi = std::numbers::pi;

// Hammersley's second coordinate: i's bits mirrored about the binary point.
double radicalInverse(std::uint32_t i) {
  i = (i << 16u) | (i >> 16u);
  i = ((i & 0x55555555u) << 1u) | ((i & 0xAAAAAAAAu) >> 1u);
  i = ((i & 0x33333333u) << 2u) | ((i & 0xCCCCCCCCu) >> 2u);
  i = ((i & 0x0F0F0F0Fu) << 4u) | ((i & 0xF0F0F0F0u) >> 4u);
  i = ((i & 0x00FF00FFu) << 8u) | ((i & 0xFF00FF00u) >> 8u);
  return static_cast<double>(i) * 2.3283064365386963e-10;
}

// Pyramid level `lod` (fractional: linear between the two levels), bilinear within each.
glm::dvec3 samplePyramid(const std::vector<EnvironmentImage>& pyramid, const glm::vec2& uv, double lod) {
  const double top = static_cast<double>(pyramid.size() - 1);
  lod = std::clamp(lod, 0.0, top);
  const int l0 = std::min(static_cast<int>(lod), static_cast<int>(top));
  const double t = lod - l0;
  const glm::dvec3 a(sampleBilinear(pyramid[static_cast<std::size_t>(l0)], uv));
  if (t <= 0.0 || l0 + 1 > static_cast<int>(top)) return a;
  const glm::dvec3 b(sampleBilinear(pyramid[static_cast<std::size_t>(l0) + 1], uv));
  return a + t * (b - a);
}

// The centre direction of texel (x, y) of a W × H map.
glm::dvec3 texelDirection(int x, int y, int width, int height) {
  return glm::dvec3(directionFromUv({(static_cast<float>(x) + 0.5f) / static_cast<float>(width),
                                     (static_cast<float>(y) + 0.5f) / static_cast<float>(height)}));
}

// An orthonormal frame around unit n (Duff et al. 2017).
void frameAround(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double c = n.x * n.y * a;
  t = {1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

EnvironmentImage prefilterSpecular(const std::vector<EnvironmentImage>& pyramid, double perceptualRoughness,
                                   const PrefilterSettings& s) {
  const double alpha = perceptualRoughness * perceptualRoughness;
  const double alpha2 = alpha * alpha;
  const int width = s.specularWidth, height = s.specularWidth / 2;
  const int samples = s.samplesPerTexel;
  // The mean solid angle of a source texel: the footprint a sample is compared with.
  const double texelSolidAngle0 = 4.0 * kPi / (static_cast<double>(pyramid[0].width) * pyramid[0].height);

  // The samples in the tangent frame (z = n = v) with their pyramid level: the same for every texel.
  struct Sample {
    glm::dvec3 l;  // tangent frame
    double nDotL;
    double lod;
  };
  std::vector<Sample> pattern;
  for (int i = 0; i < samples; ++i) {
    const double phi = 2.0 * kPi * (i + 0.5) / samples;
    const double xi = radicalInverse(static_cast<std::uint32_t>(i));
    const double cosTheta = std::sqrt((1.0 - xi) / (1.0 + (alpha2 - 1.0) * xi));
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const glm::dvec3 h(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
    const glm::dvec3 l = 2.0 * h.z * h - glm::dvec3(0.0, 0.0, 1.0);  // v = n
    if (l.z <= 0.0) continue;
    // pdf of l: D(h)·(n·h) / (4 v·h), and v·h = n·h here.
    const double d = h.z * h.z * (alpha2 - 1.0) + 1.0;
    const double pdf = alpha2 / (kPi * d * d) / 4.0;
    const double sampleSolidAngle = 1.0 / (samples * pdf);
    // Colbert and Křivánek's level, biased by one level towards smooth (their +1).
    const double lod = alpha2 == 0.0 ? 0.0 : std::max(0.0, 0.5 * std::log2(sampleSolidAngle / texelSolidAngle0) + 1.0);
    pattern.push_back({l, l.z, lod});
  }

  EnvironmentImage out{width, height, std::vector<glm::vec3>(static_cast<std::size_t>(width) * height)};
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      for (int x = 0; x < width; ++x) {
        const glm::dvec3 n = texelDirection(x, y, width, height);
        glm::dvec3 t, b;
        frameAround(n, t, b);
        glm::dvec3 sum(0.0);
        double weight = 0.0;
        for (const Sample& p : pattern) {
          const glm::dvec3 l = p.l.x * t + p.l.y * b + p.l.z * n;
          sum += p.nDotL * samplePyramid(pyramid, uvFromDirection(glm::vec3(l)), p.lod);
          weight += p.nDotL;
        }
        out.at(x, y) =
            glm::vec3(weight > 0.0 ? sum / weight : samplePyramid(pyramid, uvFromDirection(glm::vec3(n)), 0.0));
      }
    }
  });
  return out;
}

EnvironmentImage prefilterDiffuse(const std::vector<EnvironmentImage>& pyramid, const PrefilterSettings& s) {
  // The widest level of at most diffuseSourceWidth columns.
  std::size_t level = 0;
  while (level + 1 < pyramid.size() && pyramid[level].width > s.diffuseSourceWidth) ++level;
  const EnvironmentImage& src = pyramid[level];
  struct Texel {
    glm::dvec3 direction;
    glm::dvec3 radianceTimesSolidAngle;
    double solidAngle;
  };
  std::vector<Texel> texels;
  texels.reserve(src.rgb.size());
  for (int y = 0; y < src.height; ++y) {
    const double omega = texelSolidAngle(y, src.width, src.height);
    for (int x = 0; x < src.width; ++x)
      texels.push_back({texelDirection(x, y, src.width, src.height), omega * glm::dvec3(src.at(x, y)), omega});
  }
  const int width = s.diffuseWidth, height = s.diffuseWidth / 2;
  EnvironmentImage out{width, height, std::vector<glm::vec3>(static_cast<std::size_t>(width) * height)};
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      for (int x = 0; x < width; ++x) {
        const glm::dvec3 n = texelDirection(x, y, width, height);
        glm::dvec3 sum(0.0);
        double weight = 0.0;
        for (const Texel& t : texels) {
          const double c = glm::dot(n, t.direction);
          if (c <= 0.0) continue;
          sum += c * t.radianceTimesSolidAngle;
          weight += c * t.solidAngle;
        }
        out.at(x, y) = glm::vec3(sum / weight);
      }
    }
  });
  return out;
}

}  // namespace

std::string PrefilterSettings::key() const {
  return "diffuse " + std::to_string(diffuseWidth) + " from " + std::to_string(diffuseSourceWidth) + ", specular " +
         std::to_string(specularWidth) + " × " + std::to_string(specularLevels) + " levels from roughness " +
         std::to_string(kEnvironmentMinRoughness) + ", " + std::to_string(samplesPerTexel) + " samples";
}

std::vector<EnvironmentImage> environmentPyramid(const EnvironmentImage& source) {
  std::vector<EnvironmentImage> pyramid{source};
  while (pyramid.back().width > 2 && pyramid.back().height > 1) {
    const EnvironmentImage& fine = pyramid.back();
    EnvironmentImage coarse{fine.width / 2, fine.height / 2, {}};
    coarse.rgb.resize(static_cast<std::size_t>(coarse.width) * coarse.height);
    for (int y = 0; y < coarse.height; ++y) {
      // Rows weighted by their texels' solid angles (an odd last row or column is dropped).
      const double w0 = texelSolidAngle(2 * y, fine.width, fine.height);
      const double w1 = texelSolidAngle(2 * y + 1, fine.width, fine.height);
      for (int x = 0; x < coarse.width; ++x) {
        const glm::dvec3 top = glm::dvec3(fine.at(2 * x, 2 * y)) + glm::dvec3(fine.at(2 * x + 1, 2 * y));
        const glm::dvec3 bottom = glm::dvec3(fine.at(2 * x, 2 * y + 1)) + glm::dvec3(fine.at(2 * x + 1, 2 * y + 1));
        coarse.at(x, y) = glm::vec3((w0 * top + w1 * bottom) / (2.0 * (w0 + w1)));
      }
    }
    pyramid.push_back(std::move(coarse));
  }
  return pyramid;
}

PrefilteredEnvironment prefilterEnvironment(EnvironmentImage source, const PrefilterSettings& settings) {
  assert(source.width == 2 * source.height && source.height >= 1);
  assert(settings.specularLevels >= 2 && settings.diffuseWidth >= 2 && settings.specularWidth >= 2);
  const std::vector<EnvironmentImage> pyramid = environmentPyramid(source);
  PrefilteredEnvironment out;
  out.diffuse = prefilterDiffuse(pyramid, settings);
  for (int level = 1; level < settings.specularLevels; ++level)
    out.specular.push_back(
        prefilterSpecular(pyramid, environmentLevelRoughness(level, settings.specularLevels), settings));
  out.background = std::move(source);
  return out;
}

}  // namespace lenslab
