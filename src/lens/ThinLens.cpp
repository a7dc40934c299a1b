#include "lens/ThinLens.h"

#include <cmath>
#include <limits>

namespace lenslab {

double imageDistanceFromInverse(double f, double inverseFocus) { return f / (1.0 - f * inverseFocus); }

double magnification(double f, double inverseFocus) { return f * inverseFocus / (1.0 - f * inverseFocus); }

double cocDiameterOnFocusPlane(double apertureRadius, double inverseFocus, double distance) {
  if (inverseFocus == 0.0) return std::numeric_limits<double>::infinity();  // the plane is at infinity
  return 2.0 * apertureRadius * std::abs(inverseFocus - 1.0 / distance) / inverseFocus;
}

double cocDiameterOnSensor(double apertureRadius, double f, double inverseFocus, double distance) {
  return 2.0 * apertureRadius * imageDistanceFromInverse(f, inverseFocus) * std::abs(inverseFocus - 1.0 / distance);
}

double hyperfocalDistance(double f, double fNumber, double sensorCoc) { return f * f / (fNumber * sensorCoc) + f; }

DepthOfField depthOfField(double f, double zf, double h) {
  DepthOfField dof;
  dof.nearDistance = zf * (h - f) / (h + zf - 2.0 * f);
  dof.farDistance = zf < h ? zf * (h - f) / (h - zf) : std::numeric_limits<double>::infinity();
  return dof;
}

}  // namespace lenslab
