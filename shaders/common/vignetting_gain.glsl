// The lens's relative illumination (lens/effects/Vignetting.h) as a polynomial in the squared
// normalised radius r² of a point's place on the film:
//   gain = 1 + a1 r² + a2 r⁴ + a3 r⁶
// One text for both languages: the shaders include it (common/vignetting.glsl), and
// src/lens/effects/Vignetting.cpp includes it as C++ with VIGNETTING_REAL defined as double, the
// way scene/Brdf.cpp compiles common/brdf.glsl. So the fit (lens/LensFit.cpp), the camera checks
// and the image's gain all evaluate the same polynomial. Only what both languages share is
// written here: scalars, arithmetic and the conditional operator.
#ifndef VIGNETTING_REAL
#define VIGNETTING_REAL float
#endif

// The polynomial itself, in Horner's form, unclamped (where it reaches 0 is checked on this).
VIGNETTING_REAL vignettingPolynomial(VIGNETTING_REAL r2, VIGNETTING_REAL a1, VIGNETTING_REAL a2, VIGNETTING_REAL a3) {
  return 1.0 + r2 * (a1 + r2 * (a2 + r2 * a3));
}

// The gain a pixel is given: the polynomial clamped at 0, and 0 for NaN too (the comparison is
// false), so that no pixel is given a negative or undefined light.
VIGNETTING_REAL vignettingGainAt(VIGNETTING_REAL r2, VIGNETTING_REAL a1, VIGNETTING_REAL a2, VIGNETTING_REAL a3) {
  VIGNETTING_REAL g = vignettingPolynomial(r2, a1, a2, a3);
  return g > 0.0 ? g : 0.0;
}
