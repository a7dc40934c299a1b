#include "scene/gltf/Problems.h"

#include <algorithm>
#include <sstream>

namespace lenslab::gltf {

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

void noteOnce(std::vector<std::string>& notes, const std::string& note) {
  if (std::find(notes.begin(), notes.end(), note) == notes.end()) notes.push_back(note);
}

void requireIndex(int index, std::size_t count, const std::string& what, const char* kind) {
  if (index < 0 || static_cast<std::size_t>(index) >= count)
    refuse(what, " refers to ", kind, " ", index, ", which does not exist (",
           count == 0 ? std::string("the file has none") : cat("valid: 0 to ", count - 1), ")");
}

}  // namespace lenslab::gltf
