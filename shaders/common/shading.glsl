// lenslab's shading model, which the CPU ray caster reproduces exactly (src/scene/Scene.h):
//   unlit: colour = base + emission
//   lit:   colour = base * (ambient + diffuse * max(0, dot(n, toLight))) + emission
// All in linear light; sRGB textures are decoded by the sampler (GL_SRGB8_ALPHA8).

struct Lighting {
  vec3 toLight;
  float ambient;
  float diffuse;
};

vec3 shade(vec3 base, vec3 normal, bool unlit, Lighting light) {
  if (unlit) return base;
  float lambert = max(0.0, dot(normal, light.toLight));
  return base * (light.ambient + light.diffuse * lambert);
}
