#pragma once
// What `lenslab lens` reports of a prescription, for a sensor and a focus distance: first-order
// values, the field of view, distortion against field with a fitted Brown-Conrady k1 k2 k3 (and an
// equidistant fit for a fisheye), relative illumination (the cat's eye and the cos⁴ law), axial
// and lateral colour, and RMS spot sizes, all from real rays. Pure math (GLM + std), no GL.
#include "lens/LensPrescription.h"
#include "lens/ParaxialLens.h"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace lenslab {

struct LensAnalysisOptions {
  glm::dvec2 sensorMm{36.0, 24.0};
  double focusDistanceMm = 0.0;   // from the film; 0 or inf: infinity
  std::optional<double> fNumber;  // the stop closed to this paraxial f-number; open when not given
  int fieldSamples = 11;          // 0 … the half diagonal
  int pupilSamples = 48;          // across the pupil's bounding square, per axis
};

struct FieldSample {
  double fieldFraction = 0.0;         // of the sensor's half diagonal
  double imageHeightMm = 0.0;         // on the film
  double fieldAngleDegrees = 0.0;     // of the chief ray in the scene
  double distortionPercent = 0.0;     // against a rectilinear lens of the paraxial focal length
  double relativeIllumination = 0.0;  // irradiance over the axis's: vignetting × cos⁴ × pupil changes
};

struct LensReport {
  FirstOrder firstOrder;  // at infinity focus, stop as given
  double stopDiameterMm = 0.0;
  double filmDistanceMm = 0.0;         // last vertex → film, for the focus distance
  double workingFNumber = 0.0;         // 1 / (2 sin θ') of the paraxial marginal ray at the focus distance
  double magnification = 0.0;          // paraxial, image over object (0 at infinity)
  glm::dvec3 fieldOfViewDegrees{0.0};  // horizontal, vertical, diagonal: twice the chief rays' angles
  std::vector<FieldSample> field;
  glm::dvec3 brownK{0.0};  // k1 k2 k3 fitted to r_d = r_u (1 + k1 r_u² + k2 r_u⁴ + k3 r_u⁶), r in units of f
  double brownRmsErrorPercent = 0.0;  // of the fit, relative to the image height
  bool fisheye = false;               // half-diagonal field ≥ 60°
  double equidistantFocalMm = 0.0;    // h = f_e·θ fitted (fisheye only)
  double equidistantRmsErrorPercent = 0.0;
  bool dispersion = false;       // the file gives Abbe numbers
  double axialColourMm = 0.0;    // back focus at F (486 nm) minus at C (656 nm)
  double lateralColourMm = 0.0;  // chief-ray height at F minus at C, at the half diagonal
  glm::dvec3 rmsSpotMm{0.0};     // at 0, 0.5 and 1.0 of the half diagonal
};

// Refuses (one line naming the lens) where no chief ray reaches a point of the field.
LensReport analyseLens(const LensPrescription& lens, const LensAnalysisOptions& options);

}  // namespace lenslab
