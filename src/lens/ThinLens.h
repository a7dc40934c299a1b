#pragma once
// The lecture's thin lens, as relations between distances (all in world units unless the name
// says otherwise). "Rays entering parallel on one side converge at the focal point": with focal
// length f, a point at distance z in front of the lens focuses at image distance z_i behind it,
// 1/z + 1/z_i = 1/f (the lecture's f² = zZ measured from the focal points).
//
// Focus is carried as an inverse distance (1/z_f, "dioptres" in world units) so that focus at
// infinity is 0 rather than a division by infinity.

namespace lenslab {

// z_i = f·z_f / (z_f − f) = f / (1 − f·(1/z_f)); at infinity focus z_i = f.
double imageDistanceFromInverse(double focalLength, double inverseFocusDistance);

// Lateral magnification of the plane of focus onto the sensor: z_i / z_f = f·(1/z_f) / (1 − f/z_f).
double magnification(double focalLength, double inverseFocusDistance);

// Diameter of the circle of confusion of a point at distance z, measured on the plane of focus
// (the view plane, where lenslab's window is): every aperture point sees the point along a line
// that crosses the view plane somewhere in a disk of diameter 2R·|z − z_f| / z. Written with
// inverse distances it is 2R·z_f·|1/z_f − 1/z|, which stays finite for any z > 0.
double cocDiameterOnFocusPlane(double apertureRadius, double inverseFocusDistance, double distance);

// The same circle measured on the sensor: 2R·z_i·|1/z_f − 1/z|. Finite at infinity focus.
double cocDiameterOnSensor(double apertureRadius, double focalLength, double inverseFocusDistance, double distance);

// Hyperfocal distance H = f² / (N·c) + f for a circle of confusion c on the sensor.
double hyperfocalDistance(double focalLength, double fNumber, double sensorCoc);

// Near and far limits of the depth of field for focus z_f and hyperfocal distance H:
//   near = z_f·(H − f) / (H + z_f − 2f),  far = z_f·(H − f) / (H − z_f)  (infinity when z_f ≥ H).
struct DepthOfField {
  double nearDistance;
  double farDistance;
};
DepthOfField depthOfField(double focalLength, double focusDistance, double hyperfocal);

}  // namespace lenslab
