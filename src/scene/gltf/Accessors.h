#pragma once
// Accessors: the numbers an accessor holds, read with every byte checked (bufferView range,
// stride, count), sparse values substituted, declared min/max enforced, normalised integers
// mapped to [0, 1] or [-1, 1].
#include "scene/gltf/ComponentTypes.h"

#include <tiny_gltf.h>

#include <cstddef>
#include <string>
#include <vector>

namespace lenslab::gltf {

struct Elements {
  std::size_t count = 0;
  std::size_t components = 0;
  std::vector<double> values;  // count × components, element after element
  double at(std::size_t element, std::size_t component) const { return values[element * components + component]; }
};

// Reads accessors with every byte checked; tinygltf 2.7 gives only the JSON fields (it neither
// checks ranges nor applies sparse substitution).
// tinygltf-2.7: accessor ranges are checked and sparse accessors applied here, which tinygltf 2.7
// does not do; can go when tinygltf is upgraded to one that does both (verify; min/max stays).
class AccessorReader {
 public:
  explicit AccessorReader(const tinygltf::Model& model) : model_(model) {}

  // The elements after sparse substitution, checked against the declared min/max (which hold
  // stored values), then normalised integers mapped to [0, 1] or [-1, 1].
  Elements read(int index) const;

  // Everything about the accessor that can be checked without reading its data.
  void checkLayout(int index) const;

 private:
  struct Region {
    const unsigned char* first = nullptr;
    std::size_t stride = 0;
  };

  ElementLayout checkedLayout(const tinygltf::Accessor& a, const std::string& where) const;
  Region region(int viewIndex, std::size_t byteOffset, std::size_t count, const ElementLayout& layout,
                std::size_t byteStride, const std::string& where) const;
  static void decode(const Region& r, std::size_t count, const ElementLayout& layout, int componentType, double* out);
  void substituteSparse(const tinygltf::Accessor& a, const ElementLayout& layout, const std::string& where,
                        Elements& e) const;
  static void checkMinMax(const tinygltf::Accessor& a, const std::string& where, const Elements& e);

  const tinygltf::Model& model_;
};

}  // namespace lenslab::gltf
