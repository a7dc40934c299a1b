#pragma once
// Message building without std::format (GCC 12 lacks it): cat("near (", 0.1, ") must ...").
// Numbers print with up to 10 significant digits, so messages echo what the user wrote.
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

}  // namespace lenslab
