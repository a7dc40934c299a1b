#pragma once
// Primitives → meshes: a glTF primitive as a lenslab triangle mesh (lists, strips and fans as
// lists; POSITION, NORMAL or flat normals, TEXCOORD_0 and _1, TANGENT, COLOR_0), or nothing with a note where
// lenslab does not draw it.
#include "scene/Scene.h"
#include "scene/gltf/Accessors.h"

#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lenslab::gltf {

struct AttributeFormat;  // the formats glTF allows for an attribute (Primitives.cpp)

class PrimitiveConverter {
 public:
  PrimitiveConverter(const tinygltf::Model& model, const AccessorReader& reader, std::vector<std::string>& notes)
      : model_(model), reader_(reader), notes_(notes) {}

  // The primitive as a triangle mesh (material not yet assigned), or nothing where lenslab does
  // not draw it (points, lines, no POSITION, no whole triangle). Refuses malformed data.
  std::optional<Mesh> convert(int meshIndex, std::size_t k) const;

 private:
  std::size_t readVertices(const tinygltf::Primitive& p, const std::string& where, Mesh& mesh) const;
  void readTangents(const Elements& tangents, const std::string& where, Mesh& mesh) const;
  std::optional<Elements> readAttribute(const tinygltf::Primitive& p, const char* name, const AttributeFormat& format,
                                        std::optional<std::size_t> vertexCount, const std::string& where) const;
  std::vector<std::uint32_t> vertexOrder(const tinygltf::Primitive& p, std::size_t vertexCount,
                                         const std::string& where) const;

  const tinygltf::Model& model_;
  const AccessorReader& reader_;
  std::vector<std::string>& notes_;
};

}  // namespace lenslab::gltf
