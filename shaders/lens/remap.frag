#version 450 core
// The lens pass: "points are distorted geometrically from the true perspective position". Each
// output pixel looks up, in a table computed on the CPU (Newton's method in double precision, once
// per lens), the true perspective position whose distorted image it is, and samples the
// overscanned undistorted render there (Catmull–Rom). With lateral colour each channel has its own
// table: red and blue are magnified about the principal point relative to green.
layout(binding = 0) uniform sampler2D image;
layout(binding = 1) uniform sampler2D greenMap;
#ifdef LATERAL_COLOUR
layout(binding = 2) uniform sampler2D redMap;
layout(binding = 3) uniform sampler2D blueMap;
#endif
layout(location = 0) out vec4 color;

#include "../common/catmull_rom.glsl"

// The undistorted image at texture coordinate uv (under distortion most pixels fall between texels).
vec4 catmullRom(vec2 uv) {
  ivec2 first;
  vec2 w[4];
  catmullRomTaps(uv * vec2(textureSize(image, 0)), first, w);
  ivec2 last = textureSize(image, 0) - 1;
  vec4 sum = vec4(0.0);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      sum += w[i].x * w[j].y * texelFetch(image, clamp(first + ivec2(i, j), ivec2(0), last), 0);
  return max(sum, vec4(0.0));  // Catmull–Rom overshoots a little at hard edges; light is never negative
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 green = catmullRom(texelFetch(greenMap, pixel, 0).xy);
#ifdef LATERAL_COLOUR
  float red = catmullRom(texelFetch(redMap, pixel, 0).xy).r;
  float blue = catmullRom(texelFetch(blueMap, pixel, 0).xy).b;
  color = vec4(red, green.g, blue, green.a);
#else
  color = green;
#endif
}
