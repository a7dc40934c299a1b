// Texture coordinates and normal maps, one definition for both renderers: shaders/scene/scene.frag
// includes this file as GLSL, and src/scene/MaterialMaps.cpp compiles it as C++ with glm (which
// spells vec2, vec3, vec4, mat3, dot, cross, length and normalize as GLSL does). So it keeps to
// what both languages read: float literals with an f suffix, no swizzles (vec3(v) takes a vec4's
// xyz in both), no GLSL-only built-ins.

// The uv a texture reference samples: its TEXCOORD set (0 or 1) through its KHR_texture_transform
// (uv' = uvFromTexCoord · (u, v, 1); Scene.h's TextureRef).
vec2 slotUv(vec2 uv0, vec2 uv1, int texCoord, mat3 uvFromTexCoord) {
  return vec2(uvFromTexCoord * vec3(texCoord == 1 ? uv1 : uv0, 1.0f));
}

// The shading normal with a normal map, as the glTF specification and the Khronos glTF Sample
// Viewer compute it: the texel (0…1 per channel, linear) mapped to −1…1, its x and y scaled by
// normalTexture.scale, normalised, then carried out of tangent space by the frame (t, b, n):
//   n' = normalize(t·m.x + b·m.y + n·m.z),  b = w · cross(n, t)  (glTF's bitangent).
// `normal` and `tangent` are the vertex normal and tangent (world, xyz) interpolated over the
// triangle; each is normalised here, and the frame is not re-orthogonalised (the Sample Viewer
// normalises its interpolated t, b and n and uses them as they are). `handedness` is the tangent's
// w times the sign of the instance's determinant (a mirroring transform mirrors the bitangent too).
// A missing or degenerate tangent (zero, or along the normal), or a texel that maps to no
// direction, leaves the geometric normal.
vec3 mappedNormal(vec3 normal, vec3 tangent, float handedness, vec3 texel, float scale) {
  vec3 n = normalize(normal);
  float tangentLength = length(tangent);
  if (!(tangentLength > 1e-20f)) return n;
  vec3 t = tangent / tangentLength;
  vec3 b = cross(n, t);
  float bitangentLength = length(b);
  if (!(bitangentLength > 1e-6f)) return n;
  b = (handedness < 0.0f ? -1.0f : 1.0f) * b / bitangentLength;
  vec3 m = texel * 2.0f - vec3(1.0f);
  m = vec3(m.x * scale, m.y * scale, m.z);
  float mLength = length(m);
  if (!(mLength > 1e-20f)) return n;
  m = m / mLength;
  vec3 mapped = t * m.x + b * m.y + n * m.z;
  float mappedLength = length(mapped);
  return mappedLength > 1e-20f ? mapped / mappedLength : n;
}
