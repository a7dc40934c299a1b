#pragma once
// Distortion: its model (the lecture's "points are distorted geometrically from the true
// perspective position") and its module (LensEffectModule.h, kDistortionModule in Distortion.cpp).
// Normalised image coordinates as in lens/LensEffects.h: lenslab's (x, y) = (X/Z, Y/Z), y up; the
// coefficients mean what they mean in OpenCV (y down), the conversion is inside.
#include <glm/glm.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

// Brown–Conrady distortion in OpenCV's convention and coefficient order, from the true perspective
// position (x, y) to the distorted one (OpenCV frame, y down), with OpenCV's rational and thin-prism
// terms (its CALIB_RATIONAL_MODEL and CALIB_THIN_PRISM_MODEL; COLMAP's FULL_OPENCV is the first):
//   r² = x² + y²,  radial = (1 + k1 r² + k2 r⁴ + k3 r⁶) / (1 + k4 r² + k5 r⁴ + k6 r⁶)
//   x_d = x·radial + 2 p1 x y + p2 (r² + 2x²) + s1 r² + s2 r⁴
//   y_d = y·radial + p1 (r² + 2y²) + 2 p2 x y + s3 r² + s4 r⁴
// plus the lecture's series ρ = ρ'(1 + αρ' + βρ'² + γρ'³): ρ' is the true perspective radius and ρ
// the distorted one (the lecture's step "convert points to 2D spherical coordinates based in the
// middle of the image", then scale the radius). The slide prints the series without the leading 1,
// which would shrink the image centre to a point; lenslab reads it with the 1, so that the centre
// keeps its perspective scale and α = β = γ = 0 is no distortion. β is OpenCV's k1; α and γ add the
// odd powers to the numerator: 1 + α r + (k1 + β) r² + γ r³ + k2 r⁴ + k3 r⁶.
//
// Or OpenCV's fisheye model (cv::fisheye; COLMAP's OPENCV_FISHEYE, and its RADIAL_FISHEYE and
// SIMPLE_RADIAL_FISHEYE, which keep k1, k2 or k1 alone): the distorted radius is a polynomial in
// the angle from the optical axis, θ = atan r,
//   θ_d = θ (1 + k1 θ² + k2 θ⁴ + k3 θ⁶ + k4 θ⁸),  (x_d, y_d) = (θ_d / r)·(x, y),
// so that k1 = … = k4 = 0 is the equidistant fisheye (θ_d = θ), not the pinhole. k1 … k4 hold θ's
// coefficients then and every other term is 0 (the camera reader refuses any other). The true
// perspective position (x, y) = (X/Z, Y/Z) reaches only up to θ < 90°: the image of a fisheye whose
// field reaches 90° from the axis is refused (validateLensEffects), not folded.
struct Distortion {
  double k1 = 0.0, k2 = 0.0, p1 = 0.0, p2 = 0.0, k3 = 0.0;  // OpenCV
  double k4 = 0.0, k5 = 0.0, k6 = 0.0;                      // OpenCV's rational model (the denominator)
  double s1 = 0.0, s2 = 0.0, s3 = 0.0, s4 = 0.0;            // OpenCV's thin prism
  double alpha = 0.0, beta = 0.0, gamma = 0.0;              // the lecture's series
  bool fisheye = false;                                     // OpenCV's fisheye model: k1 … k4 are θ's

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

  // Whether every term is OpenCV's standard model's (none of the lecture's α, β, γ, not the
  // fisheye): then distCoeffs() says it all.
  bool isOpenCv() const { return !fisheye && alpha == 0.0 && beta == 0.0 && gamma == 0.0; }
  // How far the fisheye's image reaches on the branch that contains the centre; empty for the
  // other models.
  struct FisheyeReach {
    double theta;            // radians from the axis: 90°, or where θ_d stops growing before it
    double distortedRadius;  // θ_d there, the largest distorted radius any ray reaches
    bool folds;              // θ_d stops growing before 90° (dθ_d/dθ reaches 0)
  };
  std::optional<FisheyeReach> fisheyeReach() const;
  // OpenCV's distCoeffs for the OpenCV terms, at the shortest of its lengths that holds them: 5
  // (k1, k2, p1, p2, k3), 8 (+ k4, k5, k6) or 12 (+ s1 … s4).
  std::vector<double> distCoeffs() const;
};

// Every coefficient, by its camera-file name, in OpenCV's distCoeffs order and then the lecture's:
// what reads, writes, interpolates and keys a Distortion walks, so that no place forgets a term.
struct DistortionTerm {
  const char* name;
  double Distortion::*value;
};
inline constexpr DistortionTerm kDistortionTerms[] = {
    {"k1", &Distortion::k1},       {"k2", &Distortion::k2},     {"p1", &Distortion::p1},      {"p2", &Distortion::p2},
    {"k3", &Distortion::k3},       {"k4", &Distortion::k4},     {"k5", &Distortion::k5},      {"k6", &Distortion::k6},
    {"s1", &Distortion::s1},       {"s2", &Distortion::s2},     {"s3", &Distortion::s3},      {"s4", &Distortion::s4},
    {"alpha", &Distortion::alpha}, {"beta", &Distortion::beta}, {"gamma", &Distortion::gamma}};
// The OpenCV terms are the first 12, in distCoeffs order.
inline constexpr std::size_t kOpenCvDistortionTerms = 12;

// The terms that are not 0, for messages: "k1 = -0.3, k4 = 0.01" ("fisheye k1 = 0.02" for the fisheye).
std::string distortionTermsText(const Distortion& distortion);

// A Distortion from OpenCV's distCoeffs: its first 12 numbers at most (a 14's tilt terms τx, τy are
// the caller's to refuse), missing ones 0.
Distortion distortionFromDistCoeffs(const std::vector<double>& coefficients);

// Where a distortion folds over inside a region of the distorted image: the true perspective
// position, nearest the centre, at which the Jacobian's determinant is ≤ 0 (for a radial model,
// dρ/dρ' ≤ 0) while its distorted image still lies inside `distortedMin`–`distortedMax`.
// Beyond a fold two true positions land on one pixel and the image mirrors: no post pass or ray
// caster can undo that, so cameras with a fold inside the image are refused. A fisheye's 90° is not
// a fold (its image ends there): validateLensEffects refuses an image that reaches it by name.
struct FoldOver {
  glm::dvec2 undistorted;
  glm::dvec2 distorted;
};
std::optional<FoldOver> findFoldOver(const Distortion& distortion, glm::dvec2 distortedMin, glm::dvec2 distortedMax);

}  // namespace lenslab
