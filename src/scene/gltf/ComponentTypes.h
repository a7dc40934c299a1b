#pragma once
// glTF accessor types (SCALAR ... MAT4) and component types (BYTE ... FLOAT): their names, sizes,
// the byte layout of one element, and the value of one stored component. The numbers are glTF's
// (tinygltf's TINYGLTF_TYPE_* and TINYGLTF_COMPONENT_TYPE_* constants).
#include <cstddef>
#include <string>

namespace lenslab::gltf {

// Bytes per component; 0 for a number that is not a glTF component type.
std::size_t componentSize(int componentType);
std::string componentTypeName(int componentType);
std::string typeName(int type);
bool isUnsignedIndexType(int componentType);

// Where each component of one element lies. Matrix columns start on 4-byte boundaries (glTF
// "Data Alignment"), which only matters for byte and short matrices.
struct ElementLayout {
  std::size_t componentSize = 0;
  std::size_t components = 0;
  std::size_t rows = 0;          // components per column (all of them for scalars and vectors)
  std::size_t columnStride = 0;  // bytes
  std::size_t size = 0;          // bytes of one element
  std::size_t offset(std::size_t c) const { return c / rows * columnStride + c % rows * componentSize; }
};

// Empty (components == 0) for an unknown type or component type.
ElementLayout elementLayout(int type, int componentType);

// One component as stored (integers as their integer value).
double storedComponent(const unsigned char* p, int componentType);

// glTF's "normalized" integers (spec, "Animations", the table of decoding equations).
double normalizedComponent(double stored, int componentType);

}  // namespace lenslab::gltf
