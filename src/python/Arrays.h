#pragma once
// NumPy arrays over lenslab's buffers without a copy: the vector moves into a capsule that the
// array keeps alive (its `base`), and is freed with the last reference to the array.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace lenslab::python {

template <class T>
pybind11::array_t<T> arrayOf(std::vector<T>&& values, std::vector<pybind11::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(values));
  pybind11::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return pybind11::array_t<T>(std::move(shape), owned->data(), owner);
}

}  // namespace lenslab::python
