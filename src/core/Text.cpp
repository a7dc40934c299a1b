#include "core/Text.h"

#include <algorithm>
#include <cctype>

namespace lenslab {

std::string oneLine(const std::string& text) {
  std::string out, line;
  std::istringstream in(text);
  while (std::getline(in, line)) {
    std::replace(line.begin(), line.end(), '\r', ' ');
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    const auto last = line.find_last_not_of(" \t");
    if (!out.empty()) out += "; ";
    out += line.substr(first, last - first + 1);
  }
  return out;
}

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace lenslab
