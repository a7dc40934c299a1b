#version 450 core
// Per-tile budgets (src/render/Renderer.h): the views come in two independent streams, summed
// apart. The image is their pooled mean, each pixel divided by the weight its own tile (or, with
// the lens gather, its own pixel) received — so tiles that stopped early are as unbiased as the rest.
//
// ERROR_PER_BLOCK: instead of the image, the estimated squared error of each 8 × 8 block: with
// stream means a, b of weights wA, wB, the pooled mean's variance is E[(a − b)²]·wA·wB/(wA + wB)²
// (independent streams), summed over the block's RGB values; and how many values that is.
layout(binding = 0) uniform sampler2D sumA;
layout(binding = 1) uniform sampler2D sumB;
layout(binding = 2) uniform sampler2D weightA;  // per tile (or per pixel with PER_PIXEL_WEIGHT)
layout(binding = 3) uniform sampler2D weightB;
layout(location = 0) uniform int tileSize;
layout(location = 0) out vec4 result;

void weightsAt(ivec2 p, out vec4 wA, out vec4 wB) {
#ifdef PER_PIXEL_WEIGHT
  ivec2 w = p;
#else
  ivec2 w = p / tileSize;
#endif
  wA = texelFetch(weightA, w, 0);
  wB = texelFetch(weightB, w, 0);
}

#ifdef ERROR_PER_BLOCK
// One pixel's squared error (summed over RGB) and how many values it has from both streams.
vec2 pixelError(ivec2 p) {
  vec4 wA, wB;
  weightsAt(p, wA, wB);
  vec3 a = texelFetch(sumA, p, 0).rgb / max(wA.rgb, vec3(1e-30));
  vec3 b = texelFetch(sumB, p, 0).rgb / max(wB.rgb, vec3(1e-30));
  vec3 both = step(vec3(1e-30), wA.rgb) * step(vec3(1e-30), wB.rgb);  // values both streams reached
  vec3 d = a - b;
  return vec2(dot(both, d * d * wA.rgb * wB.rgb / max((wA.rgb + wB.rgb) * (wA.rgb + wB.rgb), vec3(1e-30))),
              both.r + both.g + both.b);
}
#endif

void main() {
#ifdef ERROR_PER_BLOCK
  // One fragment per 8 × 8 block of the image: the CPU adds a tile's blocks.
  ivec2 size = textureSize(sumA, 0);
  ivec2 origin = ivec2(gl_FragCoord.xy) * 8;
  vec2 total = vec2(0.0);
  for (int y = origin.y; y < min(origin.y + 8, size.y); ++y)
    for (int x = origin.x; x < min(origin.x + 8, size.x); ++x) total += pixelError(ivec2(x, y));
  result = vec4(total, 0.0, 0.0);
#else
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 wA, wB;
  weightsAt(p, wA, wB);
  result = (texelFetch(sumA, p, 0) + texelFetch(sumB, p, 0)) / max(wA + wB, vec4(1e-30));
#endif
}
