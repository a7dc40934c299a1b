// The vignetting gain (lens/LensEffects.h, Vignetting) at this fragment's pixel centre: the
// polynomial in the squared normalised radius of the pixel's place on the film, clamped at 0.
// render/VignetteGain.h sets the uniforms.
layout(location = 40) uniform vec2 vignettingAtOrigin;    // normalised position of the GL pixel corner (0, 0)
layout(location = 41) uniform vec2 vignettingPerPixel;    // and its step per pixel
layout(location = 42) uniform vec3 vignettingCoefficients;  // a1, a2, a3

float vignettingGain() {
  vec2 n = vignettingAtOrigin + vignettingPerPixel * gl_FragCoord.xy;
  float r2 = dot(n, n);
  return max(1.0 + r2 * (vignettingCoefficients.x + r2 * (vignettingCoefficients.y + r2 * vignettingCoefficients.z)), 0.0);
}
