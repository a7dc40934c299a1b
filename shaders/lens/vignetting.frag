#version 450 core
// Vignetting: the lens's relative illumination, a polynomial in the squared normalised radius of
// the pixel's place on the film (lens/LensEffects.h, Vignetting), multiplies every channel of the
// finished image. The pixel's place is its centre in the output image's window, in normalised
// coordinates: distorted ones when the lens pass ran, since the output image is the film.
// Alpha (the pixel's coverage) is not light and is kept.
layout(binding = 0) uniform sampler2D image;
layout(location = 0) uniform vec2 normalisedAtOrigin;  // the GL pixel corner (0, 0)
layout(location = 1) uniform vec2 normalisedPerPixel;
layout(location = 2) uniform vec3 coefficients;        // a1, a2, a3
layout(location = 0) out vec4 color;

void main() {
  vec2 n = normalisedAtOrigin + normalisedPerPixel * gl_FragCoord.xy;
  float r2 = dot(n, n);
  float gain = max(1.0 + r2 * (coefficients.x + r2 * (coefficients.y + r2 * coefficients.z)), 0.0);
  vec4 texel = texelFetch(image, ivec2(gl_FragCoord.xy), 0);
  color = vec4(texel.rgb * gain, texel.a);
}
