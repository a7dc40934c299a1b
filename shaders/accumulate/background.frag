#version 450 core
// Added views (render/Accumulator.h): the background's share of a batch of views, weight ·
// background summed over the batch, added to every pixel of the sum in one pass (blending ONE, ONE).
layout(location = 0) uniform vec4 colour;
layout(location = 0) out vec4 sum;

void main() { sum = colour; }
