#version 450 core
#include "../common/shading.glsl"

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

layout(binding = 0) uniform sampler2D baseColorTexture;

layout(location = 0) out vec4 outColor;

void main() {
  vec4 base = baseColorFactor * vertexColor;
  if (hasBaseColorTexture) base *= texture(baseColorTexture, uv, lodBias);
  if (alphaMask && base.a < alphaCutoff) discard;

  vec3 n = normalize(worldNormal);
  // A double-sided surface seen from behind is lit as its back: the normal faces the viewer.
  if (doubleSided && !gl_FrontFacing) n = -n;
  outColor = vec4(shade(base.rgb, n, unlit, Lighting(toLight, ambient, diffuse)), 1.0);
}
