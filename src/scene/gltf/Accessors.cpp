#include "scene/gltf/Accessors.h"

#include "scene/gltf/Limits.h"
#include "scene/gltf/Problems.h"
#include "scene/gltf/TinygltfModel.h"

#include <algorithm>
#include <cmath>

namespace lenslab::gltf {

// The elements after sparse substitution, checked against the declared min/max (which hold
// stored values), then normalised integers mapped to [0, 1] or [-1, 1].
Elements AccessorReader::read(int index) const {
  const tinygltf::Accessor& a = model_.accessors[toIndex(index)];
  const std::string where = cat("accessor ", index);
  const ElementLayout layout = checkedLayout(a, where);
  Elements e;
  e.count = a.count;
  e.components = layout.components;
  e.values.assign(e.count * e.components, 0.0);
  if (a.bufferView >= 0) {
    const std::size_t stride = model_.bufferViews[toIndex(a.bufferView)].byteStride;
    decode(region(a.bufferView, a.byteOffset, a.count, layout, stride, where), a.count, layout, a.componentType,
           e.values.data());
  }
  if (a.sparse.isSparse) substituteSparse(a, layout, where, e);
  checkMinMax(a, where, e);
  if (a.normalized)
    for (double& v : e.values) v = normalizedComponent(v, a.componentType);
  return e;
}

void AccessorReader::checkLayout(int index) const {
  (void)checkedLayout(model_.accessors[toIndex(index)], cat("accessor ", index));
}

ElementLayout AccessorReader::checkedLayout(const tinygltf::Accessor& a, const std::string& where) const {
  const ElementLayout layout = elementLayout(a.type, a.componentType);
  if (layout.components == 0)
    refuse(where, ": ", typeName(a.type), " of ", componentTypeName(a.componentType),
           " is not a glTF accessor format (types SCALAR, VEC2-4, MAT2-4 of BYTE, UNSIGNED_BYTE, SHORT, "
           "UNSIGNED_SHORT, UNSIGNED_INT or FLOAT)");
  if (a.count == 0) refuse(where, ": count is 0; it must be at least 1");
  if (a.normalized && layout.componentSize > 2)
    refuse(where, ": normalized is set on ", componentTypeName(a.componentType),
           "; only BYTE, UNSIGNED_BYTE, SHORT and UNSIGNED_SHORT can be normalized");
  if (a.bufferView != -1) {
    requireIndex(a.bufferView, model_.bufferViews.size(), where, "bufferView");
    (void)region(a.bufferView, a.byteOffset, a.count, layout, model_.bufferViews[toIndex(a.bufferView)].byteStride,
                 where);
  } else if (a.count > kMaxUnbackedComponents / layout.components) {
    refuse(where, ": count ", a.count, " without a bufferView is more than lenslab reads (",
           kMaxUnbackedComponents / layout.components, " of ", typeName(a.type), ")");
  }
  return layout;
}

// `count` elements from `byteOffset` in a bufferView, after checking that all lie inside it.
AccessorReader::Region AccessorReader::region(int viewIndex, std::size_t byteOffset, std::size_t count,
                                              const ElementLayout& layout, std::size_t byteStride,
                                              const std::string& where) const {
  const Bytes view = viewBytes(model_, viewIndex, where);
  if (byteStride != 0 && byteStride < layout.size)
    refuse(where, ": byteStride ", byteStride, " of bufferView ", viewIndex, " is smaller than one element (",
           layout.size, " bytes)");
  const std::size_t stride = byteStride != 0 ? byteStride : layout.size;
  const std::size_t length = view.size();
  // Written so that nothing overflows, however large the count the file claims.
  if (byteOffset > length || layout.size > length - byteOffset ||
      count - 1 > (length - byteOffset - layout.size) / stride)
    refuse(where, ": byteOffset + count*stride exceeds bufferView ", viewIndex, " (byteOffset ", byteOffset, ", count ",
           count, ", stride ", stride, ", length ", length, ")");
  return {view.data() + byteOffset, stride};
}

void AccessorReader::decode(const Region& r, std::size_t count, const ElementLayout& layout, int componentType,
                            double* out) {
  for (std::size_t e = 0; e < count; ++e)
    for (std::size_t c = 0; c < layout.components; ++c)
      *out++ = storedComponent(r.first + e * r.stride + layout.offset(c), componentType);
}

// glTF sparse accessors: `count` strictly increasing element indices, each replaced by the value
// at the same position in the values view (both tightly packed).
void AccessorReader::substituteSparse(const tinygltf::Accessor& a, const ElementLayout& layout,
                                      const std::string& where, Elements& e) const {
  const auto& sparse = a.sparse;
  if (sparse.count < 1 || static_cast<std::size_t>(sparse.count) > e.count)
    refuse(where, ": sparse.count ", sparse.count, " must be from 1 to the accessor's count (", e.count, ")");
  if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) refuse(where, ": a sparse byteOffset is negative");
  const int indexType = sparse.indices.componentType;
  if (!isUnsignedIndexType(indexType))
    refuse(where, ": sparse.indices.componentType is ", componentTypeName(indexType),
           "; it must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
  const auto n = static_cast<std::size_t>(sparse.count);
  const ElementLayout indexLayout = elementLayout(TINYGLTF_TYPE_SCALAR, indexType);
  std::vector<double> targets(n), values(n * layout.components);
  decode(region(sparse.indices.bufferView, static_cast<std::size_t>(sparse.indices.byteOffset), n, indexLayout, 0,
                where + " sparse.indices"),
         n, indexLayout, indexType, targets.data());
  decode(region(sparse.values.bufferView, static_cast<std::size_t>(sparse.values.byteOffset), n, layout, 0,
                where + " sparse.values"),
         n, layout, a.componentType, values.data());
  for (std::size_t i = 0; i < n; ++i) {
    if (targets[i] >= static_cast<double>(e.count))
      refuse(where, ": sparse index ", targets[i], " is not below the accessor's count (", e.count, ")");
    if (i > 0 && targets[i] <= targets[i - 1])
      refuse(where, ": sparse indices must strictly increase (", targets[i - 1], " then ", targets[i], ")");
    std::copy_n(&values[i * e.components], e.components,
                &e.values[static_cast<std::size_t>(targets[i]) * e.components]);
  }
}

// The declared bounds must hold the data (the validator's ACCESSOR_ELEMENT_OUT_OF_*_BOUND).
void AccessorReader::checkMinMax(const tinygltf::Accessor& a, const std::string& where, const Elements& e) {
  for (const auto* bound : {&a.minValues, &a.maxValues})
    if (!bound->empty() && bound->size() != e.components)
      refuse(where, ": ", bound == &a.minValues ? "min" : "max", " has ", bound->size(), " numbers; a ",
             typeName(a.type), " accessor needs ", e.components);
  if (a.minValues.empty() && a.maxValues.empty()) return;
  // Float data is compared with a little slack: writers round min/max to a few decimals.
  auto slack = [&](double bound) {
    return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ? 1e-6 * (1.0 + std::abs(bound)) : 0.0;
  };
  for (std::size_t i = 0; i < e.count; ++i)
    for (std::size_t c = 0; c < e.components; ++c) {
      const double v = e.at(i, c);
      if (!std::isfinite(v)) refuse(where, ": element ", i, " is not a finite number");
      const bool low = !a.minValues.empty() && v < a.minValues[c] - slack(a.minValues[c]);
      const bool high = !a.maxValues.empty() && v > a.maxValues[c] + slack(a.maxValues[c]);
      if (low || high)
        refuse(where, ": element ", i, " component ", c, " is ", v, ", ",
               low ? "below the declared min " : "above the declared max ", low ? a.minValues[c] : a.maxValues[c]);
    }
}

}  // namespace lenslab::gltf
