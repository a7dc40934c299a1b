#pragma once
// Vignetting, the lens's relative illumination: its model, and its module (LensEffectModule.h).
//
// The image's relative illumination as a polynomial in the squared distorted normalised radius
// r² = x_d² + y_d² (the pixel's own normalised image position, after distortion, green's):
//   gain = 1 + a1 r² + a2 r⁴ + a3 r⁶   (Adobe's lens-profile vignette model has this form)
// It stands for what the thin lens leaves out: the cos⁴ law's fall-off and the lens's own losses,
// beyond what the barrel (lens/LensBarrel.h) clips. Every channel of the final pixel (background
// included) is multiplied by the same gain; AOVs are not. The polynomial is one text for C++ and
// GLSL: shaders/common/vignetting_gain.glsl.
//
// Camera file: "vignetting": {"a1", "a2", "a3"} (missing keys are 0). Path: each coefficient
// linear. Plan: a gain at the end of the frame (the resolve's variant, or a pass of its own).
#include <optional>

namespace lenslab {

struct LensEffectModule;

// The polynomial 1 + a1 r² + a2 r⁴ + a3 r⁶, unclamped: the one definition that the fit
// (lens/LensFit.cpp), the checks below and the shaders evaluate.
double vignettingPolynomial(double r2, double a1, double a2, double a3);

struct Vignetting {
  double a1 = 0.0, a2 = 0.0, a3 = 0.0;
  bool isZero() const;
  double polynomial(double r2) const { return vignettingPolynomial(r2, a1, a2, a3); }
  double gain(double r2) const;  // the polynomial, clamped to ≥ 0 (0 for NaN)
};

// Where the gain first reaches 0 (or is not a finite number) going out from the centre to squared
// radius `r2Max`: that squared radius, or empty when it stays positive all the way. A polynomial
// fitted to a real lens may turn down past the field it was fitted over; inside the image that is
// refused (validateLensEffects).
std::optional<double> vignettingZeroWithin(const Vignetting& vignetting, double r2Max);
// The largest gain from the centre out to squared radius `r2Max` (at least the centre's 1).
double vignettingLargestGain(const Vignetting& vignetting, double r2Max);
// A lens lets no part of its field see many times the light of its centre: a larger gain is a
// coefficient in the wrong units (and beyond a float's range the shader's gain would overflow).
constexpr double kMaxVignettingGain = 100.0;

extern const LensEffectModule kVignettingModule;

}  // namespace lenslab
