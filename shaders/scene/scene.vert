#version 450 core
// One instance of a mesh. clipFromModel is composed on the CPU in double precision
// (clipFromWorld * worldFromModel) and only then rounded to float, so that scenes far from the
// origin keep their precision.

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inColor;

layout(location = 0) uniform mat4 clipFromModel;
layout(location = 1) uniform mat3 worldNormalFromModel;  // inverse transpose of worldFromModel
// World axes, origin at the view's shading origin (its eye): composed in double on the CPU, so
// that a scene far from the world origin reaches the shading with the precision it has near it.
layout(location = 20) uniform mat4 shadingFromModel;

// Added views draw twice (depth, then colour where depth is EQUAL): both must place each vertex alike.
invariant gl_Position;

out vec3 worldNormal;
out vec2 uv;
out vec4 vertexColor;
out vec3 shadingPosition;

void main() {
  gl_Position = clipFromModel * vec4(inPosition, 1.0);
  worldNormal = worldNormalFromModel * inNormal;
  uv = inUv;
  vertexColor = inColor;
  shadingPosition = (shadingFromModel * vec4(inPosition, 1.0)).xyz;
}
