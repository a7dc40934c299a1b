#pragma once
// An axis-aligned box in world space: the scene's bounds, and what the depth-range fitting and
// the framing need of a scene (camera/ asks for a box, not for a scene).
#include <glm/glm.hpp>

#include <limits>

namespace lenslab {

// Empty until a point is added: min is +inf and max −inf on every axis.
struct Bounds {
  glm::dvec3 min{std::numeric_limits<double>::infinity()};
  glm::dvec3 max{-std::numeric_limits<double>::infinity()};
  bool empty() const { return !(min.x <= max.x && min.y <= max.y && min.z <= max.z); }
  void extend(const glm::dvec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  glm::dvec3 center() const { return 0.5 * (min + max); }
  glm::dvec3 size() const { return max - min; }
};

}  // namespace lenslab
