#version 450 core
// Adds one aperture view into the running sum (blending ONE, ONE into an RGBA32F target).
// The lecture: "compute color along every deflected ray, average the results" — the sum here,
// the division in resolve.frag.
layout(binding = 0) uniform sampler2D view;
layout(location = 0) out vec4 sum;

void main() {
  sum = texelFetch(view, ivec2(gl_FragCoord.xy), 0);
}
