#include "scene/gltf/Primitives.h"

#include "scene/gltf/ComponentTypes.h"
#include "scene/gltf/Problems.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace lenslab::gltf {

// The formats glTF 2.0 allows for the attributes lenslab reads ("Meshes", attribute table).
struct AttributeFormat {
  std::vector<int> types;
  bool normalizedIntegers = false;  // also normalized UNSIGNED_BYTE / UNSIGNED_SHORT
  const char* valid = "";
};

namespace {

const AttributeFormat kPositionFormat{{TINYGLTF_TYPE_VEC3}, false, "VEC3 FLOAT"};
const AttributeFormat kNormalFormat{{TINYGLTF_TYPE_VEC3}, false, "VEC3 FLOAT"};
const AttributeFormat kTexcoordFormat{
    {TINYGLTF_TYPE_VEC2}, true, "VEC2 of FLOAT or of normalized UNSIGNED_BYTE/UNSIGNED_SHORT"};
const AttributeFormat kTangentFormat{{TINYGLTF_TYPE_VEC4}, false, "VEC4 FLOAT"};
const AttributeFormat kColorFormat{
    {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, true, "VEC3/VEC4 of FLOAT or of normalized UNSIGNED_BYTE/UNSIGNED_SHORT"};

bool drawsTriangles(int mode) {
  return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

// glTF 2.0, "Topology types": strip triangle i is (i, i+1, i+2) for even i and (i, i+2, i+1)
// for odd i, so that all keep the first one's winding; fan triangle i is (i+1, i+2, 0).
std::vector<std::uint32_t> triangleList(int mode, const std::vector<std::uint32_t>& order) {
  std::vector<std::uint32_t> out;
  const std::size_t n = order.size();
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    out.assign(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n / 3 * 3));
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (std::size_t i = 0; i + 2 < n; ++i) {
      if (i % 2 == 0)
        out.insert(out.end(), {order[i], order[i + 1], order[i + 2]});
      else
        out.insert(out.end(), {order[i], order[i + 2], order[i + 1]});
    }
  } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
    for (std::size_t i = 0; i + 2 < n; ++i) out.insert(out.end(), {order[i + 1], order[i + 2], order[0]});
  }
  return out;
}

// glTF: "When normals are not specified, client implementations MUST calculate flat normals":
// every triangle gets three vertices of its own that carry its face normal.
void makeFlatNormals(Mesh& mesh) {
  std::vector<Vertex> vertices;
  vertices.reserve(mesh.indices.size());
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    Vertex a = mesh.vertices[mesh.indices[t]], b = mesh.vertices[mesh.indices[t + 1]],
           c = mesh.vertices[mesh.indices[t + 2]];
    const glm::dvec3 cross = glm::cross(glm::dvec3(b.position - a.position), glm::dvec3(c.position - a.position));
    const double length = glm::length(cross);
    const glm::vec3 normal = length > 0.0 && std::isfinite(length) ? glm::vec3(cross / length) : glm::vec3(0, 0, 1);
    a.normal = b.normal = c.normal = normal;
    vertices.insert(vertices.end(), {a, b, c});
  }
  mesh.vertices = std::move(vertices);
  for (std::size_t i = 0; i < mesh.indices.size(); ++i) mesh.indices[i] = static_cast<std::uint32_t>(i);
}

}  // namespace

// The primitive as a triangle mesh (material not yet assigned), or nothing where lenslab does
// not draw it (points, lines, no POSITION, no whole triangle). Refuses malformed data.
std::optional<Mesh> PrimitiveConverter::convert(int meshIndex, std::size_t k) const {
  const tinygltf::Mesh& gltfMesh = model_.meshes[toIndex(meshIndex)];
  const tinygltf::Primitive& p = gltfMesh.primitives[k];
  const std::string where = cat("mesh ", meshIndex, " primitive ", k);
  const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
  if (!drawsTriangles(mode)) {
    noteOnce(notes_, "points and lines are not drawn (lenslab draws triangles)");
    return std::nullopt;
  }
  if (!p.attributes.count("POSITION")) {
    noteOnce(notes_, cat(where, " has no POSITION and is not drawn"));
    return std::nullopt;
  }
  if (!p.targets.empty()) noteOnce(notes_, "morph targets are ignored: meshes are drawn without them");

  Mesh mesh;
  mesh.name = gltfMesh.name.empty() ? cat("mesh", meshIndex) : gltfMesh.name;
  if (gltfMesh.primitives.size() > 1) mesh.name += cat("#", k);
  const std::size_t vertexCount = readVertices(p, where, mesh);
  const std::vector<std::uint32_t> order = vertexOrder(p, vertexCount, where);
  if (mode == TINYGLTF_MODE_TRIANGLES && order.size() % 3 != 0)
    noteOnce(notes_, cat(where, ": ", order.size(), " vertices are not whole triangles; the last ", order.size() % 3,
                         " are left out"));
  mesh.indices = triangleList(mode, order);
  if (mesh.indices.empty()) {
    noteOnce(notes_, cat(where, " has no whole triangle and is not drawn"));
    return std::nullopt;
  }
  if (!p.attributes.count("NORMAL")) makeFlatNormals(mesh);
  return mesh;
}

// POSITION, NORMAL, TEXCOORD_0, TEXCOORD_1, TANGENT and COLOR_0 into mesh.vertices; returns the vertex count.
std::size_t PrimitiveConverter::readVertices(const tinygltf::Primitive& p, const std::string& where, Mesh& mesh) const {
  const Elements positions = *readAttribute(p, "POSITION", kPositionFormat, std::nullopt, where);
  const std::size_t n = positions.count;
  mesh.vertices.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    mesh.vertices[i].position = glm::vec3(positions.at(i, 0), positions.at(i, 1), positions.at(i, 2));
  if (const auto normals = readAttribute(p, "NORMAL", kNormalFormat, n, where)) {
    for (std::size_t i = 0; i < n; ++i) {
      const glm::dvec3 v(normals->at(i, 0), normals->at(i, 1), normals->at(i, 2));
      const double length = glm::length(v);
      if (length == 0.0) noteOnce(notes_, cat(where, " has zero-length normals; they are drawn as +Z"));
      mesh.vertices[i].normal = length > 0.0 ? glm::vec3(v / length) : glm::vec3(0, 0, 1);
    }
  }
  if (const auto uvs = readAttribute(p, "TEXCOORD_0", kTexcoordFormat, n, where))
    for (std::size_t i = 0; i < n; ++i) mesh.vertices[i].uv = glm::vec2(uvs->at(i, 0), uvs->at(i, 1));
  if (const auto uvs = readAttribute(p, "TEXCOORD_1", kTexcoordFormat, n, where))
    for (std::size_t i = 0; i < n; ++i) mesh.vertices[i].uv1 = glm::vec2(uvs->at(i, 0), uvs->at(i, 1));
  if (const auto tangents = readAttribute(p, "TANGENT", kTangentFormat, n, where)) readTangents(*tangents, where, mesh);
  if (const auto colors = readAttribute(p, "COLOR_0", kColorFormat, n, where)) {
    for (std::size_t i = 0; i < n; ++i)
      mesh.vertices[i].color = glm::vec4(colors->at(i, 0), colors->at(i, 1), colors->at(i, 2),
                                         colors->components == 4 ? colors->at(i, 3) : 1.0);
    mesh.hasVertexColors = true;
  }
  return n;
}

// glTF: TANGENT is "XYZW vertex tangents where the XYZ portion is normalized, and the W component
// is a sign value (-1 or +1) indicating handedness of the tangent basis". Lengths within 1 % of 1
// are normalised (writers round them); a zero-length tangent is what some exporters write where
// uv is degenerate, and is kept as zero (the shader then uses the geometric normal); anything
// else is refused.
void PrimitiveConverter::readTangents(const Elements& tangents, const std::string& where, Mesh& mesh) const {
  for (std::size_t i = 0; i < tangents.count; ++i) {
    const glm::dvec3 t(tangents.at(i, 0), tangents.at(i, 1), tangents.at(i, 2));
    const double w = tangents.at(i, 3), length = glm::length(t);
    if (w != 1.0 && w != -1.0)
      refuse(where, " TANGENT: element ", i, " has w = ", w, "; it must be 1 or -1 (the handedness)");
    if (length != 0.0 && std::abs(length - 1.0) > 0.01)
      refuse(where, " TANGENT: element ", i, " has xyz of length ", length, "; it must be a unit vector");
    if (length == 0.0)
      noteOnce(notes_, cat(where, " has zero-length tangents; those vertices are shaded without their normal map"));
    mesh.vertices[i].tangent = glm::vec4(length > 0.0 ? glm::vec3(t / length) : glm::vec3(0.0f), static_cast<float>(w));
  }
  mesh.hasTangents = true;
}

// An attribute in one of its allowed formats, every value finite; nothing when absent.
std::optional<Elements> PrimitiveConverter::readAttribute(const tinygltf::Primitive& p, const char* name,
                                                          const AttributeFormat& format,
                                                          std::optional<std::size_t> vertexCount,
                                                          const std::string& where) const {
  const auto found = p.attributes.find(name);
  if (found == p.attributes.end()) return std::nullopt;
  const tinygltf::Accessor& a = model_.accessors[toIndex(found->second)];
  const std::string what = cat(where, " ", name, " (accessor ", found->second, ")");
  const bool isFloat = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT && !a.normalized;
  const bool isNormalizedInteger = format.normalizedIntegers && a.normalized &&
                                   (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                    a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  if (std::find(format.types.begin(), format.types.end(), a.type) == format.types.end() ||
      !(isFloat || isNormalizedInteger))
    refuse(what, " is ", typeName(a.type), " of ", a.normalized ? "normalized " : "",
           componentTypeName(a.componentType), "; it must be ", format.valid);
  Elements e = reader_.read(found->second);
  if (vertexCount && e.count != *vertexCount)
    refuse(what, " has ", e.count, " elements but POSITION has ", *vertexCount);
  for (std::size_t i = 0; i < e.values.size(); ++i)
    if (!std::isfinite(e.values[i])) refuse(what, ": element ", i / e.components, " is not a finite number");
  return e;
}

// The primitive's vertex order: its indices, each checked against the vertex count, or 0..n-1.
std::vector<std::uint32_t> PrimitiveConverter::vertexOrder(const tinygltf::Primitive& p, std::size_t vertexCount,
                                                           const std::string& where) const {
  std::vector<std::uint32_t> order;
  if (p.indices < 0) {
    if (vertexCount > UINT32_MAX) refuse(where, ": ", vertexCount, " vertices are more than 32-bit indices reach");
    order.resize(vertexCount);
    for (std::size_t i = 0; i < vertexCount; ++i) order[i] = static_cast<std::uint32_t>(i);
    return order;
  }
  const tinygltf::Accessor& a = model_.accessors[toIndex(p.indices)];
  if (a.type != TINYGLTF_TYPE_SCALAR || !isUnsignedIndexType(a.componentType) || a.normalized)
    refuse(where, " indices (accessor ", p.indices, ") are ", a.normalized ? "normalized " : "", typeName(a.type),
           " of ", componentTypeName(a.componentType),
           "; they must be SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
  const Elements e = reader_.read(p.indices);
  order.reserve(e.count);
  for (std::size_t i = 0; i < e.count; ++i) {
    const double v = e.values[i];
    if (v >= static_cast<double>(vertexCount))
      refuse(where, " indices (accessor ", p.indices, "): element ", i, " is ", v, ", not below the vertex count ",
             vertexCount);
    order.push_back(static_cast<std::uint32_t>(v));
  }
  return order;
}

}  // namespace lenslab::gltf
