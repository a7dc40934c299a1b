#pragma once
// Message building without std::format (GCC 12 lacks it): cat("near (", 0.1, ") must ...").
// Numbers print with up to 10 significant digits, so messages echo what the user wrote. And the
// small text helpers messages and file names share.
#include <filesystem>
#include <sstream>
#include <string>

namespace lenslab {

template <class... Parts>
std::string cat(const Parts&... parts) {
  std::ostringstream out;
  out.precision(10);
  (out << ... << parts);
  return out.str();
}

// A library's message as one line of ours: its lines trimmed and joined with "; " (tinygltf and
// OpenImageIO end their errors with newlines, and may hold several).
std::string oneLine(const std::string& text);

// The file name's extension in lower case, with its dot: ".png" for "Frame.PNG" (how the readers
// and writers choose a format).
std::string lowerExtension(const std::filesystem::path& path);

}  // namespace lenslab
