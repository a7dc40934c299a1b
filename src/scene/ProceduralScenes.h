#pragma once
// Scenes made in code, with known geometry, for tests that need exact answers.
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace lenslab {

// An axis-aligned box centred at the origin, outward normals, counter-clockwise faces.
Mesh boxMesh(const glm::dvec3& halfExtent, int material);

// A quad in the model's z = 0 plane, [−halfWidth, halfWidth] × [−halfHeight, halfHeight], facing +z,
// UVs from (0, 1) at the bottom-left to (1, 0) at the top-right (glTF's top-left UV origin).
Mesh quadMesh(double halfWidth, double halfHeight, int material);

struct Marker {
  glm::dvec3 center;  // world
  double halfSize;    // world
  glm::vec3 color;    // linear, unlit
};

// Small unlit cubes on a black background.
Scene markerScene(const std::vector<Marker>& markers);

// Adds an unlit, double-sided quad of `color`, placed by `worldFromModel`.
void addUnlitQuad(Scene& scene, const glm::dmat4& worldFromModel, double halfWidth, double halfHeight,
                  const glm::vec3& color);

}  // namespace lenslab
