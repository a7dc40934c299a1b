#pragma once
// glTF 2.0's metallic-roughness BRDF and KHR_lights_punctual's lights, as the ray caster evaluates
// them. The functions are shaders/common/brdf.glsl compiled as C++ (Brdf.cpp), the same text the
// rasterizer's scene.frag includes, so both renderers shade alike (docs/materials.md).
#include <glm/glm.hpp>

#include <vector>

namespace lenslab {

// A surface point as the shading sees it (brdf.glsl's Surface).
struct ShadingSurface {
  glm::vec3 baseColor{1.0f};         // linear RGB
  float metallic = 0.0f;             // [0, 1]
  float perceptualRoughness = 1.0f;  // [0, 1]; clamped below at kMinPerceptualRoughness
  float occlusion = 1.0f;            // [0, 1], image light only
  glm::vec3 n{0.0f, 0.0f, 1.0f};     // unit shading normal
  glm::vec3 v{0.0f, 0.0f, 1.0f};     // unit, toward the eye of this view
};

// A punctual light with its position relative to the shaded point's origin (brdf.glsl's Light).
struct ShadingLight {
  int type = 0;               // 0 directional, 1 point, 2 spot (LightType's order)
  glm::vec3 intensity{0.0f};  // colour × lux (directional) or × candela (point, spot)
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit, the way it shines
  float range = 0.0f;                      // 0: unbounded
  float spotScale = 0.0f;                  // spotScaleOffset's
  float spotOffset = 0.0f;
};

// Radiance toward s.v from `light` at point `p` (relative to the light's origin).
glm::vec3 punctualRadiance(const ShadingSurface& s, const ShadingLight& light, const glm::vec3& p);
// Radiance toward s.v from light all around: diffuse and specular radiance, the DFG table's three
// terms; times the occlusion.
glm::vec3 imageLightRadiance(const ShadingSurface& s, const glm::vec3& diffuseRadiance,
                             const glm::vec3& specularRadiance, glm::vec3 dfg);
// Unit direction to read the prefiltered specular along: the reflection of v about n, leaned toward
// n as roughness grows (brdf.glsl's specularDominantDirection).
glm::vec3 specularDominantDirection(const glm::vec3& n, const glm::vec3& v, float perceptualRoughness);
// KHR_lights_punctual's cone factors (scale, offset): attenuation clamp(cos θ·scale + offset, 0, 1)².
glm::vec2 spotScaleOffset(float innerConeAngleRadians, float outerConeAngleRadians);

// The split-sum DFG table: kDfgTableSize² texels (x: n·v, y: perceptual roughness; texel i holds
// the value at i / (size − 1), so the table reaches both ends of each axis; n·v 0 at kDfgMinNv),
// each (A, B, K): directional albedo E = F0·A + B of the GGX specular lobe with height-correlated
// Smith visibility, and K = ∫ (1 − (1 − v·h)⁵) (n·l)/π dl, the diffuse lobe's weight under uniform
// light (the glTF diffuse (1 − F(v·h)) c_diff/π integrates to (1 − F0)·c_diff·K). K does not depend
// on roughness; it rides in the same texel, so reading it costs no extra lookup. A and B are
// importance-sampled (GGX half vectors at a fixed
// Hammersley set of kDfgSamples points): dfgTexelIntegral, baked into the source by
// tools/update-dfg-table.sh (src/scene/DfgTableValues.inc), so no run computes it.
constexpr int kDfgTableSize = 32;
constexpr int kDfgSamples = 1024;
constexpr int kDfgDiffuseSteps = 128;
constexpr float kDfgMinNv = 1e-4f;         // the n·v that column 0 is integrated at
const std::vector<glm::vec3>& dfgTable();  // row by row: index y · size + x
// The table bilinear at (n·v, perceptual roughness), as brdf.glsl's dfgLookup.
glm::vec3 dfgLookup(float nv, float perceptualRoughness);
// The table's integral computed directly at (n·v, α) with `samples` samples (tests measure the
// table's interpolation error against it).
glm::vec2 dfgIntegral(float nv, float alpha, int samples);
// K at n·v by a product midpoint rule over cosine-distributed light directions (`steps` × 2·steps).
float dfgDiffuseIntegral(float nv, int steps);
// What texel (x, y) of the table stands for: dfgIntegral at its (n·v, roughness) with kDfgSamples
// samples, and dfgDiffuseIntegral at its n·v with kDfgDiffuseSteps.
glm::vec3 dfgTexelIntegral(int x, int y);

}  // namespace lenslab
