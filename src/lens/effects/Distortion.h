#pragma once
// Distortion: its model (the lecture's "points are distorted geometrically from the true
// perspective position") and its module (LensEffectModule.h, kDistortionModule in Distortion.cpp).
// Normalised image coordinates as in lens/LensEffects.h: lenslab's (x, y) = (X/Z, Y/Z), y up; the
// coefficients mean what they mean in OpenCV (y down), the conversion is inside.
#include <glm/glm.hpp>

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
  double alpha = 0.0, beta = 0.0, gamma = 0.0;              // the lecture's series

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
std::optional<FoldOver> findFoldOver(const Distortion& distortion, glm::dvec2 distortedMin, glm::dvec2 distortedMax);

}  // namespace lenslab
