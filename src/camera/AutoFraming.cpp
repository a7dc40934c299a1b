#include "camera/AutoFraming.h"

#include "core/Text.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

double framingDistance(double radius, double focalLength, double sensorSide) {
  // g(D) = r/√(D² − r²) − s(D − f)/(2fD) falls from +∞ (or a positive value at D = f) to
  // −s/(2f): one root, found by bisection between the bounds below (halving in log scale while
  // the interval spans decades, so that 1e-9 and 1e9 take the same effort).
  const auto g = [&](double d) {
    return radius / std::sqrt((d - radius) * (d + radius)) - sensorSide * (d - focalLength) / (2.0 * focalLength * d);
  };
  double lo = std::max(radius, focalLength);
  double hi = 2.0 * lo;
  while (g(hi) > 0.0) hi *= 2.0;
  for (int i = 0; i < 200 && hi > lo * (1.0 + 1e-15); ++i) {
    const double mid = hi > 4.0 * lo ? std::sqrt(lo * hi) : 0.5 * (lo + hi);
    (g(mid) > 0.0 ? lo : hi) = mid;
  }
  return hi;  // on the side where the sphere fits
}

SelectedCamera frameSphere(const glm::dvec3& center, double radius, double focalLengthMm, glm::dvec2 sensorMm,
                           const glm::dvec3& towardCamera) {
  // A sphere smaller than what double precision resolves at its distance from the origin (a
  // point, radius 0, included) is framed as the smallest one it does: 1e-14 of that distance
  // (45 times double's epsilon) leaves about two digits across the frame. Only a point at the origin itself needs an absolute
  // size. (A floor relative to the origin's distance that is larger than that shrinks a small
  // object far from the origin to a speck in an empty frame.)
  const double resolvable = 1e-14 * glm::length(center);
  const double r = kFramingMargin * std::max(radius, resolvable > 0.0 ? resolvable : (radius > 0.0 ? radius : 1.0));
  const double f = focalLengthMm * kMetresPerMillimetre;
  const double side = std::min(sensorMm.x, sensorMm.y) * kMetresPerMillimetre;
  const char* across = sensorMm.y <= sensorMm.x ? "height" : "width";
  const glm::dvec3 back = glm::normalize(towardCamera);
  const std::string lens = cat(focalLengthMm, " mm on ", sensorMm.x, "x", sensorMm.y, " mm");

  const double distance = framingDistance(r, f, side);
  if (distance >= 2.0 * f) {
    PhysicalCamera c;
    c.eye = center + distance * back;
    c.target = center;
    c.focalLengthMm = focalLengthMm;
    c.sensorMm = sensorMm;
    c.focusDistance = distance;
    // Near and far are fitted to the scene before rendering (the caller marks them so); these only
    // have to be valid.
    c.nearDistance = std::max(distance - r, distance * 1e-4) * 0.5;
    const double magnification = f / (distance - f);
    std::string source = cat("automatic framing: the scene's bounding sphere (radius ", radius, ") fills the frame's ",
                             across, " at ", distance, ", ", lens, ", focused on its centre");
    if (magnification > 0.1) source += cat(" (a close-up at magnification ", magnification, ")");
    return {toCamera(c, source), c};
  }
  // Beyond life size: a pinhole with the lens's infinity field of view, tan(half) = side / 2f.
  const double halfAngle = std::atan(side / (2.0 * f));
  const double d = r / std::sin(halfAngle);
  ViewSpec spec;
  spec.projection = Projection::Perspective;
  spec.vrp = center;
  spec.vpn = back;
  spec.vup = glm::dvec3(0.0, 1.0, 0.0);
  spec.prp = {0.0, 0.0, d};
  const glm::dvec2 window = sensorMm * kMetresPerMillimetre * (d / f);
  spec.window = {-0.5 * window.x, -0.5 * window.y, 0.5 * window.x, 0.5 * window.y};
  spec.nearDistance = std::max(d - r, d * 1e-4) * 0.5;
  SelectedCamera selected;
  // At magnification m the frame's smaller side shows side / m: filling it with the sphere needs
  // about side / (2r); life size shows `side`, so a sensor no larger than the sphere is the cure.
  selected.camera = cameraFocusedOnViewPlane(
      spec, 0.0,
      cat("automatic framing: the scene (bounding sphere radius ", radius, ") would need a ", lens,
          " lens at magnification ", f / (distance - f),
          ", beyond life size (1), so a pinhole with that lens's field of view frames it (no focus, no blur); "
          "a sensor no larger than the sphere (--sensor ",
          2.0 * r / kMetresPerMillimetre, "x", 2.0 * r / kMetresPerMillimetre,
          " or smaller) or --eye and --target give a lens"));
  return selected;
}

}  // namespace lenslab
