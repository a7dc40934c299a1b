#version 450 core
// The image is the mean of the aperture views.
layout(binding = 0) uniform sampler2D sum;
layout(location = 0) uniform float inverseCount;
layout(location = 0) out vec4 mean;

void main() {
  mean = texelFetch(sum, ivec2(gl_FragCoord.xy), 0) * inverseCount;
}
