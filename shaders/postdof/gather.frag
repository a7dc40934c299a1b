#version 450 core
// The real-time engines' depth of field, for comparison only: one pass over the pinhole colour and
// depth. Each pixel gathers `tapCount` neighbours on a disk as wide as the largest circle of
// confusion; a neighbour contributes when its own circle reaches this pixel (scatter-as-gather),
// weighted by 1 / its circle's area. It knows only the visible surface at each pixel, so what a
// near occluder hides stays hidden: the lecture's partial obscuration is what it gets wrong.
layout(binding = 0) uniform sampler2D colorTexture;
layout(binding = 1) uniform sampler2D cocTexture;  // r: circle-of-confusion radius in pixels
layout(location = 0) uniform int tapCount;
layout(location = 1) uniform float maxRadiusPx;
layout(location = 0) out vec4 outColor;

const float kGoldenAngle = 2.39996323;

void main() {
  ivec2 size = textureSize(colorTexture, 0);
  vec2 here = gl_FragCoord.xy;
  vec3 sum = vec3(0.0);
  float weights = 0.0;
  for (int i = 0; i < tapCount; ++i) {
    // Vogel's spiral: evenly spread taps over the disk.
    float r = maxRadiusPx * sqrt((float(i) + 0.5) / float(tapCount));
    float a = float(i) * kGoldenAngle;
    ivec2 p = clamp(ivec2(here + r * vec2(cos(a), sin(a))), ivec2(0), size - 1);
    float coc = max(texelFetch(cocTexture, p, 0).r, 0.5);
    if (coc + 0.5 >= r) {
      float w = 1.0 / (coc * coc);
      sum += w * texelFetch(colorTexture, p, 0).rgb;
      weights += w;
    }
  }
  vec3 center = texelFetch(colorTexture, ivec2(here), 0).rgb;
  outColor = vec4(weights > 0.0 ? sum / weights : center, 1.0);
}
