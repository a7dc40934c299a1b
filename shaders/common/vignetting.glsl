// The vignetting gain (lens/effects/Vignetting.h) at this fragment's pixel centre: the
// polynomial in the squared normalised radius of the pixel's place on the film, clamped at 0
// (common/vignetting_gain.glsl, the same text the C++ evaluates). render/VignetteGain.h sets the
// uniforms.
#include "locations.glsl"
#include "vignetting_gain.glsl"
layout(location = LOCATION_VIGNETTING_AT_ORIGIN) uniform vec2 vignettingAtOrigin;  // normalised position of the GL pixel corner (0, 0)
layout(location = LOCATION_VIGNETTING_PER_PIXEL) uniform vec2 vignettingPerPixel;  // and its step per pixel
layout(location = LOCATION_VIGNETTING_COEFFICIENTS) uniform vec3 vignettingCoefficients;  // a1, a2, a3

float vignettingGain() {
  vec2 n = vignettingAtOrigin + vignettingPerPixel * gl_FragCoord.xy;
  return vignettingGainAt(dot(n, n), vignettingCoefficients.x, vignettingCoefficients.y, vignettingCoefficients.z);
}
