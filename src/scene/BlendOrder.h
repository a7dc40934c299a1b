#pragma once
// The order the rasterizer draws alphaMode BLEND instances in: back to front as one view sees
// them, by each instance's bounds centre. Blending `over` is exact only in that order; within one
// instance the triangles go in index order, so interpenetrating or self-overlapping blend meshes
// may composite out of order where the ray caster (exact per ray) does not (docs/materials.md).
// Pure: no GL.
#include "scene/Scene.h"

#include <cstddef>
#include <vector>

namespace lenslab {

// Whether an instance's material has alphaMode BLEND (the glTF default material has not).
bool isBlended(const Scene& scene, const Instance& instance);
bool anyBlended(const Scene& scene);

// The world position of the centre of an instance's bounds: its mesh's model-space box centre
// carried by worldFromModel (the centre of the box's image under the affine map).
glm::dvec3 instanceBoundsCentre(const Scene& scene, const Instance& instance);

// Indices into scene.instances of its BLEND instances, farthest first. A perspective view
// (`eye` set: its projection centre, world) orders by distance from the eye; a parallel view
// (`eye` null) by distance along its viewing direction, −towardViewer. Ties keep index order.
std::vector<std::size_t> blendBackToFront(const Scene& scene, const glm::dvec3* eye, const glm::dvec3& towardViewer);

}  // namespace lenslab
