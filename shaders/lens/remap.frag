#version 450 core
// The lens pass of a single view: "points are distorted geometrically from the true perspective
// position". Each output pixel looks up, in a table computed on the CPU (Newton's method in double
// precision, once per lens), the true perspective position whose distorted image it is, and
// samples the overscanned undistorted render there, bilinearly: a single view is point-sampled
// anyway, and bilinear weights never leave the range of the texels (Catmull–Rom rang at edges).
// Accumulated views take the exact route instead (accumulate/gather_lens.frag). With lateral
// colour each channel has its own table: red and blue are magnified about the principal point
// relative to green.
layout(binding = 0) uniform sampler2D image;
layout(binding = 1) uniform sampler2D greenMap;
#ifdef LATERAL_COLOUR
layout(binding = 2) uniform sampler2D redMap;
layout(binding = 3) uniform sampler2D blueMap;
#endif
layout(location = 0) out vec4 color;

// The undistorted image at texture coordinate uv, bilinear with edges clamped.
vec4 bilinear(vec2 uv) {
  vec2 p = uv * vec2(textureSize(image, 0)) - 0.5;
  ivec2 first = ivec2(floor(p));
  vec2 f = p - vec2(first);
  ivec2 last = textureSize(image, 0) - 1;
  vec4 a = texelFetch(image, clamp(first, ivec2(0), last), 0);
  vec4 b = texelFetch(image, clamp(first + ivec2(1, 0), ivec2(0), last), 0);
  vec4 c = texelFetch(image, clamp(first + ivec2(0, 1), ivec2(0), last), 0);
  vec4 d = texelFetch(image, clamp(first + ivec2(1, 1), ivec2(0), last), 0);
  return mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 green = bilinear(texelFetch(greenMap, pixel, 0).xy);
#ifdef LATERAL_COLOUR
  float red = bilinear(texelFetch(redMap, pixel, 0).xy).r;
  float blue = bilinear(texelFetch(blueMap, pixel, 0).xy).b;
  color = vec4(red, green.g, blue, green.a);
#else
  color = green;
#endif
}
