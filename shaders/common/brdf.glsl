// glTF 2.0's metallic-roughness BRDF (the specification's Appendix B) and KHR_lights_punctual, for
// both renderers. One definition: scene.frag includes this file as GLSL, and src/scene/Brdf.cpp
// compiles it as C++ with glm (which spells vec2, vec3, dot, cross, mix, clamp as GLSL does). So it keeps
// to what both languages read: float literals with an f suffix, no swizzles, no `out` parameters,
// no struct constructors (callers build the structs), no GLSL-only built-ins.
// The includer defines `vec3 dfgTexel(int x, int y)` first: texel (x, y) of the DFG table
// (kDfgSize² texels; x: n·v = x / (kDfgSize − 1), y: perceptual roughness y / (kDfgSize − 1);
// see src/scene/Brdf.h).

const float kPi = 3.14159265358979f;
// Roughness is clamped from below: at α = 0 the GGX distribution is a delta (a mirror) that
// neither renderer can sample (the rasterizer evaluates a point light's highlight once per
// pixel view, the ray caster once per ray), and α² underflows in D's denominator long before.
// 0.045 (α ≈ 0.002) is Filament's floor for float precision.
const float kMinPerceptualRoughness = 0.045f;
const int kDfgSize = 32;

// KHR_lights_punctual's types, as numbered in scene/Scene.h's LightType.
const int kLightDirectional = 0;
const int kLightPoint = 1;
const int kLightSpot = 2;

// What the shading needs of a surface point.
struct Surface {
  vec3 baseColor;             // linear RGB: factor × texture × vertex colour
  float metallic;             // [0, 1]
  float perceptualRoughness;  // [0, 1]; the GGX α is its square
  float occlusion;            // [0, 1]: 1 + strength · (texture − 1); applies to image light only
  vec3 n;                     // unit shading normal, toward the viewer's side of the surface
  vec3 v;                     // unit, toward the eye of this view (the ray caster: −ray direction)
};

// A punctual light, with positions relative to the same origin as the shaded point's.
struct Light {
  int type;          // kLightDirectional, kLightPoint, kLightSpot
  vec3 intensity;    // colour × intensity: lux (directional) or candela (point, spot)
  vec3 position;     // point and spot
  vec3 direction;    // unit, the way the light shines (directional and spot)
  float range;       // > 0: the extension's smooth window to 0 at this distance; 0: unbounded
  float spotScale;   // the spot's cone as lightAngleScale and lightAngleOffset (spotScaleOffset)
  float spotOffset;
};

// The spot cone's falloff factors, as the extension gives them: the attenuation is
// clamp(cos θ · scale + offset, 0, 1)², 1 inside the inner cone, 0 outside the outer one.
vec2 spotScaleOffset(float innerConeAngleRadians, float outerConeAngleRadians) {
  float cosOuter = cos(outerConeAngleRadians);
  float scale = 1.0f / max(0.001f, cos(innerConeAngleRadians) - cosOuter);
  return vec2(scale, -cosOuter * scale);
}

float alphaFromPerceptual(float perceptualRoughness) {
  float r = clamp(perceptualRoughness, kMinPerceptualRoughness, 1.0f);
  return r * r;
}

// Trowbridge-Reitz (GGX) normal distribution, with its denominator nh²(α² − 1) + 1 written as
// |n × h|² + nh²α²: near the peak (nh → 1, small α) 1 − nh² cancels to rounding noise, which
// the cross product's length does not (Filament does the same).
float distributionGgx(float nh, float sinSquared, float alpha) {
  float a2 = alpha * alpha;
  float f = sinSquared + nh * nh * a2;
  return a2 / (kPi * f * f);
}

// Height-correlated Smith visibility, G / (4 |n·l| |n·v|). The sum is ≥ n·l·α > 0 for n·l > 0.
float visibilitySmithGgx(float nl, float nv, float alpha) {
  float a2 = alpha * alpha;
  float gv = nl * sqrt(nv * nv * (1.0f - a2) + a2);
  float gl = nv * sqrt(nl * nl * (1.0f - a2) + a2);
  float sum = gv + gl;
  return sum > 0.0f ? 0.5f / sum : 0.0f;
}

vec3 fresnelSchlick(vec3 f0, float vh) {
  float m = clamp(1.0f - vh, 0.0f, 1.0f);
  float m2 = m * m;
  return f0 + (vec3(1.0f) - f0) * (m2 * m2 * m);
}

vec3 specularF0(Surface s) { return mix(vec3(0.04f), s.baseColor, s.metallic); }
vec3 diffuseColor(Surface s) { return s.baseColor * (1.0f - s.metallic); }

// Unit vector from point p toward the light; zero where the light sits at p.
vec3 towardLight(Light light, vec3 p) {
  if (light.type == kLightDirectional) return -light.direction;
  vec3 d = light.position - p;
  float len = length(d);
  return len > 0.0f ? d / len : vec3(0.0f);
}

// Colour × illuminance (lux) on a plane at p facing the light: a directional light's own; a point
// or spot light's candela / d², times the recommended range window clamp(1 − (d/range)⁴, 0, 1)
// and the spot's cone. d² overflowing to ∞ gives 0; a light at p gives 0.
vec3 illuminanceFacingLight(Light light, vec3 p) {
  if (light.type == kLightDirectional) return light.intensity;
  vec3 d = light.position - p;
  float d2 = dot(d, d);
  if (!(d2 > 0.0f)) return vec3(0.0f);
  float attenuation = 1.0f / d2;
  if (light.range > 0.0f) {
    float r2 = d2 / (light.range * light.range);
    attenuation *= clamp(1.0f - r2 * r2, 0.0f, 1.0f);
  }
  if (light.type == kLightSpot) {
    float cd = dot(light.direction, -d) / sqrt(d2);
    float cone = clamp(cd * light.spotScale + light.spotOffset, 0.0f, 1.0f);
    attenuation *= cone * cone;
  }
  return light.intensity * attenuation;
}

// Radiance toward v from one punctual light at point p: (f_diffuse + f_specular) · E · n·l, with
// f_diffuse = (1 − F) c_diff / π and f_specular = F D V (Appendix B). No occlusion: the occlusion
// map stands for light from the surround that the surface's own detail hides.
vec3 punctualRadiance(Surface s, Light light, vec3 p) {
  vec3 l = towardLight(light, p);
  float nl = dot(s.n, l);
  if (!(nl > 0.0f)) return vec3(0.0f);
  // n·v ≤ 0 at silhouettes (an interpolated normal turned away): treated as grazing.
  float nv = clamp(dot(s.n, s.v), 0.0f, 1.0f);
  vec3 halfway = l + s.v;
  float halfwayLength = length(halfway);
  vec3 h = halfwayLength > 0.0f ? halfway / halfwayLength : s.n;  // l = −v: no half vector
  float nh = clamp(dot(s.n, h), 0.0f, 1.0f);
  float vh = clamp(dot(s.v, h), 0.0f, 1.0f);
  float alpha = alphaFromPerceptual(s.perceptualRoughness);
  vec3 f = fresnelSchlick(specularF0(s), vh);
  vec3 diffuse = (vec3(1.0f) - f) * diffuseColor(s) * (1.0f / kPi);
  vec3 nxh = cross(s.n, h);
  vec3 specular = f * (distributionGgx(nh, dot(nxh, nxh), alpha) * visibilitySmithGgx(nl, nv, alpha));
  return (diffuse + specular) * illuminanceFacingLight(light, p) * nl;
}

// The DFG table (split sum: specular albedo F0 · x + y, diffuse weight z) at n·v and perceptual
// roughness, bilinear between texels. The texels sit on the edges of the domain (texel i at
// i / (size − 1)), so n·v 1 and roughness 1 read their own values rather than a clamped neighbour's.
vec3 dfgLookup(float nv, float perceptualRoughness) {
  float last = float(kDfgSize - 1);
  float x = clamp(nv, 0.0f, 1.0f) * last;
  float y = clamp(perceptualRoughness, 0.0f, 1.0f) * last;
  int x0 = min(int(x), kDfgSize - 2);
  int y0 = min(int(y), kDfgSize - 2);
  float fx = x - float(x0);
  float fy = y - float(y0);
  vec3 bottom = mix(dfgTexel(x0, y0), dfgTexel(x0 + 1, y0), fx);
  vec3 top = mix(dfgTexel(x0, y0 + 1), dfgTexel(x0 + 1, y0 + 1), fx);
  return mix(bottom, top, fy);
}

// The direction to read the prefiltered specular radiance along: the reflected direction, leaned
// towards the normal as roughness grows. The prefiltered lobe is centred on its direction with the
// view along the normal; the true GGX lobe at an oblique view leans towards the normal (its
// off-specular peak). The lean is Frostbite's fit (Lagarde and de Rousiers 2014, "Moving Frostbite
// to PBR", the specular dominant direction): lerp(n, r, s(√s + α)), s = 1 − α.
vec3 specularDominantDirection(vec3 n, vec3 v, float perceptualRoughness) {
  vec3 r = 2.0f * dot(n, v) * n - v;  // reflect(−v, n)
  float alpha = alphaFromPerceptual(perceptualRoughness);
  float smoothness = 1.0f - alpha;
  return normalize(mix(n, r, smoothness * (sqrt(smoothness) + alpha)));
}

// Radiance toward v from light all around (the uniform ambient, or an environment): the split
// sum. `diffuseRadiance` is the cosine-weighted mean radiance about n; `specularRadiance` the
// radiance prefiltered for this roughness about the reflected direction; `dfg` = dfgLookup(n·v,
// roughness). Each lobe is the integral of punctualRadiance's own lobe under uniform light: the
// specular albedo E = F0·dfg.x + dfg.y; the diffuse lobe (1 − F(v·h)) c_diff / π, with
// 1 − F = (1 − F0)(1 − (1 − v·h)⁵), integrates to (1 − F0) c_diff · dfg.z. The sum is not 1 for
// a white dielectric: glTF's BRDF does not conserve energy (it loses light at grazing angles and
// gains some on rough surfaces), and the image light shows what its punctual lights show. Times
// the occlusion.
vec3 imageLightRadiance(Surface s, vec3 diffuseRadiance, vec3 specularRadiance, vec3 dfg) {
  vec3 f0 = specularF0(s);
  vec3 specularAlbedo = f0 * dfg.x + vec3(dfg.y);
  vec3 diffuse = (vec3(1.0f) - f0) * dfg.z * diffuseColor(s) * diffuseRadiance;
  return s.occlusion * (diffuse + specularAlbedo * specularRadiance);
}
