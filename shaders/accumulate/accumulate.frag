#version 450 core
// Adds a batch of aperture views into the running sum (blending ONE, ONE into an RGBA32F target).
// The lecture: "compute color along every deflected ray, average the results" — the sum here,
// the division in resolve.frag. Views are rendered into the layers of an array texture and summed
// a batch at a time, so that the scene passes of a batch need not wait for one another.
// Each view has a weight per channel: 1 for a full view; with axial chromatic aberration each
// aperture point gives three views, each focused for one colour and adding only that colour.
layout(binding = 0) uniform sampler2DArray views;
layout(location = 0) uniform int viewCount;
layout(location = 1) uniform vec4 weights[8];
layout(location = 0) out vec4 sum;

void main() {
  vec4 total = vec4(0.0);
  for (int i = 0; i < viewCount; ++i) total += weights[i] * texelFetch(views, ivec3(gl_FragCoord.xy, i), 0);
  sum = total;
}
