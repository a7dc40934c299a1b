#version 450 core
// scene.vert for a narrow field of view (ScenePass says when): the clip position in double, for
// narrow_field.geom to clip. At a field of view of 1e-7 rad a vertex 10 units off the view axis
// lands 1e8 window widths away, and float's 7 digits of that position (or of the products that
// make it) leave no digit for where its edges and its interior cross the image.
#include "../common/locations.glsl"

layout(location = ATTRIBUTE_POSITION) in vec3 inPosition;
layout(location = ATTRIBUTE_NORMAL) in vec3 inNormal;
layout(location = ATTRIBUTE_UV) in vec2 inUv;
layout(location = ATTRIBUTE_COLOR) in vec4 inColor;
#ifdef MATERIAL_MAPS
layout(location = ATTRIBUTE_TANGENT) in vec4 inTangent;
layout(location = ATTRIBUTE_UV1) in vec2 inUv1;
#endif

layout(location = LOCATION_WORLD_NORMAL_FROM_MODEL) uniform mat3 worldNormalFromModel;  // inverse transpose of worldFromModel
layout(location = LOCATION_CLIP_FROM_MODEL_DOUBLE) uniform dmat4 clipFromModelDouble;
layout(location = LOCATION_SHADING_FROM_MODEL) uniform mat4 shadingFromModel;  // as in scene.vert
#ifdef MATERIAL_MAPS
layout(location = LOCATION_WORLD_TANGENT_FROM_MODEL) uniform mat3 worldTangentFromModel;  // as in scene.vert
layout(location = LOCATION_HANDEDNESS_FROM_MODEL) uniform float handednessFromModel;
#endif

out ToClip {
  dvec4 clipPosition;
  vec3 worldNormal;
  vec2 uv;
  vec4 vertexColor;
  vec3 shadingPosition;
#ifdef MATERIAL_MAPS
  vec4 worldTangent;
  vec2 uv1;
#endif
} vertex;

void main() {
  vertex.clipPosition = clipFromModelDouble * dvec4(inPosition, 1.0);
  vertex.worldNormal = worldNormalFromModel * inNormal;
  vertex.uv = inUv;
  vertex.vertexColor = inColor;
  vertex.shadingPosition = (shadingFromModel * vec4(inPosition, 1.0)).xyz;
#ifdef MATERIAL_MAPS
  vertex.worldTangent = vec4(worldTangentFromModel * inTangent.xyz, inTangent.w * handednessFromModel);
  vertex.uv1 = inUv1;
#endif
}
