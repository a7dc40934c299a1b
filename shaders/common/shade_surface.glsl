// A glTF material assembled at one surface point, for both renderers: what the material's inputs
// make of the surface (base colour × vertex colour × texture, the alpha cut-out, the shading normal
// with its normal map and double-sided flip, metallic-roughness and occlusion) and the radiance it
// sends toward the viewer (the punctual lights, the environment or the uniform surround, emission),
// with the alpha a blend material is composited with. One definition: scene.frag includes this
// file as GLSL, and src/scene/ShadeSurface.cpp compiles it as C++ with glm (docs/materials.md).
// So it keeps to what both languages read: float literals with an f suffix, no swizzles, no `out`
// parameters, no struct constructors, no GLSL-only built-ins.
//
// Each renderer fetches the inputs its own way: the rasterizer from its textures and uniforms, the
// ray caster from its TextureSampler at the hit. The includer defines, after brdf.glsl and
// material_maps.glsl and before this file:
//   vec4 baseColorTexel()             the base colour texture at the point (linear RGBA)
//   vec4 metallicRoughnessTexel()     the metallic-roughness texture (linear: G roughness, B metallic)
//   float occlusionTexel()            the occlusion texture's R (linear)
//   vec3 emissiveTexel()              the emissive texture (linear RGB)
//   vec3 normalTexel()                the normal map (linear RGB, 0…1 per channel)
//   int shadingLightCount()           the punctual lights (brdf.glsl's Light), positions relative
//   Light shadingLight(int i)         to the same origin as SurfacePoint.position
//   float ambientRadiance()           the uniform surround's radiance (Lighting::ambient)
//   bool environmentLit()             whether an environment lights the scene instead
//   vec3 environmentDiffuseAt(vec3 n)                      environment.glsl's environmentDiffuse
//   vec3 environmentSpecularAt(vec3 r, float roughness)    environment.glsl's environmentSpecular
//   vec3 dfgAt(float nv, float perceptualRoughness)        brdf.glsl's dfgLookup (or the filtered one)
// A texture's function is called only where the material has that texture, the environment's only
// where environmentLit().
//
// SurfaceMaterial, SurfacePoint and ShadedSurface: the C++ declares the same structs itself
// (ShadeSurface.h, with defaults and the same field names), so its compilation skips these.
#ifndef SHADE_SURFACE_STRUCTS_DECLARED
// What the shading takes of a glTF material (scene/ShadeSurface.h's surfaceMaterial makes it).
struct SurfaceMaterial {
  vec4 baseColorFactor;              // linear RGBA
  bool hasBaseColorTexture;
  bool alphaMask;                    // alphaMode MASK: cut out where alpha < alphaCutoff
  float alphaCutoff;
  bool doubleSided;                  // seen from behind, lit as its back
  bool unlit;                        // KHR_materials_unlit: the base colour as it is
  float metallicFactor;
  float roughnessFactor;             // perceptual
  bool hasMetallicRoughnessTexture;
  bool hasOcclusionTexture;
  float occlusionStrength;
  bool normalMapped;                 // a normal texture, and tangents to carry it
  float normalScale;
  vec3 emissive;                     // emissiveFactor × strength, linear
  bool hasEmissiveTexture;
};

// The geometry at the point, interpolated over its triangle.
struct SurfacePoint {
  vec4 vertexColor;   // COLOR_0 (white without)
  vec3 normal;        // the vertex normal in world axes, not normalised
  vec3 tangent;       // the vertex tangent's xyz in world axes (for a normal map)
  float handedness;   // the tangent's w × the sign of the instance's determinant
  bool frontFacing;   // the side the triangle's winding faces, as GL decides it
  vec3 position;      // relative to the lights' origin
  vec3 towardViewer;  // unit: toward the eye of this view (−ray direction)
};

// What the point sends toward the viewer.
struct ShadedSurface {
  vec3 radiance;  // emission included
  vec3 normal;    // the shading normal (unit, world): toward the viewer's side where double-sided
  float alpha;    // base colour alpha clamped to [0, 1]: what a blend material composites with
};
#endif

// Base colour: factor × vertex colour × texture (straight alpha).
vec4 surfaceBaseColor(SurfaceMaterial m, vec4 vertexColor) {
  vec4 base = m.baseColorFactor * vertexColor;
  if (m.hasBaseColorTexture) base *= baseColorTexel();
  return base;
}

// Whether alphaMode MASK cuts the point out: nothing is drawn there, and what is behind shows.
bool alphaCutOut(SurfaceMaterial m, vec4 base) { return m.alphaMask && base.a < m.alphaCutoff; }

// The normal the point is shaded with: the vertex normal, or the normal map's turned by the
// tangent frame (material_maps.glsl); a double-sided surface seen from behind is lit as its back,
// so the normal turns to the viewer (with a normal map the whole frame turns: t, b and n, as the
// Khronos Sample Viewer does).
vec3 shadingNormal(SurfaceMaterial m, SurfacePoint p) {
  vec3 n = normalize(p.normal);
  if (m.normalMapped) n = mappedNormal(p.normal, p.tangent, p.handedness, normalTexel(), m.normalScale);
  if (m.doubleSided && !p.frontFacing) n = -n;
  return n;
}

// brdf.glsl lit by the punctual lights plus the light from all around.
vec3 litRadiance(SurfaceMaterial m, vec3 baseColor, vec3 n, SurfacePoint p) {
  Surface s;
  s.baseColor = baseColor;
  s.metallic = m.metallicFactor;
  s.perceptualRoughness = m.roughnessFactor;
  s.occlusion = 1.0f;
  if (m.hasMetallicRoughnessTexture) {
    vec4 mr = metallicRoughnessTexel();
    s.perceptualRoughness *= mr.g;
    s.metallic *= mr.b;
  }
  // The occlusion map darkens only the light from all around (brdf.glsl's imageLightRadiance).
  if (m.hasOcclusionTexture) s.occlusion = 1.0f + m.occlusionStrength * (occlusionTexel() - 1.0f);
  s.n = n;
  s.v = p.towardViewer;
  vec3 colour = vec3(0.0f);
  for (int i = 0; i < shadingLightCount(); ++i) colour += punctualRadiance(s, shadingLight(i), p.position);
  // Light from all around: the environment, prefiltered (environment.glsl), or the uniform surround.
  vec3 ambientDiffuse = vec3(ambientRadiance());
  vec3 ambientSpecular = vec3(ambientRadiance());
  if (environmentLit()) {
    ambientDiffuse = environmentDiffuseAt(s.n);
    ambientSpecular = environmentSpecularAt(specularDominantDirection(s.n, s.v, s.perceptualRoughness), s.perceptualRoughness);
  }
  colour += imageLightRadiance(s, ambientDiffuse, ambientSpecular, dfgAt(dot(s.n, s.v), s.perceptualRoughness));
  return colour;
}

// The point shaded, from its base colour (surfaceBaseColor, not cut out).
ShadedSurface shadeSurface(SurfaceMaterial m, vec4 base, SurfacePoint p) {
  ShadedSurface shaded;
  shaded.normal = shadingNormal(m, p);
  vec3 baseColor = vec3(base);
  shaded.radiance = m.unlit ? baseColor : litRadiance(m, baseColor, shaded.normal, p);
  // Emission is added to the shaded colour, lit or unlit.
  shaded.radiance += m.hasEmissiveTexture ? m.emissive * emissiveTexel() : m.emissive;
  // Straight alpha, clamped: GL does not clamp a float target's blend factors.
  shaded.alpha = clamp(base.a, 0.0f, 1.0f);
  return shaded;
}
