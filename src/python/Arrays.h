#pragma once
// NumPy arrays over lenslab's buffers without a copy: the vector moves into a capsule that the
// array keeps alive (its `base`), and is freed with the last reference to the array; or a
// read-only view of a buffer whose owner the capsule keeps.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace lenslab::python {

template <class T>
pybind11::array_t<T> arrayOf(std::vector<T>&& values, std::vector<pybind11::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(values));
  pybind11::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return pybind11::array_t<T>(std::move(shape), owned->data(), owner);
}

// A read-only NumPy view of `values`, which `owner` keeps alive (the array's `base` holds it).
template <class T>
pybind11::array_t<T> readOnlyView(const std::vector<T>& values, std::vector<pybind11::ssize_t> shape,
                                  std::shared_ptr<const void> owner) {
  auto* kept = new std::shared_ptr<const void>(std::move(owner));
  pybind11::capsule base(kept, [](void* p) { delete static_cast<std::shared_ptr<const void>*>(p); });
  pybind11::array_t<T> array(std::move(shape), values.data(), base);
  array.attr("setflags")(pybind11::arg("write") = false);
  return array;
}

}  // namespace lenslab::python
