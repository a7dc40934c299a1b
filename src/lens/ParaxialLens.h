#pragma once
// First-order (paraxial) optics of a lens prescription: focal lengths, principal planes, pupils
// and focusing, from the 2 × 2 ray-transfer matrices of its surfaces. Pure math (std), no GL.
//
// A paraxial ray is (y, n·u): its height and its slope times the medium's index. Refraction at a
// surface of curvature c from index n to n' keeps y and takes n·u to n·u − y·(n' − n)·c; a gap t
// in index n keeps n·u and takes y to y + t·(n·u)/n. Both matrices have determinant 1.
// Positions are along the axis in mm, the first surface's vertex at 0, growing toward the film.
#include "lens/LensPrescription.h"

#include <optional>

namespace lenslab {

struct RayTransfer {
  double a = 1.0, b = 0.0;                          // y'    = a·y + b·nu
  double c = 0.0, d = 1.0;                          // nu'   = c·y + d·nu
  RayTransfer then(const RayTransfer& next) const;  // this, followed by `next`
};

// From just before surface `first` refracts to just before surface `last` refracts (first ≤ last):
// the refractions of surfaces first … last − 1 and the gaps after them.
RayTransfer rayTransfer(const LensPrescription& lens, std::size_t first, std::size_t last);
// The whole lens, from before its first surface to after its last (both in air).
RayTransfer lensTransfer(const LensPrescription& lens);

struct FirstOrder {
  double focalLengthMm = 0.0;     // effective focal length; inf for a lens of no power
  double backFocalMm = 0.0;       // last vertex → rear focal point
  double frontFocalMm = 0.0;      // front focal point → first vertex (positive in front of it)
  double rearPrincipalMm = 0.0;   // position of the rear principal plane H'
  double frontPrincipalMm = 0.0;  // position of the front principal plane H
  double entrancePupilMm = 0.0;   // position of the stop's image seen from the scene
  double entrancePupilDiameterMm = 0.0;
  double exitPupilMm = 0.0;  // position of the stop's image seen from the film
  double exitPupilDiameterMm = 0.0;
  double fNumber = 0.0;  // paraxial, at infinity focus: focal length / entrance pupil
};

// First-order properties with the stop at `stopDiameterMm` (its row's aperture when not given).
// A lens of no power (a flat plate) is refused: it has no focal length to render with.
FirstOrder firstOrder(const LensPrescription& lens, std::optional<double> stopDiameterMm = std::nullopt);

// The stop's diameter that gives paraxial f-number `fNumber` (the stop row's own when not given):
// the stop scales the entrance pupil in proportion (the front group's magnification). Refused
// (naming the lens and the fastest f-number) where that is wider than the design's stop.
// An f-number this much (relative) below the design's full opening is the full opening as people
// round it (f/2 for a design's f/2.03, f/1.4 for f/1.43); one further below is refused.
constexpr double kFNumberRounding = 0.025;
double stopDiameterForFNumber(const LensPrescription& lens, std::optional<double> fNumber);

// Where the film goes to focus at `focusDistanceMm`, measured from the film (as a camera's
// distance scale is): the distance from the last vertex to the film, paraxially. Infinity gives
// the back focal distance. Refused (naming the lens) where no real image of that distance forms
// behind the lens, e.g. closer than about four focal lengths.
double filmDistanceForFocusMm(const LensPrescription& lens, double focusDistanceMm);

// The same for an object `objectMm` in front of the first vertex (a camera focused at a distance
// from its entrance pupil knows this one): last vertex → film. Refused where no real image forms.
double filmDistanceForObjectMm(const LensPrescription& lens, double objectMm);

}  // namespace lenslab
