#include "lens/ParaxialLens.h"

#include "core/Error.h"
#include "core/Text.h"

#include <cmath>

namespace lenslab {
namespace {

RayTransfer refraction(const LensPrescription& lens, std::size_t i) {
  const double power = (lens.surfaces[i].indexAfter - lens.indexBefore(i)) * lens.surfaces[i].curvaturePerMm();
  return {1.0, 0.0, -power, 1.0};
}

RayTransfer gap(double thicknessMm, double index) { return {1.0, thicknessMm / index, 0.0, 1.0}; }

}  // namespace

RayTransfer RayTransfer::then(const RayTransfer& n) const {
  return {n.a * a + n.b * c, n.a * b + n.b * d, n.c * a + n.d * c, n.c * b + n.d * d};
}

RayTransfer rayTransfer(const LensPrescription& lens, std::size_t first, std::size_t last) {
  RayTransfer m;
  for (std::size_t i = first; i < last; ++i)
    m = m.then(refraction(lens, i)).then(gap(lens.surfaces[i].thicknessMm, lens.surfaces[i].indexAfter));
  return m;
}

RayTransfer lensTransfer(const LensPrescription& lens) {
  const std::size_t last = lens.surfaces.size() - 1;
  return rayTransfer(lens, 0, last).then(refraction(lens, last));
}

FirstOrder firstOrder(const LensPrescription& lens, std::optional<double> stopDiameterMm) {
  const RayTransfer m = lensTransfer(lens);
  // Relative to the lens's own scale: a plate's c is rounding noise next to 1/length.
  const double scale = std::max(lens.lengthMm(), lens.surfaces.front().apertureMm);
  if (!(std::abs(m.c) * scale > 1e-12))
    throw InputError(cat(lens.source,
                         ": the lens has no optical power (an afocal system or a flat plate); it forms no image to "
                         "render with"));
  FirstOrder f;
  const double length = lens.lengthMm();
  f.focalLengthMm = -1.0 / m.c;
  if (f.focalLengthMm < 0.0)
    throw InputError(cat(lens.source, ": the lens diverges (its focal length is ", f.focalLengthMm,
                         " mm): it forms no real image on a film behind it; give a converging lens"));
  // A ray parallel to the axis leaves at height a with n·u = c: it meets the axis a/(−c) on.
  f.backFocalMm = -m.a / m.c;
  // And backward: the ray from the front focal point leaves parallel, c·y + d·u = 0 at y = s·u.
  f.frontFocalMm = -m.d / m.c;
  f.rearPrincipalMm = length + f.backFocalMm - f.focalLengthMm;
  f.frontPrincipalMm = -f.frontFocalMm + f.focalLengthMm;

  const std::size_t stop = lens.stopIndex();
  const double stopDiameter = stopDiameterMm.value_or(lens.surfaces[stop].apertureMm);
  // The stop seen from the scene: the axial point s in front of the first vertex that the front
  // group images onto the stop's centre (a·s + b = 0), magnified 1/a there.
  const RayTransfer front = rayTransfer(lens, 0, stop);
  f.entrancePupilMm = front.b / front.a;
  f.entrancePupilDiameterMm = stopDiameter / std::abs(front.a);
  // The stop seen from the film: where the rear group's image of the stop's centre lies (d·t + b
  // = 0 after the last vertex), magnified 1/d (the matrices have determinant 1).
  const RayTransfer rear =
      rayTransfer(lens, stop, lens.surfaces.size() - 1).then(refraction(lens, lens.surfaces.size() - 1));
  f.exitPupilMm = length - rear.b / rear.d;
  f.exitPupilDiameterMm = stopDiameter / std::abs(rear.d);
  f.fNumber = f.focalLengthMm / f.entrancePupilDiameterMm;
  return f;
}

double stopDiameterForFNumber(const LensPrescription& lens, std::optional<double> fNumber) {
  const double openStop = lens.surfaces[lens.stopIndex()].apertureMm;
  if (!fNumber) return openStop;
  const FirstOrder open = firstOrder(lens);
  const double stop = openStop * (open.focalLengthMm / *fNumber) / open.entrancePupilDiameterMm;
  if (stop > openStop * (1.0 + 1e-9)) {
    // As people type it: a lens sold as f/2 is f/2.03 by its own first-order numbers.
    if (*fNumber >= open.fNumber * (1.0 - kFNumberRounding)) return openStop;
    // The full opening as `lenslab lens` prints it, and the least f-number that opens to it.
    const double full = std::round(open.fNumber * 100.0) / 100.0;
    const double least = std::ceil(open.fNumber * (1.0 - kFNumberRounding) * 100.0) / 100.0;
    throw InputError(cat(lens.source, ": f/", *fNumber, " is faster than the design's full opening, f/", full,
                         " (it needs a stop of ", std::round(stop * 1000.0) / 1000.0, " mm; the design's opens to ",
                         openStop, " mm); give --f-number ", least, " or more (", least, " to ", full,
                         " open it fully)"));
  }
  return stop;
}

double filmDistanceForFocusMm(const LensPrescription& lens, double focusDistanceMm) {
  const RayTransfer m = lensTransfer(lens);
  if (std::isinf(focusDistanceMm)) return -m.a / m.c;
  // An axial point s in front of the first vertex images d = −(a·s + b)/(c·s + d) behind the last;
  // the film is focusDistance from the point: s + length + d = focus, a quadratic in s.
  const double span = focusDistanceMm - lens.lengthMm();
  const double qa = -m.c, qb = span * m.c - m.d + m.a, qc = span * m.d + m.b;
  const double discriminant = qb * qb - 4.0 * qa * qc;
  if (discriminant >= 0.0) {
    // The far conjugate (the object far, the film near), as a camera focuses.
    const double root = std::sqrt(discriminant);
    const double q = -0.5 * (qb + std::copysign(root, qb));  // no cancellation
    double best = -1.0, bestFilm = 0.0;
    for (double s : {q != 0.0 ? qc / q : -1.0, qa != 0.0 ? q / qa : -1.0}) {
      const double d = -(m.a * s + m.b) / (m.c * s + m.d);
      if (s > 0.0 && d > 0.0 && s > best) best = s, bestFilm = d;
    }
    if (best > 0.0) return bestFilm;
  }
  throw InputError(cat(lens.source, ": no real image of a point ", focusDistanceMm,
                       " mm from the film forms behind the lens; focus farther (about 4 focal lengths, ",
                       4.0 * -1.0 / m.c, " mm, at least)"));
}

double filmDistanceForObjectMm(const LensPrescription& lens, double objectMm) {
  const RayTransfer m = lensTransfer(lens);
  if (std::isinf(objectMm)) return -m.a / m.c;
  const double d = -(m.a * objectMm + m.b) / (m.c * objectMm + m.d);
  if (!(objectMm > 0.0) || !(d > 0.0) || !std::isfinite(d))
    throw InputError(cat(lens.source, ": no real image of a point ", objectMm,
                         " mm in front of the lens forms behind it; focus farther ", "(about 4 focal lengths, ",
                         4.0 * -1.0 / m.c, " mm, at least)"));
  return d;
}

}  // namespace lenslab
