// Image-based lighting: lookups into an equirectangular environment and its prefiltered maps
// (scene/Environment.h says how they are made). One definition for both renderers: the scene
// shader includes this file as GLSL, and src/scene/EnvironmentLookup.cpp compiles it as C++ with
// glm inside a class that supplies environmentTexel. So it keeps to what both languages read:
// float literals with an f suffix, no swizzles, no GLSL-only built-ins, no texture filtering by
// the GPU (its bilinear weights have 8 bits on some hardware): every tap is a texel fetch and the
// weights are computed here, so that both sides return the same value.
//
// The includer defines, before including this file:
//   vec3 environmentTexel(int map, int x, int y, int layer)
// the texel at column x, row y (row 0 the top) of map kEnvironmentBackground (the source image,
// layer 0), kEnvironmentSpecular (layer l − 1 holds roughness level l ≥ 1) or kEnvironmentDiffuse.
//
// Convention: u = 0.5 is the direction −Z (what a default camera looks at), u grows towards +X
// (u = 0.75), u = 0 and 1 meet at +Z; v = 0 is +Y (the top row), v = 1 is −Y. A texel (x, y) of a
// W × H map covers u in [x, x + 1] / W, v in [y, y + 1] / H.

const int kEnvironmentBackground = 0;
const int kEnvironmentSpecular = 1;
const int kEnvironmentDiffuse = 2;
const float kEnvironmentPi = 3.14159265358979f;
// The smallest perceptual roughness the shading uses (brdf.glsl's kMinPerceptualRoughness): level 0,
// the source image, stands for it, and the levels are spaced from it to 1, so that a near-mirror
// reads level 0 alone instead of a blend with a rough level.
const float kEnvironmentMinRoughness = 0.045f;

struct EnvironmentParams {
  vec2 rotation;       // cos, sin of the environment's rotation about world +Y
  float intensity;     // multiplies every lookup
  ivec2 backgroundSize;
  ivec2 specularSize;  // every level ≥ 1 has this size
  ivec2 diffuseSize;
  int specularLevels;  // roughness levels including level 0 (the background itself), ≥ 2
};

// World direction (need not be unit) to (u, v). The environment turned by θ about +Y shows at
// world direction d what the unturned one has at R_y(−θ)·d.
vec2 environmentUv(EnvironmentParams p, vec3 d) {
  float x = p.rotation.x * d.x - p.rotation.y * d.z;
  float z = p.rotation.y * d.x + p.rotation.x * d.z;
  float y = d.y;
  // Straight up or down every column is the pole; GLSL leaves atan(0, 0) undefined.
  float u = x == 0.0f && z == 0.0f ? 0.5f : 0.5f + atan(x, -z) / (2.0f * kEnvironmentPi);
  // atan of the horizontal length over y, not acos(y): as accurate near the poles as elsewhere.
  float v = atan(sqrt(x * x + z * z), y) / kEnvironmentPi;
  return vec2(u, v);
}

// Columns wrap (the seam at u = 0/1), rows clamp (the poles).
int environmentColumn(int x, int width) {
  if (x < 0) return x + width;
  if (x >= width) return x - width;
  return x;
}

vec3 environmentBilinear(int map, int layer, ivec2 size, vec2 uv) {
  float x = uv.x * float(size.x) - 0.5f;
  float y = uv.y * float(size.y) - 0.5f;
  float fx = floor(x);
  float fy = floor(y);
  float tx = x - fx;
  float ty = y - fy;
  int x0 = environmentColumn(int(fx), size.x);
  int x1 = environmentColumn(int(fx) + 1, size.x);
  int y0 = clamp(int(fy), 0, size.y - 1);
  int y1 = clamp(int(fy) + 1, 0, size.y - 1);
  vec3 top = mix(environmentTexel(map, x0, y0, layer), environmentTexel(map, x1, y0, layer), tx);
  vec3 bottom = mix(environmentTexel(map, x0, y1, layer), environmentTexel(map, x1, y1, layer), tx);
  return mix(top, bottom, ty);
}

// Radiance seen straight along `d`, × intensity: the background.
vec3 environmentBackground(EnvironmentParams p, vec3 d) {
  return p.intensity * environmentBilinear(kEnvironmentBackground, 0, p.backgroundSize, environmentUv(p, d));
}

// Irradiance / π on a surface with normal `n`, × intensity: what a white Lambertian surface shows.
vec3 environmentDiffuse(EnvironmentParams p, vec3 n) {
  return p.intensity * environmentBilinear(kEnvironmentDiffuse, 0, p.diffuseSize, environmentUv(p, n));
}

vec3 environmentLevel(EnvironmentParams p, int level, vec2 uv) {
  if (level == 0) return environmentBilinear(kEnvironmentBackground, 0, p.backgroundSize, uv);
  return environmentBilinear(kEnvironmentSpecular, level - 1, p.specularSize, uv);
}

// Radiance around the reflected direction `r` prefiltered by GGX of this perceptual roughness
// (up to kEnvironmentMinRoughness the mirror … 1), × intensity: linear between the two nearest
// levels. Level l has roughness r_min + (1 − r_min)·l / (levels − 1).
vec3 environmentSpecular(EnvironmentParams p, vec3 r, float perceptualRoughness) {
  vec2 uv = environmentUv(p, r);
  float spaced = (perceptualRoughness - kEnvironmentMinRoughness) / (1.0f - kEnvironmentMinRoughness);
  float level = clamp(spaced, 0.0f, 1.0f) * float(p.specularLevels - 1);
  int l0 = min(int(floor(level)), p.specularLevels - 2);
  float t = level - float(l0);
  return p.intensity * mix(environmentLevel(p, l0, uv), environmentLevel(p, l0 + 1, uv), t);
}
