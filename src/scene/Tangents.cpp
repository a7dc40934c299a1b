#include "scene/Tangents.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

// How the tangents are made (MikkTSpace's method, Mikkelsen 2008, "Simulation of wrinkled
// surfaces revisited", as its reference implementation runs with its defaults):
//  1. Each triangle's tangent is ∂P/∂u of the plane through it, from its edges e1, e2 and their uv
//     steps (du, dv): T = (e1·dv2 − e2·dv1) / (du1·dv2 − du2·dv1), normalised. The sign of the uv
//     area (the denominator) is the triangle's handedness, negated because glTF's v points down
//     the image while its normal maps' +Y points up (see triangleFrame): uv mirrored across the
//     seam of a symmetric model flips it. A triangle of no uv area has no direction and adds nothing.
//  2. At each corner, T less its component along the vertex normal (Gram–Schmidt), normalised,
//     weighted by the corner's angle (its edges projected into the plane ⟂ the normal), is
//     summed over every triangle of the same handedness meeting at the vertex. Vertices are
//     the same vertex when position, normal and the uv set agree, whatever their index
//     (MikkTSpace welds them too), so a file's duplicated vertices get one tangent.
//  3. The sum, normalised, is the tangent; w is the handedness.
// Where it differs from mikktspace.c:
//  - A vertex shared by triangles of both handedness is split in two, each copy with its own
//    sum, as MikkTSpace does; copies are appended and the minority's triangles re-indexed, so
//    the vertex order differs from MikkTSpace's (which re-emits every corner).
//  - MikkTSpace's angular threshold (default 180°: never split by angle) is not implemented.
//  - A vertex whose triangles all lack a direction gets any tangent ⟂ its normal
//    (anyPerpendicular), where MikkTSpace copies one from a neighbouring group: the frame is
//    arbitrary there either way, since no uv gradient exists to map the texture by.
//  - Sums are in double; results agree with MikkTSpace to float rounding on meshes with
//    non-degenerate uv (tests/scene/tangents_test.cpp checks them against the analytic ∂P/∂u).

namespace lenslab {

glm::vec3 anyPerpendicular(const glm::vec3& n) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float b = n.x * n.y * a;
  return {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
}

namespace {

glm::dvec2 texCoordOf(const Vertex& v, int texCoord) { return glm::dvec2(texCoord == 1 ? v.uv1 : v.uv); }

// Gram–Schmidt: `t` less its component along unit `n`, normalised; zero where nothing is left.
glm::dvec3 perpendicularPart(const glm::dvec3& t, const glm::dvec3& n) {
  const glm::dvec3 p = t - n * glm::dot(n, t);
  const double length = glm::length(p);
  return length > 0.0 && std::isfinite(length) ? p / length : glm::dvec3(0.0);
}

struct TriangleFrame {
  glm::dvec3 tangent{0.0};  // unit ∂P/∂u, or zero without uv area
  bool positive = true;     // handedness: uv area > 0
  bool valid = false;
};

TriangleFrame triangleFrame(const Vertex& a, const Vertex& b, const Vertex& c, int texCoord) {
  const glm::dvec3 e1 = glm::dvec3(b.position) - glm::dvec3(a.position),
                   e2 = glm::dvec3(c.position) - glm::dvec3(a.position);
  const glm::dvec2 d1 = texCoordOf(b, texCoord) - texCoordOf(a, texCoord),
                   d2 = texCoordOf(c, texCoord) - texCoordOf(a, texCoord);
  const double det = d1.x * d2.y - d2.x * d1.y;
  TriangleFrame f;
  if (!(det != 0.0) || !std::isfinite(det)) return f;
  const glm::dvec3 t = (e1 * d2.y - e2 * d1.y) / det;
  const double length = glm::length(t);
  if (!(length > 0.0) || !std::isfinite(length)) return f;
  f.tangent = t / length;
  // glTF's v runs down the image and a normal map's +Y is up the image (glTF 2.0, material.
  // normalTexture: "+X is right and +Y is up"), so the bitangent is −∂P/∂v: right-handed where
  // the uv area, with v pointing down, is negative. (MikkTSpace is fed v pointing up by the
  // exporters that write glTF's tangents, e.g. Blender's, which flip v on export.)
  f.positive = det < 0.0;
  f.valid = true;
  return f;
}

// The corner's angle between its two edges, both projected into the plane ⟂ unit `n`.
double cornerAngle(const glm::dvec3& corner, const glm::dvec3& next, const glm::dvec3& previous, const glm::dvec3& n) {
  const glm::dvec3 a = perpendicularPart(next - corner, n), b = perpendicularPart(previous - corner, n);
  if (a == glm::dvec3(0.0) || b == glm::dvec3(0.0)) return 0.0;
  return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
}

}  // namespace

TangentStats generateTangents(Mesh& mesh, int texCoord) {
  TangentStats stats;
  const std::size_t triangles = mesh.indices.size() / 3;
  std::vector<TriangleFrame> frames(triangles);
  for (std::size_t t = 0; t < triangles; ++t) {
    const std::uint32_t* i = &mesh.indices[3 * t];
    frames[t] = triangleFrame(mesh.vertices[i[0]], mesh.vertices[i[1]], mesh.vertices[i[2]], texCoord);
    if (!frames[t].valid) ++stats.uvDegenerateTriangles;
  }

  // Welded vertices: one group per distinct (position, normal, uv).
  const std::size_t n = mesh.vertices.size();
  std::vector<std::size_t> groupOf(n);
  std::map<std::array<float, 8>, std::size_t> groups;
  for (std::size_t v = 0; v < n; ++v) {
    const Vertex& x = mesh.vertices[v];
    const glm::vec2 uv = texCoord == 1 ? x.uv1 : x.uv;
    const std::array<float, 8> key{x.position.x, x.position.y, x.position.z, x.normal.x,
                                   x.normal.y,   x.normal.z,   uv.x,         uv.y};
    groupOf[v] = groups.emplace(key, groups.size()).first->second;
  }

  // Angle-weighted sums per group and handedness.
  std::vector<glm::dvec3> sums(2 * groups.size(), glm::dvec3(0.0));
  // Each vertex's first handedness (from its first triangle with a direction; + without one).
  std::vector<std::int8_t> primary(n, -1);
  for (std::size_t t = 0; t < triangles; ++t) {
    if (!frames[t].valid) continue;
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t v = mesh.indices[3 * t + static_cast<std::size_t>(c)];
      const std::uint32_t next = mesh.indices[3 * t + static_cast<std::size_t>((c + 1) % 3)];
      const std::uint32_t previous = mesh.indices[3 * t + static_cast<std::size_t>((c + 2) % 3)];
      const glm::dvec3 normal = glm::normalize(glm::dvec3(mesh.vertices[v].normal));
      const double angle = cornerAngle(glm::dvec3(mesh.vertices[v].position), glm::dvec3(mesh.vertices[next].position),
                                       glm::dvec3(mesh.vertices[previous].position), normal);
      sums[2 * groupOf[v] + (frames[t].positive ? 1 : 0)] += angle * perpendicularPart(frames[t].tangent, normal);
      if (primary[v] < 0) primary[v] = frames[t].positive ? 1 : 0;
    }
  }
  for (std::int8_t& p : primary)
    if (p < 0) p = 1;

  // Corners of the other handedness than their vertex's first move to a copy of the vertex.
  std::vector<std::uint32_t> copyOf(n, UINT32_MAX);
  std::vector<std::uint32_t> originalOf;  // of each appended copy, whose handedness is the other one
  for (std::size_t t = 0; t < triangles; ++t) {
    if (!frames[t].valid) continue;
    const std::int8_t handedness = frames[t].positive ? 1 : 0;
    for (int c = 0; c < 3; ++c) {
      std::uint32_t& v = mesh.indices[3 * t + static_cast<std::size_t>(c)];
      if (v >= n || primary[v] == handedness) continue;
      if (copyOf[v] == UINT32_MAX) {
        copyOf[v] = static_cast<std::uint32_t>(mesh.vertices.size());
        mesh.vertices.push_back(mesh.vertices[v]);
        originalOf.push_back(v);
        ++stats.splitVertices;
      }
      v = copyOf[v];
    }
  }

  auto finish = [&](Vertex& vertex, std::size_t group, bool positive) {
    const glm::dvec3 normal = glm::normalize(glm::dvec3(vertex.normal));
    glm::dvec3 t = perpendicularPart(sums[2 * group + (positive ? 1 : 0)], normal);
    if (t == glm::dvec3(0.0)) {
      t = glm::dvec3(anyPerpendicular(glm::vec3(normal)));
      ++stats.fallbackVertices;
    }
    vertex.tangent = glm::vec4(glm::vec3(t), positive ? 1.0f : -1.0f);
  };
  for (std::size_t v = 0; v < n; ++v) finish(mesh.vertices[v], groupOf[v], primary[v] == 1);
  for (std::size_t k = 0; k < originalOf.size(); ++k)
    finish(mesh.vertices[n + k], groupOf[originalOf[k]], primary[originalOf[k]] != 1);
  mesh.hasTangents = true;
  return stats;
}

}  // namespace lenslab
