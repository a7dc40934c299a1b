// The lecture form of a camera file: the viewing description itself (io/CameraJson.h).
#include "io/CameraJsonForms.h"

#include "core/Text.h"

#include <cmath>

namespace lenslab {

const std::set<std::string> kLectureKeys = {
    "projection", "vrp", "vpn", "vup", "prp", "window", "near", "far", "aperture_radius", "focus_distance"};

// "aperture_radius" (world units), 0 when absent: a pinhole.
double apertureRadiusOf(const JsonReader& r) {
  if (!r.has("aperture_radius")) return 0.0;
  const double aperture = r.number("aperture_radius");
  if (aperture < 0.0)
    r.fail("aperture_radius", cat("is ", aperture, "; give a radius ≥ 0 in world units (0 = pinhole)"));
  return aperture;
}

CameraFile parseLecture(const JsonReader& r) {
  for (const char* key : {"vrp", "vpn", "prp", "window"}) r.require(key, "lecture");
  ViewSpec spec;
  if (r.has("projection")) {
    const std::string p = r.string("projection");
    if (p == "perspective")
      spec.projection = Projection::Perspective;
    else if (p == "parallel")
      spec.projection = Projection::Parallel;
    else
      r.fail("projection", cat("is \"", p, "\"; use \"perspective\" or \"parallel\""));
  }
  spec.vrp = r.vector<3>("vrp");
  spec.vpn = r.vector<3>("vpn");
  if (r.has("vup")) spec.vup = r.vector<3>("vup");
  spec.prp = r.vector<3>("prp");
  const glm::dvec4 w = r.vector<4>("window");
  spec.window = {w.x, w.y, w.z, w.w};
  const bool perspective = spec.projection == Projection::Perspective;
  const double defaultNear = perspective ? spec.prp.z * kDefaultNearPerViewPlaneDistance : 0.0;
  spec.nearDistance = r.has("near") ? r.distance("near") : defaultNear;
  if (r.has("far"))
    spec.farDistance = r.distance("far");
  else if (!perspective)
    r.require("far", "parallel-projection lecture");
  validate(spec, r.where());
  const double aperture = apertureRadiusOf(r);
  CameraFile file;
  file.camera = cameraFocusedOnViewPlane(spec, aperture, r.where());
  file.camera.nearFromScene = perspective && !r.has("near");
  file.camera.farFromScene = !r.has("far");
  // The view plane is the plane of focus unless focus_distance says otherwise: then the focus goes
  // through refocused(), the same path as --focus-distance (infinity and far focus as 1/z_f).
  if (r.has("focus_distance"))
    file.camera = refocused(file.camera, r.distance("focus_distance"), r.where() + ": focus_distance");
  // A lens focused at distance d has a focal length below d, and no lens is faster than f/0.5
  // (radius ≤ focal length): its aperture radius is below d.
  if (const double focus = r.has("focus_distance") ? r.distance("focus_distance") : spec.prp.z;
      perspective && aperture > 0.0 && std::isfinite(focus) && !(aperture < focus))
    r.fail("aperture_radius",
           cat("is ", aperture, " for a lens focused at ", focus,
               "; a lens focused there has a focal length below that distance and an aperture radius no larger "
               "than its focal length: give a radius below ",
               focus));
  return file;
}

}  // namespace lenslab
