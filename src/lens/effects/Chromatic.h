#pragma once
// Chromatic aberration, lateral and axial: its model and its module (LensEffectModule.h,
// kChromaticModule in Chromatic.cpp).
#include <array>

namespace lenslab {

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

}  // namespace lenslab
