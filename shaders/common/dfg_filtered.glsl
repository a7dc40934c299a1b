// brdf.glsl's dfgLookup as one filtered texture lookup, for GLSL only (the includer declares
// `sampler2D dfgTable`, the RGB32F table with GL_LINEAR filtering and GL_CLAMP_TO_EDGE). The table's
// texel i stands for t = i / (size − 1) (edge-aligned), while GL places texel centres at
// (i + ½)/size: t maps to (t·(size − 1) + ½)/size, where GL's bilinear filter weighs the same
// four texels as dfgLookup does, in one fetch instead of four (BrdfGlsl.* compares it with the
// C++ dfgLookup).
vec3 dfgFiltered(float nv, float perceptualRoughness) {
  // The size from the texture: this file is included before brdf.glsl's kDfgSize.
  vec2 size = vec2(textureSize(dfgTable, 0));
  vec2 t = clamp(vec2(nv, perceptualRoughness), 0.0, 1.0);
  return texture(dfgTable, (t * (size - 1.0) + 0.5) / size).rgb;
}
