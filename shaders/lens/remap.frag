#version 450 core
// The lens pass: "points are distorted geometrically from the true perspective position". Each
// output pixel looks up, in a table computed on the CPU (Newton's method in double precision, once
// per lens), the true perspective position whose distorted image it is, and samples the
// overscanned undistorted render there, bilinearly. With lateral colour each channel has its own
// table: red and blue are magnified about the principal point relative to green.
layout(binding = 0) uniform sampler2D image;
layout(binding = 1) uniform sampler2D greenMap;
#ifdef LATERAL_COLOUR
layout(binding = 2) uniform sampler2D redMap;
layout(binding = 3) uniform sampler2D blueMap;
#endif
layout(location = 0) out vec4 color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 green = texture(image, texelFetch(greenMap, pixel, 0).xy);
#ifdef LATERAL_COLOUR
  float red = texture(image, texelFetch(redMap, pixel, 0).xy).r;
  float blue = texture(image, texelFetch(blueMap, pixel, 0).xy).b;
  color = vec4(red, green.g, blue, green.a);
#else
  color = green;
#endif
}
