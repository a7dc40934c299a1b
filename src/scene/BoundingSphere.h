#pragma once
// A tight sphere around a scene's vertices, for framing: the smallest enclosing ball of the world
// positions (Welzl's algorithm on a small core set of the points, grown until every vertex lies
// inside). The bounding box's circumsphere can be √3 times larger than the object (a round
// object's box corners), so a model framed by its box may span only 1/√3 ≈ 58 % of the frame's
// height; DamagedHelmet spans 62 % of it framed by its box, 89 % framed by this sphere.
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace lenslab {

struct BoundingSphere {
  glm::dvec3 center{0.0};
  double radius = 0.0;  // 0 for a single point; negative when there are no points
  bool empty() const { return radius < 0.0; }
};

// The smallest ball holding every point, to within a relative 1e-9 of its radius (it always holds
// them all: the last step only ever grows it).
BoundingSphere smallestEnclosingSphere(const std::vector<glm::dvec3>& points);

// Every instance's vertices in world space (double precision, as computeBounds does). Empty scene:
// an empty sphere.
BoundingSphere boundingSphere(const Scene& scene);

}  // namespace lenslab
