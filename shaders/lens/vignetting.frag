#version 450 core
// Vignetting as a pass of its own, where no resolve runs last to multiply it in (one view, the
// lens remap of one view, the two-stream resolve): the finished image times the lens's relative
// illumination at each pixel's place on the film (common/vignetting.glsl). The pixel's place is
// its centre in the output image's window, in normalised coordinates: distorted ones when the lens
// pass ran, since the output image is the film. Alpha (the pixel's coverage) is not light and is kept.
#include "../common/vignetting.glsl"
layout(binding = 0) uniform sampler2D image;
layout(location = 0) out vec4 color;

void main() {
  vec4 texel = texelFetch(image, ivec2(gl_FragCoord.xy), 0);
  color = vec4(texel.rgb * vignettingGain(), texel.a);
}
