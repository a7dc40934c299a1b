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
#ifdef CELL_FILL
// The cell filter (cell_filter.frag): what the views' cells saw beyond what each view shows is
// each pixel's shortfall of coverage, filled with the farthest surface the views saw there.
layout(binding = 2) uniform sampler2D weight;
layout(binding = 3) uniform sampler2D behind;
layout(binding = 4) uniform sampler2D holes;
#endif
#ifdef VIGNETTING
#include "../common/vignetting.glsl"
#endif
layout(location = 0) out vec4 mean;

void main() {
#ifdef PER_PIXEL_WEIGHT
  vec4 w = texelFetch(weight, ivec2(gl_FragCoord.xy), 0);
  mean = texelFetch(sum, ivec2(gl_FragCoord.xy), 0) / max(w, vec4(1e-30));
#elif defined(CELL_FILL)
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 covered = texelFetch(weight, p, 0), hole = texelFetch(holes, p, 0);
  vec4 b = texelFetch(behind, p, 0), s = texelFetch(sum, p, 0);
  vec4 own = s / max(covered, vec4(1e-30));  // the views' own mean, where nothing was seen behind
  vec4 far = vec4(b.a > 0.0 ? b.rgb / b.a : own.rgb, own.a);  // alpha fills as the pixel's own mean
  mean = (s + hole * far) / max(covered + hole, vec4(1e-30));
#else
  mean = texelFetch(sum, ivec2(gl_FragCoord.xy), 0) * inverseWeight;
#endif
#ifdef VIGNETTING
  mean.rgb *= vignettingGain();
#endif
}
