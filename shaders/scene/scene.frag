#version 450 core
// Variants (render/ScenePass.h): none, a plain view; DEPTH_ONLY (+ ALPHA_MASK), the depth pass of
// a view added into a sum; ADD_TO_SUM, its colour pass, which adds where depth is EQUAL;
// ALPHA_BLEND, the surfaces of alphaMode BLEND, blended `over` a plain view (ScenePass::drawBlended).
#include "../common/material_maps.glsl"
// The environment's lookups, for the image-light term: only in the ENVIRONMENT variant, built for
// scenes that have one (ScenePass::selectPrograms), so a scene without pays nothing for them.
#ifdef ENVIRONMENT
#include "../common/environment_textures.glsl"
#endif

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
#ifdef ALPHA_BLEND
// Depth is tested, not written, and a blend material has no discard: test before shading.
layout(early_fragment_tests) in;
#endif

in vec3 worldNormal;
in vec2 uv;
in vec4 vertexColor;
in vec3 shadingPosition;  // scene.vert: the point relative to the view's shading origin
#ifdef MATERIAL_MAPS
in vec4 worldTangent;  // xyz, w: handedness (mirrored with the instance); zero without tangents
in vec2 uv1;
#endif

layout(location = 2) uniform vec4 baseColorFactor;
layout(location = 3) uniform bool hasBaseColorTexture;
layout(location = 4) uniform bool unlit;
layout(location = 5) uniform bool alphaMask;
layout(location = 6) uniform float alphaCutoff;
layout(location = 7) uniform bool doubleSided;
// Radiance of the uniform surround (Lighting::ambient). Locations 8 and 10 (the former light) are free.
layout(location = 9) uniform float ambient;
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

// Normal map and texture coordinates (locations 80–99; 80–81 are scene.vert's tangent transform),
// in the MATERIAL_MAPS variant only (materials with a normal map, TEXCOORD_1 or a uv transform).
// Each texture slot samples TEXCOORD_<texCoord> through its KHR_texture_transform: its uv is
// <slot>Uv() in either variant (the plain variant's is TEXCOORD_0 as it is), e.g. for the
// metallic-roughness and occlusion textures metallicRoughnessUv() and occlusionUv().
#ifdef MATERIAL_MAPS
layout(location = 82) uniform bool hasNormalTexture;
layout(location = 83) uniform float normalScale;
layout(location = 84) uniform int normalTexCoord;
layout(location = 85) uniform mat3 normalUvFromTexCoord;
layout(location = 86) uniform int baseColorTexCoord;
layout(location = 87) uniform mat3 baseColorUvFromTexCoord;
layout(location = 88) uniform int emissiveTexCoord;
layout(location = 89) uniform mat3 emissiveUvFromTexCoord;
layout(location = 90) uniform int metallicRoughnessTexCoord;
layout(location = 91) uniform mat3 metallicRoughnessUvFromTexCoord;
layout(location = 92) uniform int occlusionTexCoord;
layout(location = 93) uniform mat3 occlusionUvFromTexCoord;
layout(binding = 4) uniform sampler2D normalTexture;  // linear (GL_RGBA8)
vec2 baseColorUv() { return slotUv(uv, uv1, baseColorTexCoord, baseColorUvFromTexCoord); }
vec2 emissiveUv() { return slotUv(uv, uv1, emissiveTexCoord, emissiveUvFromTexCoord); }
vec2 metallicRoughnessUv() { return slotUv(uv, uv1, metallicRoughnessTexCoord, metallicRoughnessUvFromTexCoord); }
vec2 occlusionUv() { return slotUv(uv, uv1, occlusionTexCoord, occlusionUvFromTexCoord); }
#else
vec2 baseColorUv() { return uv; }
vec2 emissiveUv() { return uv; }
vec2 metallicRoughnessUv() { return uv; }
vec2 occlusionUv() { return uv; }
#endif
// glTF metallic-roughness and KHR_lights_punctual (docs/materials.md; render/ScenePass.cpp sets them).
// The shading origin is this view's eye for a perspective view; a parallel view has no eye, its
// direction toward the viewer is `towardViewer` and the origin a point near the scene.
layout(location = 21) uniform vec3 towardViewer;
layout(location = 22) uniform bool parallelView;
layout(location = 23) uniform float metallicFactor;
layout(location = 24) uniform float roughnessFactor;
layout(location = 25) uniform bool hasMetallicRoughnessTexture;
layout(location = 26) uniform bool hasOcclusionTexture;
layout(location = 27) uniform float occlusionStrength;
layout(location = 28) uniform int lightCount;
// ScenePass compiles the scene's light count in (a loop of known length costs llvmpipe less);
// other users of this shader get the uniform.
#ifndef LIGHT_COUNT
#define LIGHT_COUNT lightCount
#endif
// Up to kMaxShadingLights (scene/ShadingLights.h) lights, positions relative to the shading origin.
layout(location = 32) uniform vec4 lightPositionRange[8];   // xyz position, w range (0: none)
layout(location = 40) uniform vec4 lightDirectionType[8];   // xyz the way it shines, w LightType
layout(location = 48) uniform vec3 lightIntensity[8];       // colour × lux or candela
layout(location = 56) uniform vec2 lightSpot[8];            // spotScaleOffset
layout(binding = 2) uniform sampler2D metallicRoughnessTexture;  // linear: G roughness, B metallic
layout(binding = 3) uniform sampler2D occlusionTexture;          // linear: R
layout(binding = 9) uniform sampler2D dfgTable;                  // RGB32F, kDfgSize², bilinear, clamped
vec3 dfgTexel(int x, int y) { return texelFetch(dfgTable, ivec2(x, y), 0).rgb; }
#include "../common/dfg_filtered.glsl"
#include "../common/brdf.glsl"

// Punctual lights plus the surround, as the ray caster's shadeAlong computes them.
vec3 shadeLit(vec3 base, vec3 n) {
  Surface s;
  s.baseColor = base;
  s.metallic = metallicFactor;
  s.perceptualRoughness = roughnessFactor;
  s.occlusion = 1.0;
#ifdef MATERIAL_MAPS
  // (Only materials with these maps use this variant: llvmpipe would sample them in the plain
  // program too, for every pixel, even where no material has them.)
  if (hasMetallicRoughnessTexture) {
    vec4 mr = texture(metallicRoughnessTexture, metallicRoughnessUv(), lodBias);
    s.perceptualRoughness *= mr.g;
    s.metallic *= mr.b;
  }
  if (hasOcclusionTexture) s.occlusion = 1.0 + occlusionStrength * (texture(occlusionTexture, occlusionUv(), lodBias).r - 1.0);
#endif
  s.n = n;
  s.v = parallelView ? towardViewer : normalize(-shadingPosition);
  vec3 colour = vec3(0.0);
  for (int i = 0; i < LIGHT_COUNT; ++i) {
    Light light;
    light.type = int(lightDirectionType[i].w);
    light.intensity = lightIntensity[i];
    light.position = lightPositionRange[i].xyz;
    light.direction = lightDirectionType[i].xyz;
    light.range = lightPositionRange[i].w;
    light.spotScale = lightSpot[i].x;
    light.spotOffset = lightSpot[i].y;
    colour += punctualRadiance(s, light, shadingPosition);
  }
  // Light from all around: the environment, prefiltered (environment.glsl), or the uniform surround.
  vec3 ambientDiffuse = vec3(ambient);
  vec3 ambientSpecular = vec3(ambient);
#ifdef ENVIRONMENT
  EnvironmentParams e = environmentParams();
  ambientDiffuse = environmentDiffuse(e, s.n);
  ambientSpecular = environmentSpecular(e, specularDominantDirection(s.n, s.v, s.perceptualRoughness), s.perceptualRoughness);
#endif
  colour += imageLightRadiance(s, ambientDiffuse, ambientSpecular, dfgFiltered(dot(s.n, s.v), s.perceptualRoughness));
  return colour;
}

#ifndef DEPTH_ONLY
layout(location = 0) out vec4 outColor;
#endif

void main() {
  vec4 base = baseColorFactor * vertexColor;
#ifdef DEPTH_ONLY
  // Alpha-masked materials only: the cut-out must not hide what is behind it.
#ifdef ALPHA_MASK
  if (hasBaseColorTexture) base *= texture(baseColorTexture, baseColorUv(), lodBias);
  if (alphaMask && base.a < alphaCutoff) discard;
#endif
  return;
#else
  if (hasBaseColorTexture) base *= texture(baseColorTexture, baseColorUv(), lodBias);
#ifndef ADD_TO_SUM
  // (Added views need no discard: the depth pass left no depth where a cut-out is.)
  if (alphaMask && base.a < alphaCutoff) discard;
#endif

  vec3 n = normalize(worldNormal);
#ifdef MATERIAL_MAPS
  if (hasNormalTexture) {
    const vec3 texel = texture(normalTexture, slotUv(uv, uv1, normalTexCoord, normalUvFromTexCoord), lodBias).rgb;
    n = mappedNormal(worldNormal, worldTangent.xyz, worldTangent.w, texel, normalScale);
  }
#endif
  // A double-sided surface seen from behind is lit as its back: the normal faces the viewer
  // (with a normal map, the whole frame turns: t, b and n, as the Sample Viewer does).
  if (doubleSided && !gl_FrontFacing) n = -n;
  vec3 colour = unlit ? base.rgb : shadeLit(base.rgb, n);
  colour += hasEmissiveTexture ? emissive * texture(emissiveTexture, emissiveUv(), lodBias).rgb : emissive;
#ifdef ADD_TO_SUM
  outColor = addWeight * vec4(colour - background, 1.0);
#elif defined(ALPHA_BLEND)
  // Straight alpha (factor × texture × vertex colour), blended SRC_ALPHA, ONE_MINUS_SRC_ALPHA:
  // the whole shaded colour, emission included, as the Khronos Sample Viewer. Alpha blends ONE,
  // ONE_MINUS_SRC_ALPHA, so the view's alpha stays its coverage. Clamped: a float target's blend
  // factors are not.
  outColor = vec4(colour, clamp(base.a, 0.0, 1.0));
#else
  outColor = vec4(colour, 1.0);
#endif
#endif
}
