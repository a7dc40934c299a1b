#include "scene/Brdf.h"

#include "scene/Scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <stdexcept>

namespace lenslab {

namespace {
const std::vector<glm::vec3>& table();
}

// The GLSL, as C++: glm's names are GLSL's.
namespace glsl {
using glm::clamp;
using glm::cross;
using glm::dot;
using glm::length;
using glm::max;
using glm::min;
using glm::mix;
using glm::normalize;
using glm::vec2;
using glm::vec3;
using std::cos;
using std::sqrt;
// brdf.glsl's one input from its includer: a texel of the DFG table.
vec3 dfgTexel(int x, int y) {
  return table()[static_cast<std::size_t>(y * kDfgTableSize + x)];
}  // = kDfgSize, asserted below
#include "../../shaders/common/brdf.glsl"
}  // namespace glsl

static_assert(glsl::kDfgSize == kDfgTableSize);
static_assert(glsl::kLightDirectional == static_cast<int>(LightType::Directional));
static_assert(glsl::kLightPoint == static_cast<int>(LightType::Point));
static_assert(glsl::kLightSpot == static_cast<int>(LightType::Spot));

namespace {

glsl::Surface toGlsl(const ShadingSurface& s) {
  return {s.baseColor, s.metallic, s.perceptualRoughness, s.occlusion, s.n, s.v};
}

glsl::Light toGlsl(const ShadingLight& l) {
  return {l.type, l.intensity, l.position, l.direction, l.range, l.spotScale, l.spotOffset};
}

// The i-th of n points of the Hammersley set: (i/n, radical inverse of i in base 2).
glm::vec2 hammersley(std::uint32_t i, std::uint32_t n) {
  std::uint32_t bits = i;
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return {static_cast<float>(i) / static_cast<float>(n), static_cast<float>(bits) * 2.3283064365386963e-10f};
}

#ifdef LENSLAB_DFG_TABLE_UNBAKED
// tools/make_dfg_table.cpp's own build of this file: it writes the values and reads none, and
// those it replaces may be of another size (which the static_assert below refuses).
const std::vector<glm::vec3>& table() {
  throw std::logic_error("this build has no baked DFG table (LENSLAB_DFG_TABLE_UNBAKED)");
}
#else
const std::vector<glm::vec3>& table() {
  static constexpr float kValues[] = {
#include "scene/DfgTableValues.inc"
  };
  static_assert(std::size(kValues) == 3 * kDfgTableSize * kDfgTableSize);
  static const std::vector<glm::vec3> t = [] {
    std::vector<glm::vec3> values(static_cast<std::size_t>(kDfgTableSize * kDfgTableSize));
    for (std::size_t i = 0; i < values.size(); ++i)
      values[i] = {kValues[3 * i], kValues[3 * i + 1], kValues[3 * i + 2]};
    return values;
  }();
  return t;
}
#endif

}  // namespace

glm::vec3 dfgTexelIntegral(int x, int y) {
  // Edge-aligned: texel i at i / (size − 1). At n·v = 0 the view lies in the tangent plane, which
  // no shaded point is seen from (a silhouette's n·v ≤ 0 is clamped to 0 as the grazing limit), and
  // half of the importance samples' reflected directions fall on or below the horizon; the texel
  // holds the limit from above, taken at kDfgMinNv.
  const float last = static_cast<float>(kDfgTableSize - 1);
  const float nv = std::max(static_cast<float>(x) / last, kDfgMinNv);
  const float roughness = static_cast<float>(y) / last;
  return glm::vec3(dfgIntegral(nv, glsl::alphaFromPerceptual(roughness), kDfgSamples),
                   dfgDiffuseIntegral(nv, kDfgDiffuseSteps));
}

float dfgDiffuseIntegral(float nv, int steps) {
  // Cosine-distributed l: with u = sin²θ_l uniform on [0, 1] and φ uniform, (n·l)/π dl = du dφ / (2π),
  // so K is the mean of 1 − (1 − v·h)⁵ over the (u, φ) rectangle. Midpoints: the integrand is
  // smooth, and a fixed rule gives the same value on every CPU up to libm's last bits.
  const glm::dvec3 v(std::sqrt(std::max(0.0, 1.0 - double(nv) * nv)), 0.0, nv);
  double sum = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double u = (i + 0.5) / steps;
    const double sinTheta = std::sqrt(u), cosTheta = std::sqrt(1.0 - u);
    for (int j = 0; j < 2 * steps; ++j) {
      const double phi = (j + 0.5) / (2 * steps) * 2.0 * glsl::kPi;
      const glm::dvec3 l(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
      const glm::dvec3 halfway = l + v;
      const double halfwayLength = glm::length(halfway);
      const double vh = halfwayLength > 0.0 ? std::clamp(glm::dot(v, halfway) / halfwayLength, 0.0, 1.0) : 0.0;
      sum += 1.0 - std::pow(1.0 - vh, 5.0);
    }
  }
  return static_cast<float>(sum / (2.0 * steps * steps));
}

glm::vec2 dfgIntegral(float nv, float alpha, int samples) {
  // n = +z, v in the xz plane. Half vectors drawn from D(h)·(n·h), so that the sample weight of
  // f·(n·l) with f = F·D·V is F · V · 4 (v·h) (n·l) / (n·h), split into F's two terms.
  const glm::dvec3 v(std::sqrt(std::max(0.0, 1.0 - double(nv) * nv)), 0.0, nv);
  const double a2 = double(alpha) * alpha;
  double sumA = 0.0, sumB = 0.0;
  for (int i = 0; i < samples; ++i) {
    const glm::vec2 u = hammersley(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(samples));
    const double phi = 2.0 * glsl::kPi * u.x;
    const double cosTheta = std::sqrt((1.0 - u.y) / (1.0 + (a2 - 1.0) * u.y));
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const glm::dvec3 h(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
    const double vh = glm::dot(v, h);
    const glm::dvec3 l = 2.0 * vh * h - v;
    if (l.z <= 0.0 || vh <= 0.0) continue;
    const double visibility = glsl::visibilitySmithGgx(static_cast<float>(l.z), nv, alpha);
    const double weight = visibility * 4.0 * vh * l.z / h.z;
    const double fc = std::pow(1.0 - vh, 5.0);
    sumA += (1.0 - fc) * weight;
    sumB += fc * weight;
  }
  return {static_cast<float>(sumA / samples), static_cast<float>(sumB / samples)};
}

glm::vec3 punctualRadiance(const ShadingSurface& s, const ShadingLight& light, const glm::vec3& p) {
  return glsl::punctualRadiance(toGlsl(s), toGlsl(light), p);
}

glm::vec3 imageLightRadiance(const ShadingSurface& s, const glm::vec3& diffuseRadiance,
                             const glm::vec3& specularRadiance, glm::vec3 dfg) {
  return glsl::imageLightRadiance(toGlsl(s), diffuseRadiance, specularRadiance, dfg);
}

glm::vec3 specularDominantDirection(const glm::vec3& n, const glm::vec3& v, float perceptualRoughness) {
  return glsl::specularDominantDirection(n, v, perceptualRoughness);
}

glm::vec2 spotScaleOffset(float innerConeAngleRadians, float outerConeAngleRadians) {
  return glsl::spotScaleOffset(innerConeAngleRadians, outerConeAngleRadians);
}

const std::vector<glm::vec3>& dfgTable() { return table(); }

glm::vec3 dfgLookup(float nv, float perceptualRoughness) { return glsl::dfgLookup(nv, perceptualRoughness); }

}  // namespace lenslab
