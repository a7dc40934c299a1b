#pragma once
// Numbers read from text the same way everywhere: std::from_chars over the whole field, so no
// locale, no white space or leading '+', and nothing after the number.
#include <charconv>
#include <cmath>
#include <optional>
#include <string_view>

namespace lenslab {

// The double that all of `text` spells, or nullopt; "inf" and "nan" are read as such.
inline std::optional<double> parseDouble(std::string_view text) {
  double value = 0.0;
  const char* const end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end) return std::nullopt;
  return value;
}

// parseDouble's value when it is finite.
inline std::optional<double> parseFiniteNumber(std::string_view text) {
  const std::optional<double> value = parseDouble(text);
  if (!value || !std::isfinite(*value)) return std::nullopt;
  return value;
}

}  // namespace lenslab
