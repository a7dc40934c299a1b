#version 450 core
// Variants (render/ScenePass.h): none, a plain view; DEPTH_ONLY (+ ALPHA_MASK), the depth pass of
// a view added into a sum; ADD_TO_SUM, its colour pass, which adds where depth is EQUAL.
#include "../common/shading.glsl"
// The environment's lookups, for the image-light term (call them where hasEnvironment is true).
#include "../common/environment_textures.glsl"

// Uniform locations and texture units, by who uses them (scene.vert uses locations 0–1):
//   2–16      base colour, alpha, the default light, emission (below)
//   20–79     metallic-roughness, occlusion and punctual lights   texture units 2–3 (+ 9 for a table)
//   80–99     normal maps and KHR_texture_transform                texture unit 4
//   100–119   the environment                                      texture units 5–8
// Vertex attributes: 0–3 below, 4 tangent, 5 TEXCOORD_1.

#ifdef ADD_TO_SUM
// Depth and stencil decide which fragment adds before it is shaded (the pass has no discard).
layout(early_fragment_tests) in;
#endif

in vec3 worldNormal;
in vec2 uv;
in vec4 vertexColor;

layout(location = 2) uniform vec4 baseColorFactor;
layout(location = 3) uniform bool hasBaseColorTexture;
layout(location = 4) uniform bool unlit;
layout(location = 5) uniform bool alphaMask;
layout(location = 6) uniform float alphaCutoff;
layout(location = 7) uniform bool doubleSided;
layout(location = 8) uniform vec3 toLight;
layout(location = 9) uniform float ambient;
layout(location = 10) uniform float diffuse;
// Added to GL's level of detail. N jittered views sample each pixel N times, so each lookup should
// filter over its own 1/√N of the pixel (λ − ½·log2 N), not over the whole pixel: the mean of the
// views then converges to the pixel integral of the unfiltered texture, not to a pixel-blurred one.
layout(location = 11) uniform float lodBias;
// Emitted radiance (factor × strength, linear), times the emissive texture where there is one.
layout(location = 15) uniform vec3 emissive;
layout(location = 16) uniform bool hasEmissiveTexture;

#ifdef ADD_TO_SUM
// The sum holds weight · (colour − background) per view; the accumulator adds weight · background
// for all views at once, so a pixel that shows only the background costs a view nothing.
layout(location = 13) uniform vec3 background;
layout(location = 14) uniform vec4 addWeight;
#endif

layout(binding = 0) uniform sampler2D baseColorTexture;
layout(binding = 1) uniform sampler2D emissiveTexture;

#ifndef DEPTH_ONLY
layout(location = 0) out vec4 outColor;
#endif

void main() {
  vec4 base = baseColorFactor * vertexColor;
#ifdef DEPTH_ONLY
  // Alpha-masked materials only: the cut-out must not hide what is behind it.
#ifdef ALPHA_MASK
  if (hasBaseColorTexture) base *= texture(baseColorTexture, uv, lodBias);
  if (alphaMask && base.a < alphaCutoff) discard;
#endif
  return;
#else
  if (hasBaseColorTexture) base *= texture(baseColorTexture, uv, lodBias);
#ifndef ADD_TO_SUM
  // (Added views need no discard: the depth pass left no depth where a cut-out is.)
  if (alphaMask && base.a < alphaCutoff) discard;
#endif

  vec3 n = normalize(worldNormal);
  // A double-sided surface seen from behind is lit as its back: the normal faces the viewer.
  if (doubleSided && !gl_FrontFacing) n = -n;
  vec3 colour = shade(base.rgb, n, unlit, Lighting(toLight, ambient, diffuse));
  colour += hasEmissiveTexture ? emissive * texture(emissiveTexture, uv, lodBias).rgb : emissive;
#ifdef ADD_TO_SUM
  outColor = addWeight * vec4(colour - background, 1.0);
#else
  outColor = vec4(colour, 1.0);
#endif
#endif
}
