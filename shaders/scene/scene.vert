#version 450 core
// One instance of a mesh. clipFromModel is composed on the CPU in double precision
// (clipFromWorld * worldFromModel) and only then rounded to float, so that scenes far from the
// origin keep their precision.
#include "../common/locations.glsl"

layout(location = ATTRIBUTE_POSITION) in vec3 inPosition;
layout(location = ATTRIBUTE_NORMAL) in vec3 inNormal;
layout(location = ATTRIBUTE_UV) in vec2 inUv;
layout(location = ATTRIBUTE_COLOR) in vec4 inColor;
#ifdef MATERIAL_MAPS
// The variant for materials with a normal map, TEXCOORD_1 or a uv transform (ScenePass): the
// plain one carries none of this, so a scene without them costs what it did before.
layout(location = ATTRIBUTE_TANGENT) in vec4 inTangent;  // xyz, w = ±1; zero where the mesh has none
layout(location = ATTRIBUTE_UV1) in vec2 inUv1;      // TEXCOORD_1
#endif

layout(location = LOCATION_CLIP_FROM_MODEL) uniform mat4 clipFromModel;
layout(location = LOCATION_WORLD_NORMAL_FROM_MODEL) uniform mat3 worldNormalFromModel;  // inverse transpose of worldFromModel
// World axes, origin at the view's shading origin (its eye): composed in double on the CPU, so
// that a scene far from the world origin reaches the shading with the precision it has near it.
layout(location = LOCATION_SHADING_FROM_MODEL) uniform mat4 shadingFromModel;
// Tangents lie in the surface, so they move with it: by worldFromModel's linear part (a direction
// on the surface is a difference of two surface points; glTF 2.0's mesh attribute TANGENT is such
// a direction, ∂P/∂u), not by the normal matrix, as the Khronos glTF Sample Viewer transforms them
// (its model matrix for tangents, its normal matrix for normals). Scaled to its largest entry
// near 1, as the normal matrix is.
#ifdef MATERIAL_MAPS
layout(location = LOCATION_WORLD_TANGENT_FROM_MODEL) uniform mat3 worldTangentFromModel;
// −1 where worldFromModel mirrors (negative determinant): the bitangent, w·cross(n, t), must
// mirror with the surface, and cross() of the mirrored n and t does not.
layout(location = LOCATION_HANDEDNESS_FROM_MODEL) uniform float handednessFromModel;
#endif

// Added views draw twice (depth, then colour where depth is EQUAL): both must place each vertex alike.
invariant gl_Position;

out vec3 worldNormal;
out vec2 uv;
out vec4 vertexColor;
out vec3 shadingPosition;
#ifdef MATERIAL_MAPS
out vec4 worldTangent;
out vec2 uv1;
#endif

void main() {
  gl_Position = clipFromModel * vec4(inPosition, 1.0);
  worldNormal = worldNormalFromModel * inNormal;
  uv = inUv;
  vertexColor = inColor;
  shadingPosition = (shadingFromModel * vec4(inPosition, 1.0)).xyz;
#ifdef MATERIAL_MAPS
  worldTangent = vec4(worldTangentFromModel * inTangent.xyz, inTangent.w * handednessFromModel);
  uv1 = inUv1;
#endif
}
