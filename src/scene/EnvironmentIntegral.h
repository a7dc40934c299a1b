#pragma once
// The light a glTF surface reflects from an environment, integrated directly: a Monte Carlo
// estimate of  L_o(v) = ∫ L_env(l) f(v, l) (n·l) dl  over the hemisphere about n, with f the
// glTF metallic-roughness BRDF as brdf.glsl defines it (Lambert (1 − F) c_diff / π plus GGX,
// height-correlated Smith and Schlick's F) and L_env the environment's full-resolution radiance
// (the background lookup: bilinear, no prefiltering). Pure C++, no GL.
//
// It is the yardstick for the split sum both renderers use (splitSumRadiance below): their
// agreement with each other says nothing about the split sum's own error, this does
// (docs/environment.md, "How far the split sum is from the true integral").
//
// Sampling: the specular lobe (the same surface as a metal of base colour F0) and the diffuse
// lobe (the rest of f) are integrated apart, half the samples each (all to the specular for a
// metal), each by two strategies combined with the balance heuristic (Veach's multi-sample MIS):
// specular from the GGX distribution of half vectors (D(h)·(n·h)) and, in a share that grows with
// α up to a third, from the environment's own luminance (a texel picked with probability ∝
// luminance × solid angle, then a direction uniform in solid angle within it); diffuse half from
// cos θ / π, half from the luminance. A sample's weight f·L·(n·l) / Σ c_i p_i(l) stays bounded
// wherever one density follows the integrand, so neither a mirror-like lobe nor a small bright
// light gives fireflies; GGX and the cosine cover the whole hemisphere, so the estimate is
// unbiased even where the luminance density is zero (a black texel lit by its neighbours through
// bilinear interpolation).
#include "scene/Brdf.h"
#include "scene/Environment.h"

#include <cstdint>
#include <vector>

namespace lenslab {

struct RadianceEstimate {
  glm::dvec3 mean{0.0};
  // The standard error of `mean`, per channel, from the samples' spread. The strategies take
  // their turns in a fixed order, which can only lower the true error below this (pooled) one.
  glm::dvec3 standardError{0.0};
};

class EnvironmentIntegral {
 public:
  // `image`: the environment as read (unturned, intensity 1), width = 2 × height ≥ 2.
  explicit EnvironmentIntegral(EnvironmentImage image);

  // L_env along `direction` (unit): the source image, bilinear (environment.glsl's background).
  glm::dvec3 radiance(const glm::dvec3& direction) const;
  // L_o toward s.v from `samples` samples (rounded up to whole turns of the strategies), seeded.
  RadianceEstimate outgoingRadiance(const ShadingSurface& s, int samples, std::uint64_t seed) const;
  // The environment strategy's density (per steradian) of `direction`, for tests.
  double environmentPdf(const glm::dvec3& direction) const;

 private:
  // The environment strategy's direction from three uniform numbers in [0, 1).
  glm::dvec3 sampleLuminance(double u1, double u2, double u3) const;

  EnvironmentImage image_;
  std::vector<double> texelCdf_;  // running sum of luminance × solid angle, texel by texel
  double luminanceTimesSolidAngle_ = 0.0;
};

// What both renderers compute for the same surface (the ray caster's shading, RayCaster.cpp):
// imageLightRadiance with the prefiltered diffuse about n, the prefiltered specular about the
// reflected direction at s.perceptualRoughness, and the DFG table at (n·v, roughness).
glm::vec3 splitSumRadiance(const EnvironmentLookup& lookup, const ShadingSurface& s);

// Rec. 709 luminance, the weights the environment strategy samples by.
double luminance(const glm::dvec3& rgb);

}  // namespace lenslab
