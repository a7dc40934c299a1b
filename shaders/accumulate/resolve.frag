#version 450 core
// The image is the mean of the aperture views: each channel's sum over the weight it received.
layout(binding = 0) uniform sampler2D sum;
layout(location = 0) uniform vec4 inverseWeight;
layout(location = 0) out vec4 mean;

void main() {
  mean = texelFetch(sum, ivec2(gl_FragCoord.xy), 0) * inverseWeight;
}
