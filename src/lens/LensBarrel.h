#pragma once
// Optical (cat's-eye) vignetting: the lens barrel in front of the aperture. Seen from the middle of
// the image the whole aperture shows through the barrel's opening; seen from off-axis, the opening
// is displaced against the aperture and clips it, so a highlight near the corner blurs into the
// aperture cut by a circle (the "cat's eye") and the corners receive less light.
//
// Model: a circular opening of radius `radius`, centred on the axis at `distance` in front of the
// aperture (toward the scene), both in world units. The ray from aperture point p (the lens offset,
// in the PRP's plane) toward the point of the plane of focus seen in the direction n (normalised
// image coordinates: the pinhole ray's x/z, y/z) crosses the opening's plane at
//   p·(1 − distance/z_f) + distance·n
// and passes if that lies within the radius. A pinhole has no aperture to clip: the barrel then
// changes nothing (both renderers).
#include <glm/glm.hpp>

#include <optional>
#include <string>

namespace lenslab {

struct LensBarrel {
  double distance = 0.0;  // world units in front of the aperture; 0 with radius 0: no barrel
  double radius = 0.0;    // world units; 0: no barrel

  bool present() const { return radius > 0.0; }
  bool operator==(const LensBarrel&) const = default;
};

// Whether the ray from lens offset `lensOffset` (world units) toward direction `normalised` passes
// the barrel's opening, for focus at inverse distance `inverseFocus` (1/z_f; 0 at infinity).
bool throughBarrel(const LensBarrel& barrel, glm::dvec2 lensOffset, glm::dvec2 normalised, double inverseFocus);

// The share of a round aperture of radius `apertureRadius` that shows through the barrel in
// direction `normalised`: the area of two circles' overlap (the aperture seen in the opening's
// plane, radius R·|1 − distance/z_f|, centred at distance·n; the opening) over the aperture's area.
double roundApertureThroughBarrel(const LensBarrel& barrel, double apertureRadius, glm::dvec2 normalised,
                                  double inverseFocus);

// The barrel's "distance_mm" and "diameter_mm" as a camera file gives them (millimetres; world
// units are metres): a barrel in world units, or what is wrong ("distance_mm is -3; give ...").
struct BarrelProblem {
  std::string field;
  std::string message;
};
std::optional<BarrelProblem> barrelProblem(double distanceMm, double diameterMm);
LensBarrel barrelFromMillimetres(double distanceMm, double diameterMm);

}  // namespace lenslab
