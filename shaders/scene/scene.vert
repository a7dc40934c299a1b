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
#ifdef FIELD_CURVATURE
// The lecture's "curved focal plane" (see src/render/ScenePass.h, FocusWarp): the plane of focus
// of this aperture view bends with the square of the normalised radius seen from the lens centre,
// which moves the vertex by ndcShiftPerRadius2 · r².
layout(location = 11) uniform mat4 eyeFromModel;
layout(location = 12) uniform vec2 ndcShiftPerRadius2;
#endif

out vec3 worldNormal;
out vec2 uv;
out vec4 vertexColor;

void main() {
  gl_Position = clipFromModel * vec4(inPosition, 1.0);
#ifdef FIELD_CURVATURE
  vec3 eye = (eyeFromModel * vec4(inPosition, 1.0)).xyz;
  if (eye.z > 0.0) {
    float r2 = dot(eye.xy, eye.xy) / (eye.z * eye.z);
    gl_Position.xy += gl_Position.w * ndcShiftPerRadius2 * r2;
  }
#endif
  worldNormal = worldNormalFromModel * inNormal;
  uv = inUv;
  vertexColor = inColor;
}
