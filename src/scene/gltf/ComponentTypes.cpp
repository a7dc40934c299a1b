#include "scene/gltf/ComponentTypes.h"

#include "core/Text.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace lenslab::gltf {

std::size_t componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;  // not a glTF component type
  }
}

std::string componentTypeName(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    default: return cat("componentType ", componentType);
  }
}

std::string typeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return cat("type ", type);
  }
}

bool isUnsignedIndexType(int componentType) {
  return componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
         componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
         componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

// Empty (components == 0) for an unknown type or component type.
ElementLayout elementLayout(int type, int componentType) {
  ElementLayout l;
  l.componentSize = componentSize(componentType);
  std::size_t columns = 1;
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: l.rows = 1; break;
    case TINYGLTF_TYPE_VEC2: l.rows = 2; break;
    case TINYGLTF_TYPE_VEC3: l.rows = 3; break;
    case TINYGLTF_TYPE_VEC4: l.rows = 4; break;
    case TINYGLTF_TYPE_MAT2: l.rows = columns = 2; break;
    case TINYGLTF_TYPE_MAT3: l.rows = columns = 3; break;
    case TINYGLTF_TYPE_MAT4: l.rows = columns = 4; break;
    default: return {};
  }
  if (l.componentSize == 0) return {};
  l.components = l.rows * columns;
  l.columnStride = l.rows * l.componentSize;
  if (columns > 1) l.columnStride = (l.columnStride + 3) / 4 * 4;
  l.size = l.columnStride * columns;
  return l;
}

// One component as stored (integers as their integer value).
double storedComponent(const unsigned char* p, int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return static_cast<std::int8_t>(p[0]);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      std::int16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
    default: return 0.0;
  }
}

// glTF's "normalized" integers (spec, "Animations", the table of decoding equations).
double normalizedComponent(double stored, int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return std::max(stored / 127.0, -1.0);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return stored / 255.0;
    case TINYGLTF_COMPONENT_TYPE_SHORT: return std::max(stored / 32767.0, -1.0);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return stored / 65535.0;
    default: return stored;
  }
}

}  // namespace lenslab::gltf
