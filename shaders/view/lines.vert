#version 450 core
// The outside view's diagram: world-space segments through the outside camera's clipFromWorld.
layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 color;
layout(location = 0) uniform mat4 clipFromWorld;
out vec3 vertexColor;

void main() {
  vertexColor = color;
  gl_Position = clipFromWorld * vec4(worldPosition, 1.0);
}
