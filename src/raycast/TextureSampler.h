#pragma once
// Texture sampling as the GPU does it, so that the ray caster's image differs from the raster's
// only by the method: the same wrap modes, the same bilinear and mipmap filters, sRGB decoded to
// linear before filtering, and a mip chain built like glGenerateMipmap (2×2 box in linear light,
// stored back as 8-bit sRGB).
//
// Minification: the level of detail is GL's λ = log2 ρ with ρ the larger of the lengths of the
// texel-space derivatives along image x and y (OpenGL 4.5 §8.14.1). The ray caster gets those
// derivatives from ray differentials: the rays one sample footprint over (a pixel for one sample,
// 1/√spp of a pixel for spp stratified samples), cut with the plane of the hit triangle.
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace lenslab {

class TextureSampler {
 public:
  TextureSampler() = default;
  // `srgb`: the image holds colour, decoded from sRGB before filtering (GL_SRGB8_ALPHA8); false:
  // it holds data (normal, metallic-roughness, occlusion maps), filtered as stored (GL_RGBA8).
  TextureSampler(const TextureImage& image, bool mipmaps, bool srgb = true);

  // uv in glTF's convention (0, 0 at the image's top-left); dUvDx, dUvDy: how far uv moves across
  // the sample's footprint along image x and y. Returns linear RGBA.
  glm::vec4 sample(const Sampler& sampler, glm::vec2 uv, glm::vec2 dUvDx, glm::vec2 dUvDy) const;

  int levels() const { return static_cast<int>(levels_.size()); }

 private:
  struct Level {
    int width = 0;
    int height = 0;
    std::vector<glm::vec4> texels;  // linear, decoded from the stored 8 bits (sRGB or not)
  };
  glm::vec4 bilinear(const Level& level, const Sampler& s, glm::vec2 uv, bool linear) const;

  std::vector<Level> levels_;
};

}  // namespace lenslab
