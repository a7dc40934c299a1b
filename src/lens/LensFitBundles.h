#pragma once
// The measurements lens/LensFit fits its knobs to: bundles of real rays traced backward from film
// points, centre to corner, through the lens, per channel wavelength. Each bundle says where its
// film point's blur centre lies in the scene, at what depth the point is sharp, how much light
// reaches it (with the rims, and with the stop alone: the cat's eye), and the blur no thin lens
// has. Kept apart from the fit so that what is measured and what is fitted to it read separately.
// Pure math (GLM + std), no GL.
#include "lens/LensFit.h"
#include "lens/LensPrescription.h"

#include <glm/glm.hpp>

#include <array>
#include <string>
#include <vector>

namespace lenslab {

class ExitPupil;

// What the rays traced backward from one film point do in the scene. Each ray's transverse
// position at depth Z in front of the entrance pupil is a + b·Z (mm; b the ray's slope), so the
// bundle is a set of lines; where they come closest (least squares across the axis) is the scene
// point the film point sees sharply.
struct LensFitBundle {
  double share = 0.0;  // relative illumination: the mean sample weight
  glm::dvec2 meanA{0.0}, meanB{0.0};
  double inverseFocusPerMm = 0.0;
  double rmsAngle = 0.0;  // RMS of the rays' angular spread about their centre at that depth
};

// The bundle of film point `filmMm` through `pupil`, n × n samples, lines measured from the
// entrance pupil at z = entrancePupilZ.
LensFitBundle traceLensFitBundle(const ExitPupil& pupil, glm::dvec2 filmMm, double entrancePupilZ, int n);

// The bundles of `fieldSamples` film points from the centre out to the sensor's corner.
struct LensFitField {
  bool dispersion = false;
  std::vector<int> channels;                          // green (1) first; red 0 and blue 2 with dispersion
  std::vector<double> heights;                        // film heights, mm, centre first
  std::array<std::vector<LensFitBundle>, 3> bundles;  // per channel, per height; shares relative to the axis's
  std::vector<double> catsEye;                        // green's share with the rims over with the stop alone
  std::string why;                                    // not empty: no ray reaches some film point
  int size() const { return static_cast<int>(heights.size()); }
};

// Traces the field for the film at `filmZ` (lens coordinates, mm), the stop opened to `stopMm`,
// lines measured from the entrance pupil at `entrancePupilZ`.
LensFitField traceLensFitField(const LensPrescription& lens, const LensFitSettings& s, double filmZ, double stopMm,
                               double entrancePupilZ);

}  // namespace lenslab
