#pragma once
// Problems and notes, shared by every part of the glTF loader: a problem with the file is thrown
// as Problem (loadGltf turns it into an InputError naming the file); what is left out of the
// scene is a note. Internal to the loader (src/scene/gltf and src/scene/GltfLoader.cpp).
#include "core/Text.h"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace lenslab::gltf {

// A problem with the file, in words; loadGltf prefixes the file name and throws InputError.
struct Problem : std::runtime_error {
  using std::runtime_error::runtime_error;
};

template <class... Parts>
[[noreturn]] void refuse(const Parts&... parts) {
  throw Problem(cat(parts...));
}

// "a, b, c"
std::string joined(const std::vector<std::string>& names);

void noteOnce(std::vector<std::string>& notes, const std::string& note);

// Refuses an index outside [0, count), naming `what` refers to it and the valid range.
void requireIndex(int index, std::size_t count, const std::string& what, const char* kind);

inline std::size_t toIndex(int index) { return static_cast<std::size_t>(index); }

}  // namespace lenslab::gltf
