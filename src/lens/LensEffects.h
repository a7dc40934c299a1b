#pragma once
// The lecture's last part: real lenses are not pinholes. "Points are distorted geometrically from
// the true perspective position"; "points also become more blurred as they approach the edge of
// the image"; "the focal length of a lens is a function of the wavelength of the light".
//
// All three act in normalised image coordinates: the point where a ray from the PRP crosses a
// view plane at unit distance, measured from the principal point (the foot of the PRP on the view
// plane). In lenslab's eye frame that is (x, y) = (X/Z, Y/Z), x right and y UP. OpenCV's normalised
// coordinates are the same with y DOWN; the distortion below converts so that its coefficients
// mean exactly what they mean in OpenCV (a calibration's k1, k2, p1, p2, k3 can be used as given).
#include <glm/glm.hpp>

#include <array>
#include <optional>

namespace lenslab {

// Brown–Conrady distortion in OpenCV's convention and coefficient order, from the true perspective
// position (x, y) to the distorted one (OpenCV frame, y down):
//   r² = x² + y²,  radial = 1 + k1 r² + k2 r⁴ + k3 r⁶
//   x_d = x·radial + 2 p1 x y + p2 (r² + 2x²)
//   y_d = y·radial + p1 (r² + 2y²) + 2 p2 x y
// plus the lecture's series ρ = ρ'(1 + αρ' + βρ'² + γρ'³): ρ' is the true perspective radius and ρ
// the distorted one (the lecture's step "convert points to 2D spherical coordinates based in the
// middle of the image", then scale the radius). The slide prints the series without the leading 1,
// which would shrink the image centre to a point; lenslab reads it with the 1, so that the centre
// keeps its perspective scale and α = β = γ = 0 is no distortion. β is OpenCV's k1; α and γ add the
// odd powers: radial = 1 + α r + (k1 + β) r² + γ r³ + k2 r⁴ + k3 r⁶.
struct Distortion {
  double k1 = 0.0, k2 = 0.0, p1 = 0.0, p2 = 0.0, k3 = 0.0;  // OpenCV
  double alpha = 0.0, beta = 0.0, gamma = 0.0;             // the lecture's series

  bool isZero() const;
  // From the true perspective position to the distorted one; both in lenslab's frame (y up).
  glm::dvec2 distort(glm::dvec2 undistorted) const;
  // ∂ distorted / ∂ undistorted (columns: ∂/∂x, ∂/∂y), lenslab's frame.
  glm::dmat2 jacobian(glm::dvec2 undistorted) const;
  // The true perspective position whose distorted image is `distorted`: Newton's method in double
  // precision from `guess`, until the step is below 1e-13 (relative). Empty when it does not
  // converge in 64 steps or the Jacobian is singular (a fold, see findFoldOver).
  std::optional<glm::dvec2> undistort(glm::dvec2 distorted, glm::dvec2 guess) const;
  std::optional<glm::dvec2> undistort(glm::dvec2 distorted) const { return undistort(distorted, distorted); }
};

// Where a distortion folds over inside a region of the distorted image: the true perspective
// position, nearest the centre, at which the Jacobian's determinant is ≤ 0 (for a radial model,
// dρ/dρ' ≤ 0) while its distorted image still lies inside `distortedMin`–`distortedMax`.
// Beyond a fold two true positions land on one pixel and the image mirrors: no post pass or ray
// caster can undo that, so cameras with a fold inside the image are refused.
struct FoldOver {
  glm::dvec2 undistorted;
  glm::dvec2 distorted;
};
std::optional<FoldOver> findFoldOver(const Distortion& distortion, glm::dvec2 distortedMin,
                                     glm::dvec2 distortedMax);

enum class Channel { Red = 0, Green = 1, Blue = 2 };

// Chromatic aberration: "different colors of light from a single point will be out-of-focus".
// Green is the reference channel (the camera's focus and magnification are green's).
struct Chromatic {
  // Lateral: red's and blue's images are magnified about the principal point by (1 + lateral)
  // relative to green's (after distortion). 0.002 moves a point 1000 px from the centre by 2 px.
  double lateralRed = 0.0;
  double lateralBlue = 0.0;
  // Axial: each channel's plane of focus, as a shift of the inverse focus distance relative to
  // green's (1/world unit). A thin lens's power 1/f changes with wavelength while the sensor stays
  // put, and 1/z_f = 1/f − 1/z_i, so the shift of 1/z_f is the shift of 1/f: it does not change
  // when the camera refocuses.
  double inverseFocusShiftRed = 0.0;
  double inverseFocusShiftBlue = 0.0;

  bool hasLateral() const { return lateralRed != 0.0 || lateralBlue != 0.0; }
  bool hasAxial() const { return inverseFocusShiftRed != 0.0 || inverseFocusShiftBlue != 0.0; }
  double lateral(Channel c) const;
  double inverseFocusShift(Channel c) const;
};

// Axial chromatic aberration of a thin lens of glass with Abbe number V = (n_d − 1)/(n_F − n_C),
// focal length f (world units) at the d line (green). With Cauchy's n(λ) = A + B/λ², the C (red,
// 656.3 nm) and F (blue, 486.1 nm) lines sit 0.301 and 0.699 of the way below and above d, so
//   1/f_red = (1/f)(1 − 0.301/V),  1/f_blue = (1/f)(1 + 0.699/V).
// Returns the inverse focus shifts {red, blue}.
std::array<double, 2> inverseFocusShiftsFromAbbe(double abbeNumber, double focalLength);

// Field curvature, the lecture's "curved focal plane": the surface in sharp focus bends toward the
// lens away from the image centre. Its inverse distance at normalised radius r is
//   1/z_f(r) = 1/z_f + curvature · r²        (the Petzval surface's r² sag, in inverse distance)
struct FieldCurvature {
  double inverseFocusPerRadius2 = 0.0;  // 1/world unit per unit r²
  bool isZero() const { return inverseFocusPerRadius2 == 0.0; }
};

// The image's relative illumination as a polynomial in the squared distorted normalised radius
// r² = x_d² + y_d² (the pixel's own normalised image position, after distortion, green's):
//   gain = 1 + a1 r² + a2 r⁴ + a3 r⁶   (Adobe's lens-profile vignette model has this form)
// It stands for what the thin lens leaves out: the cos⁴ law's fall-off and the lens's own losses,
// beyond what the barrel (lens/LensBarrel.h) clips. Every channel of the final pixel (background
// included) is multiplied by the same gain; AOVs are not.
struct Vignetting {
  double a1 = 0.0, a2 = 0.0, a3 = 0.0;
  bool isZero() const;
  double gain(double r2) const;  // the polynomial, clamped to ≥ 0
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

struct LensEffects {
  Distortion distortion;
  Chromatic chromatic;
  FieldCurvature fieldCurvature;
  Vignetting vignetting;

  bool isZero() const {
    return distortion.isZero() && !chromatic.hasLateral() && !chromatic.hasAxial() && fieldCurvature.isZero() && vignetting.isZero();
  }
  // The post pass (distortion and lateral colour, both geometric remaps of the image) is needed.
  bool needsRemap() const { return !distortion.isZero() || chromatic.hasLateral(); }
  // Green's true perspective position of the channel-`c` image point `distorted` (normalised):
  // lateral colour undone, then the distortion. Empty where Newton fails.
  std::optional<glm::dvec2> undistortChannel(Channel c, glm::dvec2 distorted, glm::dvec2 guess) const;
  // Forward: where the true perspective position lands in channel `c`'s image.
  glm::dvec2 distortChannel(Channel c, glm::dvec2 undistorted) const;
  // Inverse focus distance of channel `c` for a pixel at true perspective position `undistorted`.
  double inverseFocusShift(Channel c, glm::dvec2 undistorted) const;
};

}  // namespace lenslab
