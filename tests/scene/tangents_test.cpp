// Tangents made for normal maps (src/scene/Tangents.h) against closed forms: a plane's and a
// sphere's ∂P/∂u, handedness from mirrored uv, finite frames from degenerate uv.
#include "scene/Tangents.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace lenslab {
namespace {

Vertex vertex(glm::vec3 p, glm::vec3 n, glm::vec2 uv) {
  Vertex v;
  v.position = p;
  v.normal = n;
  v.uv = uv;
  v.uv1 = uv;
  return v;
}

// A unit square in the z = 0 plane, normal +z, uv given per corner (x0y0, x1y0, x1y1, x0y1).
Mesh quad(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d) {
  Mesh m;
  const glm::vec3 n(0, 0, 1);
  m.vertices = {vertex({0, 0, 0}, n, a), vertex({1, 0, 0}, n, b), vertex({1, 1, 0}, n, c), vertex({0, 1, 0}, n, d)};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

void expectUnitPerpendicular(const Vertex& v) {
  const glm::vec3 t(v.tangent);
  ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z));
  EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(t, v.normal), 0.0f, 1e-5f);
  EXPECT_TRUE(v.tangent.w == 1.0f || v.tangent.w == -1.0f);
}

TEST(Tangents, FlatQuadFollowsDpDu) {
  // uv = 2·R·(x, y) + offset with R a rotation by −30°: P = Rᵀ·(uv − offset) / 2, so ∂P/∂u is
  // Rᵀ's first column, (cos 30°, sin 30°, 0), up to length.
  const float c = std::cos(glm::radians(30.0f)), s = std::sin(glm::radians(30.0f));
  auto uvAt = [&](float x, float y) {
    return 2.0f * glm::vec2(c * x + s * y, -s * x + c * y) + glm::vec2(0.3f, -0.1f);
  };
  Mesh m = quad(uvAt(0, 0), uvAt(1, 0), uvAt(1, 1), uvAt(0, 1));
  const TangentStats stats = generateTangents(m, 0);
  EXPECT_TRUE(m.hasTangents);
  EXPECT_EQ(stats.splitVertices, 0u);
  ASSERT_EQ(m.vertices.size(), 4u);
  for (const Vertex& v : m.vertices) {
    expectUnitPerpendicular(v);
    EXPECT_NEAR(v.tangent.x, c, 1e-4f);
    EXPECT_NEAR(v.tangent.y, s, 1e-4f);
    // ∂P/∂v = (−sin 30°, cos 30°) = cross(n, ∂P/∂u); the bitangent is −∂P/∂v (up the image,
    // against glTF's v), so w = −1.
    EXPECT_EQ(v.tangent.w, -1.0f);
  }
}

TEST(Tangents, ImageUprightIsRightHandedAndMirroredUvIsLeftHanded) {
  // The image upright on the quad (glTF's v down the image, so v falls along +y): ∂P/∂u = +x,
  // the bitangent (up the image, −∂P/∂v) = +y = cross(n, t): w = +1.
  Mesh upright = quad({0, 1}, {1, 1}, {1, 0}, {0, 0});
  generateTangents(upright, 0);
  for (const Vertex& v : upright.vertices) {
    expectUnitPerpendicular(v);
    EXPECT_NEAR(v.tangent.x, 1.0f, 1e-4f);
    EXPECT_EQ(v.tangent.w, 1.0f);
  }
  // Mirrored (u decreasing along x): ∂P/∂u = −x, the bitangent still +y = −cross(n, t): w = −1.
  Mesh m = quad({1, 1}, {0, 1}, {0, 0}, {1, 0});
  generateTangents(m, 0);
  for (const Vertex& v : m.vertices) {
    expectUnitPerpendicular(v);
    EXPECT_NEAR(v.tangent.x, -1.0f, 1e-4f);
    EXPECT_EQ(v.tangent.w, -1.0f);
    // glTF's bitangent, w · cross(n, t), points up the image: −∂P/∂v = +y.
    const glm::vec3 bitangent = v.tangent.w * glm::cross(v.normal, glm::vec3(v.tangent));
    EXPECT_NEAR(bitangent.y, 1.0f, 1e-4f);
  }
}

TEST(Tangents, SharedVertexOfBothHandednessIsSplit) {
  // Two quads side by side sharing the edge x = 1, the second with its u mirrored (a symmetric
  // model's seam): the shared vertices are split, each copy with its side's tangent.
  Mesh m;
  const glm::vec3 n(0, 0, 1);
  m.vertices = {vertex({0, 0, 0}, n, {0, 0}), vertex({1, 0, 0}, n, {1, 0}), vertex({1, 1, 0}, n, {1, 1}),
                vertex({0, 1, 0}, n, {0, 1}), vertex({2, 0, 0}, n, {0, 0}), vertex({2, 1, 0}, n, {0, 1})};
  m.indices = {0, 1, 2, 0, 2, 3, 1, 4, 5, 1, 5, 2};
  const TangentStats stats = generateTangents(m, 0);
  EXPECT_EQ(stats.splitVertices, 2u);
  ASSERT_EQ(m.vertices.size(), 8u);
  for (std::size_t t = 0; t < 4; ++t)
    for (int c = 0; c < 3; ++c) {
      const Vertex& v = m.vertices[m.indices[3 * t + static_cast<std::size_t>(c)]];
      expectUnitPerpendicular(v);
      EXPECT_EQ(v.tangent.w, t < 2 ? -1.0f : 1.0f) << "triangle " << t;  // v along +y: −1 (see above)
      EXPECT_NEAR(v.tangent.x, t < 2 ? 1.0f : -1.0f, 1e-4f) << "triangle " << t;
    }
}

TEST(Tangents, DegenerateUvGivesFiniteUnitTangents) {
  for (const glm::vec2 same : {glm::vec2(0.5f), glm::vec2(0.0f)}) {
    Mesh m = quad(same, same, same, same);  // no uv area anywhere
    const TangentStats stats = generateTangents(m, 0);
    EXPECT_EQ(stats.uvDegenerateTriangles, 2u);
    EXPECT_EQ(stats.fallbackVertices, 4u);
    for (const Vertex& v : m.vertices) expectUnitPerpendicular(v);
  }
  // uv along a line (zero area) and a triangle of zero geometric area next to a good one.
  Mesh line = quad({0, 0}, {1, 0}, {2, 0}, {3, 0});
  generateTangents(line, 0);
  for (const Vertex& v : line.vertices) expectUnitPerpendicular(v);
  Mesh collapsed = quad({0, 0}, {1, 0}, {1, 1}, {0, 1});
  collapsed.vertices[3].position = collapsed.vertices[2].position;
  generateTangents(collapsed, 0);
  for (const Vertex& v : collapsed.vertices) expectUnitPerpendicular(v);
  // Normals pointing along each axis, both signs (anyPerpendicular's branches).
  for (const glm::vec3 n : {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(1, 0, 0), glm::vec3(0, -1, 0)}) {
    const glm::vec3 t = anyPerpendicular(n);
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(t, n), 0.0f, 1e-6f);
  }
}

TEST(Tangents, UsesTheChosenUvSet) {
  Mesh m = quad({0, 0}, {1, 0}, {1, 1}, {0, 1});
  for (Vertex& v : m.vertices) v.uv1 = glm::vec2(v.uv.y, v.uv.x);  // set 1: u along y
  generateTangents(m, 1);
  for (const Vertex& v : m.vertices) {
    EXPECT_NEAR(v.tangent.y, 1.0f, 1e-4f);
    EXPECT_EQ(v.tangent.w, 1.0f);  // swapping u and v mirrors (set 0 here would give −1)
  }
}

// A uv sphere: P(u, v) = (sin θ cos φ, cos θ, −sin θ sin φ) with φ = 2πu, θ = πv, the seam's
// vertices duplicated (u = 0 and u = 1) as exporters write them. ∂P/∂u ∝ (−sin φ, 0, −cos φ).
Mesh uvSphere(int segments, int rings) {
  Mesh m;
  for (int j = 0; j <= rings; ++j)
    for (int i = 0; i <= segments; ++i) {
      const float u = static_cast<float>(i) / static_cast<float>(segments),
                  v = static_cast<float>(j) / static_cast<float>(rings);
      const float phi = glm::two_pi<float>() * u, theta = glm::pi<float>() * v;
      const glm::vec3 p(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
      m.vertices.push_back(vertex(p, p, {u, v}));
    }
  const auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (segments + 1) + i); };
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < segments; ++i) {
      // Counter-clockwise seen from outside.
      if (j > 0) m.indices.insert(m.indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j)});
      if (j + 1 < rings) m.indices.insert(m.indices.end(), {at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)});
    }
  return m;
}

TEST(Tangents, UvSphereFollowsDpDu) {
  const int segments = 64, rings = 32;
  Mesh m = uvSphere(segments, rings);
  const std::size_t original = m.vertices.size();
  const TangentStats stats = generateTangents(m, 0);
  EXPECT_EQ(stats.splitVertices, 0u);
  EXPECT_EQ(m.vertices.size(), original);
  double worst = 0.0, worstSeam = 0.0;
  for (const Vertex& v : m.vertices) {
    expectUnitPerpendicular(v);
    const float phi = glm::two_pi<float>() * v.uv.x, theta = glm::pi<float>() * v.uv.y;
    if (std::sin(theta) < 1e-3f) continue;  // the poles: ∂P/∂u vanishes there
    const glm::dvec3 dPdu = glm::normalize(glm::dvec3(-std::sin(phi), 0.0, -std::cos(phi)));
    const glm::dvec3 dPdv(std::cos(theta) * std::cos(phi), -std::sin(theta), -std::cos(theta) * std::sin(phi));
    // The seam's vertices (u = 0 and u = 1 are different vertices) see the triangles of one side
    // only, whose chord leans by half a segment's angle; MikkTSpace does the same (it welds
    // vertices only where their uv agree).
    const bool seam = v.uv.x == 0.0f || v.uv.x == 1.0f;
    (seam ? worstSeam : worst) = std::max(seam ? worstSeam : worst, glm::length(glm::dvec3(v.tangent) - dPdu));
    const double handedness = glm::dot(glm::cross(glm::dvec3(v.normal), dPdu), -dPdv);  // bitangent: −∂P/∂v
    EXPECT_EQ(v.tangent.w, handedness > 0.0 ? 1.0f : -1.0f);
  }
  EXPECT_LE(worst, 1e-4);
  EXPECT_LE(worstSeam, 1.01 * std::sin(glm::pi<double>() / segments));  // half a segment's chord angle
}

}  // namespace
}  // namespace lenslab
