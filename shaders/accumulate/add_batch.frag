#version 450 core
// Added views (render/Accumulator.h): a batch of views was added into a partial sum of its own,
// weight · (colour − background) each; this pass adds that partial sum and the batch's
// weight · background to the running sum (blending ONE, ONE). Summing in two levels keeps the
// float rounding of a long sum small: each add into the running sum is a whole batch's worth.
layout(binding = 7) uniform sampler2D partial;  // unit 7: the renderer keeps sums bound on 0 to 3
layout(location = 0) uniform vec4 background;   // the batch's weight · background (alpha 0)
layout(location = 0) out vec4 sum;

void main() { sum = texelFetch(partial, ivec2(gl_FragCoord.xy), 0) + background; }
