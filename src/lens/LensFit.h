#pragma once
// The real-time camera that comes closest to a real lens: the lecture's thin lens at the entrance
// pupil, with the knobs lenslab's rasterizer has (radial distortion, lateral and axial colour,
// field curvature, the barrel's cat's eye, a radial illumination gain), each fitted to bundles of
// real rays traced backward from the film through the lens (lens/ExitPupil) so that the fitted
// image lands where the real one does, not merely so that first-order values match.
//
// What each knob is fitted to, for film points from the centre out to the sensor's corner:
//   focal length F and k1 k2 k3  — least squares of the image height h = F·x_u(1 + k1 x_u² + …)
//                                  against x_u, the tangent of the bundle's mean direction
//                                  (where the blur's centre is, at the focus distance);
//   focus and field curvature    — each bundle's best focus in the scene: the depth at which the
//                                  traced rays come closest together (least squares across the
//                                  axis), as 1/z = 1/z_f + c·x_u², fitted over the field;
//   axial colour                 — the same best focus per channel wavelength, on the axis;
//   lateral colour               — each channel's image height against green's;
//   cat's eye                    — the barrel (distance, radius) whose overlap with the aperture
//                                  matches the share of the pupil the rims leave, per field;
//   illumination                 — the rest of the relative illumination (cos⁴, the pupil's own
//                                  changes), 1 + a1 r² + a2 r⁴ + a3 r⁶ over the image radius.
// What no knob holds is the residual blur of the lens's aberrations (spherical, coma,
// astigmatism): the thin lens images a point as a point. It is reported beside the fit's errors.
// Pure math (GLM + std), no GL.
#include "lens/LensBarrel.h"
#include "lens/LensEffects.h"
#include "lens/LensPrescription.h"

#include <glm/glm.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

struct LensFitSettings {
  glm::dvec2 sensorMm{36.0, 24.0};
  double focusDistanceMm = INFINITY;  // from the entrance pupil (as LensCamera's); +inf: infinity
  std::optional<double> fNumber;      // paraxial; the design's full opening when not given
  int fieldSamples = 24;              // film points from the centre to the corner
  int pupilSamples = 48;              // per axis of each exit-pupil box
};

// How far the fitted camera is from the traced lens, per effect, on the film (µm) or as a share.
struct LensFitError {
  double positionUm = 0.0;        // worst |fitted − traced| image height (distortion, F)
  double lateralColourUm = 0.0;   // worst channel image-height error (0 without dispersion)
  double focusBlurUm = 0.0;       // worst blur diameter from the fitted focus's error (field curvature, axial colour)
  double illumination = 0.0;      // worst |fitted − traced| relative illumination
  double aberrationBlurUm = 0.0;  // worst RMS radius of a traced bundle at its best focus: no knob holds it
  // The worst image-point error a user sees, µm: the larger of position + lateral colour and
  // half the focus blur + the aberrations' RMS radius.
  double worstUm() const;
};

struct FittedLensSample {
  double imageHeightMm = 0.0;      // film point, from the centre
  double undistorted = 0.0;        // x_u: tangent of the bundle's mean direction
  double inverseFocusPerMm = 0.0;  // best focus, 1/mm from the entrance pupil (0: infinity)
  double relativeIllumination = 0.0;
  double catsEye = 0.0;    // the share of the pupil the rims leave (RI with rims / without)
  double rmsBlurUm = 0.0;  // at the best focus, on the film
};

struct FittedLens {
  // Whether a rectilinear camera can hold the lens at all; `why` says what stops it (a fisheye's
  // field reaching 90°, a fitted distortion that folds inside the image).
  bool usable = false;
  std::string why;

  double focalLengthMm = 0.0;            // F: the normalised image coordinate is the film height over F
  double entrancePupilDiameterMm = 0.0;  // the thin lens's aperture
  double inverseFocusPerMm = 0.0;        // the fitted focus on the axis, 1/mm from the entrance pupil
  Distortion distortion;                 // k1 k2 k3
  double lateralRed = 0.0, lateralBlue = 0.0;
  double inverseFocusShiftRedPerMm = 0.0, inverseFocusShiftBluePerMm = 0.0;
  double fieldCurvaturePerMm = 0.0;                     // 1/mm per x_u²
  double barrelDistanceMm = 0.0, barrelRadiusMm = 0.0;  // 0 radius: no barrel
  glm::dvec3 illuminationGain{0.0};                     // a1 a2 a3 over the distorted normalised radius²

  LensFitError error;
  std::vector<FittedLensSample> samples;  // green's, centre to corner
};

// Refuses (one line naming the lens) an f-number faster than the design's. A sensor whose corners
// lie past the lens's image circle gives an unusable fit (`why` says so): only the exact trace
// renders that image.
FittedLens fitLens(const LensPrescription& lens, const LensFitSettings& settings);

// The fitted lens's effects in world units (`worldPerMm` world units per mm: metres 1e-3).
LensEffects fittedEffects(const FittedLens& fit, double worldPerMm);
LensBarrel fittedBarrel(const FittedLens& fit, double worldPerMm);

}  // namespace lenslab
