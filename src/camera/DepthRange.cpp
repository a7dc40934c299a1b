#include "camera/DepthRange.h"

#include "camera/Projection.h"
#include "core/Error.h"
#include "core/Text.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

DepthInterval depthIntervalOf(const ViewSpec& view, const Bounds& bounds) {
  const ViewBasis b = viewBasis(view);
  const glm::dvec3 prp = prpWorld(view);
  DepthInterval d{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 p((corner & 1) ? bounds.max.x : bounds.min.x, (corner & 2) ? bounds.max.y : bounds.min.y,
                       (corner & 4) ? bounds.max.z : bounds.min.z);
    // Depth is linear in the point, so its extremes over the box are at corners.
    const double depth = -glm::dot(p - prp, b.n);
    d.nearest = std::min(d.nearest, depth);
    d.farthest = std::max(d.farthest, depth);
  }
  return d;
}

Camera withDepthRangeFitted(const Camera& camera, const Bounds& bounds) {
  Camera c = camera;
  ViewSpec& v = c.view;
  if (v.projection != Projection::Perspective || bounds.empty()) return c;
  const DepthInterval d = depthIntervalOf(v, bounds);
  if (!std::isfinite(d.nearest) || !std::isfinite(d.farthest)) return c;
  // Reverse-Z stores near / depth: below about 1e-38 float has no normal number for it, and the
  // scene is drawn nowhere (a given near of 1e-100 before a scene 5 away rendered only the sky).
  if (!camera.nearFromScene && d.farthest > 0.0 && v.nearDistance < 1e-30 * d.farthest)
    throw InputError(cat(camera.source, ": near is ", v.nearDistance, " with the scene reaching ", d.farthest,
                         " away; depth keeps 1e-30 of that at most: give near >= ", 1e-30 * d.farthest,
                         " or leave it out"));
  if (!(camera.nearFromScene || camera.farFromScene)) return c;
  // A margin of 1 % of the depth range, and at least 1e-6 of the distance and of the scene's size:
  // a scene with no depth (a plane facing the camera) still gets a range wider than the float
  // rounding (~6e-8 of the coordinates) of the depths its vertices are drawn at.
  const double margin =
      std::max({0.01 * (d.farthest - d.nearest), 1e-6 * std::max(std::abs(d.nearest), std::abs(d.farthest)),
                1e-6 * glm::length(bounds.size())});
  // An open near is also kept above 1e-6 of the scene's depth: clipping works in float, and a
  // surface that passes beside the camera clips at a w whose rounding (~6e-8 of the coordinates)
  // must stay below near, or the clipped vertex projects anywhere (PRP n = 1e-7 with the default
  // near n/1000 drew a fan of garbage over the floor).
  const double clipFloor = 1e-6 * std::max(std::abs(d.nearest), std::abs(d.farthest));
  // The camera's own near (0.05 for a physical camera, PRP.n/1000 for the lecture's) is only a
  // default: it would clip away a whole scene smaller than itself (a 1 cm model seen from 3 cm). In
  // front of the scene the near is fitted to it; inside its bounds it is kept below 1e-3 of the
  // scene's size, so that a scene and its camera scaled together keep their picture.
  if (camera.nearFromScene) {
    const double inside = std::min(v.nearDistance, 1e-3 * glm::length(bounds.size()));
    v.nearDistance = std::max(d.nearest - margin > 0.0 ? d.nearest - margin : inside, clipFloor);
  }
  if (camera.farFromScene && d.farthest + margin > v.nearDistance)
    v.farDistance = std::min(v.farDistance, d.farthest + margin);
  return c;
}

}  // namespace lenslab
