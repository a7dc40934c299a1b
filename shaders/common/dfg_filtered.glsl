// brdf.glsl's dfgLookup as one filtered texture lookup, for GLSL only (the includer declares
// `sampler2D dfgTable`, the RG32F table with GL_LINEAR filtering and GL_CLAMP_TO_EDGE): GL's
// bilinear filter of a clamped float texture at (n·v, roughness) places texel centres at
// (i + ½)/size and weighs the four around as dfgLookup does, in one fetch instead of four
// (BrdfGlsl.* compares it with the C++ dfgLookup).
vec2 dfgFiltered(float nv, float perceptualRoughness) {
  return texture(dfgTable, vec2(clamp(nv, 0.0, 1.0), clamp(perceptualRoughness, 0.0, 1.0))).rg;
}
