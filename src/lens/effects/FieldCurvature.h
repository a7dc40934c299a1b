#pragma once
// Field curvature: its model and its module (LensEffectModule.h, kFieldCurvatureModule in
// FieldCurvature.cpp).
namespace lenslab {

// Field curvature, the lecture's "curved focal plane": the surface in sharp focus bends toward the
// lens away from the image centre. Its inverse distance at normalised radius r is
//   1/z_f(r) = 1/z_f + curvature · r²        (the Petzval surface's r² sag, in inverse distance)
struct FieldCurvature {
  double inverseFocusPerRadius2 = 0.0;  // 1/world unit per unit r²
  bool isZero() const { return inverseFocusPerRadius2 == 0.0; }
};

}  // namespace lenslab
