#pragma once
// Per-vertex tangents for normal maps, made where a glTF file gives none. The glTF specification
// asks for MikkTSpace tangents then ("When tangents are not specified, client implementations
// SHOULD calculate tangents using default MikkTSpace algorithms with the specified vertex
// positions, normals, and texture coordinates associated with the normal texture"). This is our
// own implementation of what MikkTSpace computes on well-behaved meshes (see Tangents.cpp for how
// and for where it differs). Pure: no GL.
#include "scene/Scene.h"

#include <cstddef>

namespace lenslab {

struct TangentStats {
  std::size_t uvDegenerateTriangles = 0;  // no uv area: they give no tangent direction
  std::size_t splitVertices = 0;          // vertices duplicated because their triangles' handedness differs
  std::size_t fallbackVertices = 0;       // no direction from any triangle: an arbitrary tangent ⟂ normal
};

// Fills every vertex's `tangent` (xyz unit and perpendicular to its normal, w = ±1: the
// bitangent is w · cross(normal, tangent.xyz), glTF's convention; tangent.xyz follows ∂P/∂u and
// the bitangent −∂P/∂v, up the image, as glTF's normal maps have +Y up) from the uv set `texCoord`
// (0: Vertex::uv, 1: Vertex::uv1), and sets mesh.hasTangents. May add vertices (see splitVertices).
TangentStats generateTangents(Mesh& mesh, int texCoord);

// A unit vector perpendicular to unit `n` (Duff et al. 2017, "Building an orthonormal basis,
// revisited"): the tangent of last resort, continuous except across n.z = 0's sign.
glm::vec3 anyPerpendicular(const glm::vec3& n);

}  // namespace lenslab
