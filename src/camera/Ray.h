#pragma once
// The lecture's ray casting: "Ray R from PRP toward (VRP + u·udir + v·vdir)". The same ViewSpec
// that gives the rasterizer its clipFromWorld gives the ray caster its rays, so any difference
// between the two images is the method's error, not a second camera model's.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "camera/ViewSpec.h"

#include <glm/glm.hpp>

namespace lenslab {

struct Ray {
  glm::dvec3 origin;     // world
  glm::dvec3 direction;  // world, unit length
  double tNear = 0.0;    // the ray's visible span, in units of direction: [tNear, tFar] is
  double tFar = 0.0;     // the part between the near and far distances from the PRP
};

// World position of the window point (u, v) on the view plane: VRP + u·udir + v·vdir.
glm::dvec3 viewPlanePoint(const ViewSpec& spec, glm::dvec2 uv);

// The primary ray through window point (u, v). Perspective: from the PRP toward the view-plane
// point. Parallel: along DOP = CW − PRP through that point, starting on the PRP's plane (n = PRP.n).
Ray primaryRay(const ViewSpec& spec, glm::dvec2 uv);

// Ray casting through the thin lens, built the way the rasterizer builds its views: the ray
// through continuous pixel position `pixel` (origin at the image's top-left corner) of the view
// from aperture offset `lensOffset` (u, v; world units) — viewThroughLens, then primaryRay. All
// rays of one pixel meet on the plane of focus (the lecture's "fire rays from every lens surface
// point toward this point").
// `inverseFocusShift` as for viewThroughLens.
Ray lensRay(const Camera& camera, glm::dvec2 lensOffset, glm::dvec2 pixel, ImageSize size,
            double inverseFocusShift = 0.0);

}  // namespace lenslab
