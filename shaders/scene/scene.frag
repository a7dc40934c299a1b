#version 450 core
// Variants (render/ScenePass.h): none, a plain view; DEPTH_ONLY (+ ALPHA_MASK), the depth pass of
// a view added into a sum; ADD_TO_SUM, its colour pass, which adds where depth is EQUAL;
// ALPHA_BLEND, the surfaces of alphaMode BLEND, blended `over` a plain view (ScenePass::drawBlended).
#include "../common/locations.glsl"
#include "../common/material_maps.glsl"
// The environment's lookups, for the image-light term: only in the ENVIRONMENT variant, built for
// scenes that have one (ScenePass::selectPrograms), so a scene without pays nothing for them.
#ifdef ENVIRONMENT
#include "../common/environment_textures.glsl"
#endif

// Uniform locations and texture units: common/locations.glsl. Vertex attributes: 0–3 below,
// 4 tangent, 5 TEXCOORD_1.

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

layout(location = LOCATION_BASE_COLOR_FACTOR) uniform vec4 baseColorFactor;
layout(location = LOCATION_HAS_BASE_COLOR_TEXTURE) uniform bool hasBaseColorTexture;
layout(location = LOCATION_UNLIT) uniform bool unlit;
layout(location = LOCATION_ALPHA_MASK) uniform bool alphaMask;
layout(location = LOCATION_ALPHA_CUTOFF) uniform float alphaCutoff;
layout(location = LOCATION_DOUBLE_SIDED) uniform bool doubleSided;
// Radiance of the uniform surround (Lighting::ambient).
layout(location = LOCATION_AMBIENT) uniform float ambient;
// Added to GL's level of detail. N jittered views sample each pixel N times, so each lookup should
// filter over its own 1/√N of the pixel (λ − ½·log2 N), not over the whole pixel: the mean of the
// views then converges to the pixel integral of the unfiltered texture, not to a pixel-blurred one.
layout(location = LOCATION_LOD_BIAS) uniform float lodBias;
// Emitted radiance (factor × strength, linear), times the emissive texture where there is one.
layout(location = LOCATION_EMISSIVE) uniform vec3 emissive;
layout(location = LOCATION_HAS_EMISSIVE_TEXTURE) uniform bool hasEmissiveTexture;

#ifdef ADD_TO_SUM
// The sum holds weight · (colour − background) per view; the accumulator adds weight · background
// for all views at once, so a pixel that shows only the background costs a view nothing.
layout(location = LOCATION_BACKGROUND) uniform vec3 background;
layout(location = LOCATION_ADD_WEIGHT) uniform vec4 addWeight;
#endif

layout(binding = UNIT_BASE_COLOR) uniform sampler2D baseColorTexture;
layout(binding = UNIT_EMISSIVE) uniform sampler2D emissiveTexture;

// Normal map and texture coordinates (locations 80–99; 80–81 are scene.vert's tangent transform),
// in the MATERIAL_MAPS variant only (materials with a normal map, TEXCOORD_1 or a uv transform).
// Each texture slot samples TEXCOORD_<texCoord> through its KHR_texture_transform: its uv is
// <slot>Uv() in either variant (the plain variant's is TEXCOORD_0 as it is), e.g. for the
// metallic-roughness and occlusion textures metallicRoughnessUv() and occlusionUv().
#ifdef MATERIAL_MAPS
layout(location = LOCATION_HAS_NORMAL_TEXTURE) uniform bool hasNormalTexture;
layout(location = LOCATION_NORMAL_SCALE) uniform float normalScale;
layout(location = LOCATION_NORMAL_TEX_COORD) uniform int normalTexCoord;
layout(location = LOCATION_NORMAL_TEX_COORD + 1) uniform mat3 normalUvFromTexCoord;
layout(location = LOCATION_BASE_COLOR_TEX_COORD) uniform int baseColorTexCoord;
layout(location = LOCATION_BASE_COLOR_TEX_COORD + 1) uniform mat3 baseColorUvFromTexCoord;
layout(location = LOCATION_EMISSIVE_TEX_COORD) uniform int emissiveTexCoord;
layout(location = LOCATION_EMISSIVE_TEX_COORD + 1) uniform mat3 emissiveUvFromTexCoord;
layout(location = LOCATION_METALLIC_ROUGHNESS_TEX_COORD) uniform int metallicRoughnessTexCoord;
layout(location = LOCATION_METALLIC_ROUGHNESS_TEX_COORD + 1) uniform mat3 metallicRoughnessUvFromTexCoord;
layout(location = LOCATION_OCCLUSION_TEX_COORD) uniform int occlusionTexCoord;
layout(location = LOCATION_OCCLUSION_TEX_COORD + 1) uniform mat3 occlusionUvFromTexCoord;
layout(binding = UNIT_NORMAL) uniform sampler2D normalTexture;  // linear (GL_RGBA8)
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
// glTF metallic-roughness and KHR_lights_punctual (docs/materials.md; render/SceneUniforms.cpp sets them).
layout(location = LOCATION_TOWARD_VIEWER) uniform vec3 towardViewer;
layout(location = LOCATION_PARALLEL_VIEW) uniform bool parallelView;
layout(location = LOCATION_METALLIC_FACTOR) uniform float metallicFactor;
layout(location = LOCATION_ROUGHNESS_FACTOR) uniform float roughnessFactor;
layout(location = LOCATION_HAS_METALLIC_ROUGHNESS_TEXTURE) uniform bool hasMetallicRoughnessTexture;
layout(location = LOCATION_HAS_OCCLUSION_TEXTURE) uniform bool hasOcclusionTexture;
layout(location = LOCATION_OCCLUSION_STRENGTH) uniform float occlusionStrength;
layout(location = LOCATION_LIGHT_COUNT) uniform int lightCount;
// ScenePass compiles the scene's light count in (a loop of known length costs llvmpipe less);
// other users of this shader get the uniform.
#ifndef LIGHT_COUNT
#define LIGHT_COUNT lightCount
#endif
// Up to kMaxShadingLights (scene/ShadingLights.h) lights, positions relative to the shading origin.
layout(location = LOCATION_LIGHT_POSITION_RANGE) uniform vec4 lightPositionRange[MAX_SHADING_LIGHTS];  // xyz position, w range (0: none)
layout(location = LOCATION_LIGHT_DIRECTION_TYPE) uniform vec4 lightDirectionType[MAX_SHADING_LIGHTS];  // xyz the way it shines, w LightType
layout(location = LOCATION_LIGHT_INTENSITY) uniform vec3 lightIntensity[MAX_SHADING_LIGHTS];  // colour × lux or candela
layout(location = LOCATION_LIGHT_SPOT) uniform vec2 lightSpot[MAX_SHADING_LIGHTS];            // spotScaleOffset
layout(binding = UNIT_METALLIC_ROUGHNESS) uniform sampler2D metallicRoughnessTexture;  // linear: G roughness, B metallic
layout(binding = UNIT_OCCLUSION) uniform sampler2D occlusionTexture;                   // linear: R
layout(binding = UNIT_DFG) uniform sampler2D dfgTable;  // RGB32F, kDfgSize², bilinear, clamped
vec3 dfgTexel(int x, int y) { return texelFetch(dfgTable, ivec2(x, y), 0).rgb; }
#include "../common/dfg_filtered.glsl"
#include "../common/brdf.glsl"

// shade_surface.glsl's inputs, fetched the rasterizer's way: the material's textures at this
// fragment (each through its slot's uv, biased by lodBias), the lights and the surround.
vec4 baseColorTexel() { return texture(baseColorTexture, baseColorUv(), lodBias); }
vec3 emissiveTexel() { return texture(emissiveTexture, emissiveUv(), lodBias).rgb; }
#ifdef MATERIAL_MAPS
vec4 metallicRoughnessTexel() { return texture(metallicRoughnessTexture, metallicRoughnessUv(), lodBias); }
float occlusionTexel() { return texture(occlusionTexture, occlusionUv(), lodBias).r; }
vec3 normalTexel() { return texture(normalTexture, slotUv(uv, uv1, normalTexCoord, normalUvFromTexCoord), lodBias).rgb; }
#else
// The plain variant's materials have none of these maps (ScenePass's materialMaps): material()
// says so in constants, and the compiler drops the branches that would read them. (llvmpipe would
// otherwise sample them for every pixel, even where no material has them.)
vec4 metallicRoughnessTexel() { return vec4(1.0); }
float occlusionTexel() { return 1.0; }
vec3 normalTexel() { return vec3(0.5, 0.5, 1.0); }
#endif
int shadingLightCount() { return LIGHT_COUNT; }
Light shadingLight(int i) {
  Light light;
  light.type = int(lightDirectionType[i].w);
  light.intensity = lightIntensity[i];
  light.position = lightPositionRange[i].xyz;
  light.direction = lightDirectionType[i].xyz;
  light.range = lightPositionRange[i].w;
  light.spotScale = lightSpot[i].x;
  light.spotOffset = lightSpot[i].y;
  return light;
}
float ambientRadiance() { return ambient; }
#ifdef ENVIRONMENT
bool environmentLit() { return true; }
vec3 environmentDiffuseAt(vec3 n) { return environmentDiffuse(environmentParams(), n); }
vec3 environmentSpecularAt(vec3 r, float perceptualRoughness) {
  return environmentSpecular(environmentParams(), r, perceptualRoughness);
}
#else
bool environmentLit() { return false; }
vec3 environmentDiffuseAt(vec3 n) { return vec3(0.0); }
vec3 environmentSpecularAt(vec3 r, float perceptualRoughness) { return vec3(0.0); }
#endif
vec3 dfgAt(float nv, float perceptualRoughness) { return dfgFiltered(nv, perceptualRoughness); }
#include "../common/shade_surface.glsl"

// The material of the instance drawn (ScenePass sets the uniforms from scene/ShadeSurface.h's
// surfaceMaterial, the ray caster's own).
SurfaceMaterial material() {
  SurfaceMaterial m;
  m.baseColorFactor = baseColorFactor;
  m.hasBaseColorTexture = hasBaseColorTexture;
  m.alphaMask = alphaMask;
  m.alphaCutoff = alphaCutoff;
  m.doubleSided = doubleSided;
  m.unlit = unlit;
  m.metallicFactor = metallicFactor;
  m.roughnessFactor = roughnessFactor;
  m.occlusionStrength = occlusionStrength;
  m.emissive = emissive;
  m.hasEmissiveTexture = hasEmissiveTexture;
#ifdef MATERIAL_MAPS
  m.hasMetallicRoughnessTexture = hasMetallicRoughnessTexture;
  m.hasOcclusionTexture = hasOcclusionTexture;
  m.normalMapped = hasNormalTexture;
  m.normalScale = normalScale;
#else
  m.hasMetallicRoughnessTexture = false;
  m.hasOcclusionTexture = false;
  m.normalMapped = false;
  m.normalScale = 1.0;
#endif
  return m;
}

// This fragment's geometry.
SurfacePoint point() {
  SurfacePoint p;
  p.vertexColor = vertexColor;
  p.normal = worldNormal;
#ifdef MATERIAL_MAPS
  p.tangent = worldTangent.xyz;
  p.handedness = worldTangent.w;
#else
  p.tangent = vec3(0.0);
  p.handedness = 1.0;
#endif
  p.frontFacing = gl_FrontFacing;
  p.position = shadingPosition;
  // The shading origin is this view's eye for a perspective view; a parallel view has no eye, its
  // direction toward the viewer is `towardViewer` and the origin a point near the scene.
  // Scaled before normalize: in a scene 1e-30 across the squared length underflows a float to 0,
  // and normalize would give NaN (the ray caster works in double).
  vec3 eyeward = -shadingPosition;
  float largest = max(max(abs(eyeward.x), abs(eyeward.y)), abs(eyeward.z));
  p.towardViewer = parallelView ? towardViewer : largest > 0.0 ? normalize(eyeward / largest) : vec3(0.0, 0.0, 1.0);
  return p;
}

#ifndef DEPTH_ONLY
layout(location = 0) out vec4 outColor;
#endif

void main() {
  SurfaceMaterial m = material();
#ifdef DEPTH_ONLY
  // Alpha-masked materials only: the cut-out must not hide what is behind it.
#ifdef ALPHA_MASK
  if (alphaCutOut(m, surfaceBaseColor(m, vertexColor))) discard;
#endif
  return;
#else
  vec4 base = surfaceBaseColor(m, vertexColor);
#ifndef ADD_TO_SUM
  // (Added views need no discard: the depth pass left no depth where a cut-out is.)
  if (alphaCutOut(m, base)) discard;
#endif
  ShadedSurface shaded = shadeSurface(m, base, point());
#ifdef ADD_TO_SUM
  outColor = addWeight * vec4(shaded.radiance - background, 1.0);
#elif defined(ALPHA_BLEND)
  // Straight alpha (factor × texture × vertex colour), blended SRC_ALPHA, ONE_MINUS_SRC_ALPHA:
  // the whole shaded colour, emission included, as the Khronos Sample Viewer. Alpha blends ONE,
  // ONE_MINUS_SRC_ALPHA, so the view's alpha stays its coverage.
  outColor = vec4(shaded.radiance, shaded.alpha);
#else
  outColor = vec4(shaded.radiance, 1.0);
#endif
#endif
}
