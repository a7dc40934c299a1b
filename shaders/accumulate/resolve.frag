#version 450 core
// The image is the mean of the aperture views: each channel's sum over the weight it received.
// With the lens gather (gather_lens.frag) the weights differ per pixel and are summed beside the
// colours; otherwise they are the same for every pixel and come as a uniform. With VIGNETTING the
// mean is multiplied by the lens's relative illumination here, the last pass of the frame.
layout(binding = 0) uniform sampler2D sum;
#ifdef PER_PIXEL_WEIGHT
layout(binding = 1) uniform sampler2D weight;
#else
layout(location = 0) uniform vec4 inverseWeight;
#endif
#ifdef VIGNETTING
#include "../common/vignetting.glsl"
#endif
layout(location = 0) out vec4 mean;

void main() {
#ifdef PER_PIXEL_WEIGHT
  vec4 w = texelFetch(weight, ivec2(gl_FragCoord.xy), 0);
  mean = texelFetch(sum, ivec2(gl_FragCoord.xy), 0) / max(w, vec4(1e-30));
#else
  mean = texelFetch(sum, ivec2(gl_FragCoord.xy), 0) * inverseWeight;
#endif
#ifdef VIGNETTING
  mean.rgb *= vignettingGain();
#endif
}
