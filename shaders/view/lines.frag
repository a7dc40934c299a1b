#version 450 core
// Colours are given display-encoded: the lines go straight onto the window's 8-bit framebuffer.
in vec3 vertexColor;
layout(location = 0) out vec4 fragColor;

void main() { fragColor = vec4(vertexColor, 1.0); }
