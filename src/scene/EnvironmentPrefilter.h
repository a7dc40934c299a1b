#pragma once
// Prefiltering an environment for image-based lighting (the split-sum approximation: radiance
// prefiltered per roughness with the view along the normal, as Karis 2013 and Filament do).
// Pure C++, spread over the cores by TBB; every output texel is computed alone from the same
// inputs, so the result does not depend on the number of threads.
//
// Diffuse: irradiance / π as a small equirectangular map (diffuseWidth × diffuseWidth/2), each
// texel the cosine-weighted mean of the source over its hemisphere, summed over every texel of
// the source's pyramid level of at most diffuseSourceWidth columns with its solid angle. A map,
// not nine spherical-harmonic coefficients: SH9 rings (goes negative) around small bright soft
// boxes and a sun, and a map is looked up in both renderers by the same bilinear fetches as the
// other maps. The discrete cosine weights are divided by their own sum (≈ π), so a constant
// environment gives back exactly its constant.
//
// Specular: levels 1 … n − 1 (perceptual roughness r_min + (1 − r_min)·l / (n − 1), r_min =
// kEnvironmentMinRoughness, GGX α its square), each
// specularWidth × specularWidth/2, each texel the NdotL-weighted mean of samplesPerTexel GGX
// importance samples (Hammersley) around its direction, each sample read from the source's
// pyramid at the level whose texels match the solid angle the sample stands for (filtered
// importance sampling, Colbert and Křivánek 2007): no fireflies from a small bright light.
// Level 0 is the source itself: it stands for roughness r_min, whose lobe (α ≈ 0.002) is narrower
// than a texel of any source we load.
#include "scene/Environment.h"

#include <cstdint>
#include <string>

namespace lenslab {

struct PrefilterSettings {
  int diffuseWidth = 64;         // the diffuse map's columns (rows: half)
  int diffuseSourceWidth = 256;  // the diffuse sum reads the source's pyramid at most this wide
  int specularWidth = 256;       // each specular level's columns (rows: half)
  int specularLevels = 6;        // including level 0: roughness 0.045, 0.236, … 1
  int samplesPerTexel = 256;     // GGX samples per specular texel
  // Everything that changes the result, for the cache's key.
  std::string key() const;
};

// The prefiltered maps of `source` (width = 2 × height ≥ 2, finite, non-negative radiance).
PrefilteredEnvironment prefilterEnvironment(EnvironmentImage source, const PrefilterSettings& settings = {});

// The source's pyramid: level 0 the image, each next one half as wide and high (2 × 2 texels
// averaged with their solid angles, so that each level holds the same radiant power), down to
// 2 × 1. For filtered importance sampling and the diffuse sum.
std::vector<EnvironmentImage> environmentPyramid(const EnvironmentImage& source);

}  // namespace lenslab
