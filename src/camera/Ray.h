#pragma once
// The lecture's ray casting: "Ray R from PRP toward (VRP + u·udir + v·vdir)". The same ViewSpec
// that gives the rasterizer its clipFromWorld gives the ray caster its rays, so any difference
// between the two images is the method's error, not a second camera model's.
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

}  // namespace lenslab
