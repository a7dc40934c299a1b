// The view transforms: scene-referred linear RGB (already exposed) to display-referred linear RGB
// in [0, 1], which the caller then encodes as sRGB. One definition for both sides: the viewer's
// display shader includes this file as GLSL, and src/io/ToneMap.cpp compiles it as C++ with glm
// (which spells vec3, min, max and mix as GLSL does). So it keeps to what both languages read:
// float literals with an f suffix, no swizzles beyond .r .g .b, no GLSL-only built-ins.

// View transforms by number (io/ToneMap.h's ViewTransform holds the same values).
const int kViewTransformNone = 0;
const int kViewTransformPbrNeutral = 1;

// Khronos PBR Neutral (the Khronos 3D Commerce group's tone mapper, 2024), from its specification:
// colours whose largest channel stays below the start of compression (0.76 after the offset)
// come out as they went in, less a small offset that undoes the 4 % specular reflection a lit
// surface adds to its base colour, so that a product's base colour under a white light of 1 shows
// as that base colour. Above it, the largest channel is compressed towards 1 along
// 1 − d² / (peak + d − start), and the colour is desaturated towards that peak by a fraction that
// grows with the compression; both act on all channels alike, so the hue stays.
vec3 pbrNeutral(vec3 color) {
  const float startCompression = 0.8f - 0.04f;
  const float desaturation = 0.15f;
  // Negative radiance has no display; NaN-free input assumed. Above 1e30 every value maps as 1e30
  // does (to the peak): ∞ would otherwise meet 1/∞ below and make NaN, shown as black.
  color = clamp(color, vec3(0.0f), vec3(1e30f));
  float x = min(color.r, min(color.g, color.b));
  // The offset: 0.04 for colours with every channel ≥ 0.08, a quadratic toe below (x − 6.25x²,
  // which meets 0.04 at x = 0.08 with the same slope of 0), so that black stays black.
  float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
  color -= offset;
  float peak = max(color.r, max(color.g, color.b));
  if (peak < startCompression) return color;
  const float d = 1.0f - startCompression;
  float newPeak = 1.0f - d * d / (peak + d - startCompression);
  color *= newPeak / peak;
  float g = 1.0f - 1.0f / (desaturation * (peak - newPeak) + 1.0f);
  return mix(color, newPeak * vec3(1.0f), g);
}

// Exposed linear RGB to display-referred linear RGB in [0, 1] by the transform numbered
// `transform`: none clips at 1 (each channel on its own: bright colours turn towards white or
// yellow at the clip); pbr-neutral compresses.
vec3 viewTransformed(vec3 color, int transform) {
  if (transform == kViewTransformPbrNeutral) return min(pbrNeutral(color), vec3(1.0f));
  return clamp(color, vec3(0.0f), vec3(1.0f));
}
