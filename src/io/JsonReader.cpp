#include "io/JsonReader.h"

#include "core/Error.h"
#include "core/NumberInput.h"
#include "core/Text.h"

#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>

namespace lenslab {

using nlohmann::json;

std::string joinedKeys(const std::set<std::string>& keys) {
  std::string s;
  for (const std::string& k : keys) s += (s.empty() ? "" : ", ") + k;
  return s;
}

void JsonReader::fail(const std::string& key, const std::string& message) const {
  throw InputError(cat(where_, ": \"", prefix_, key, "\" ", message));
}

void JsonReader::failNumber(const std::string& key, const std::string& problem, const std::string& what) const {
  throw InputError(cat(where_, ": \"", prefix_, key, "\"", what.empty() ? "" : cat(" (", what, ")"), ": ", problem));
}

double JsonReader::number(const std::string& key) const {
  const json& v = object_.at(key);
  if (!v.is_number()) fail(key, cat("must be a number, not ", excerpt(v.dump())));
  // core/NumberInput's finiteness rule (JSON has no nan, but 1e309 reads as infinity).
  if (const auto problem = numberProblem(v.get<double>(), NumberRange{})) failNumber(key, *problem);
  return v.get<double>();
}

double JsonReader::distance(const std::string& key) const {
  const json& v = object_.at(key);
  if (v.is_string() && v.get<std::string>() == "infinity") return std::numeric_limits<double>::infinity();
  if (!v.is_number()) fail(key, cat("must be a number or \"infinity\", not ", excerpt(v.dump())));
  return number(key);
}

int JsonReader::integer(const std::string& key) const {
  const json& v = object_.at(key);
  if (!v.is_number_integer()) fail(key, cat("must be a whole number, not ", excerpt(v.dump())));
  // get<int>() wraps what int cannot hold (4294967297 would be read as 1): refused instead.
  const bool fits = v.is_number_unsigned() ? v.get<std::uint64_t>() <= INT_MAX
                                           : v.get<std::int64_t>() >= INT_MIN && v.get<std::int64_t>() <= INT_MAX;
  if (!fits) fail(key, cat("is ", excerpt(v.dump()), "; give a whole number from ", INT_MIN, " to ", INT_MAX));
  return v.get<int>();
}

std::optional<double> JsonReader::element(const std::string& key, std::size_t i) const {
  const json& v = object_.at(key).at(i);
  if (!v.is_number() || !std::isfinite(v.get<double>())) return std::nullopt;
  return v.get<double>();
}

void JsonReader::require(const std::string& key, const std::string& form) const {
  if (!has(key)) throw InputError(cat(where_, ": \"", prefix_, key, "\" is missing; the ", form, " form needs it"));
}

RotationRows JsonReader::matrix3(const std::string& key, const std::string& shape) const {
  const json& v = object_.at(key);
  const auto bad = [&] {
    fail(key, cat("must be a 3×3 matrix given row by row, ", shape, ", of finite numbers, not ", excerpt(v.dump())));
  };
  if (!v.is_array() || v.size() != 3) bad();
  RotationRows m;
  for (std::size_t i = 0; i < 3; ++i) {
    if (!v[i].is_array() || v[i].size() != 3) bad();
    for (std::size_t c = 0; c < 3; ++c) {
      if (!v[i][c].is_number()) bad();
      m[i][static_cast<int>(c)] = v[i][c].get<double>();
      if (!std::isfinite(m[i][static_cast<int>(c)])) bad();
    }
  }
  return m;
}

std::string JsonReader::string(const std::string& key) const {
  const json& v = object_.at(key);
  if (!v.is_string()) fail(key, cat("must be a string, not ", excerpt(v.dump())));
  return v.get<std::string>();
}

JsonReader JsonReader::child(const std::string& key, const std::set<std::string>& allowed) const {
  const json& v = object_.at(key);
  if (!v.is_object())
    fail(key, cat("must be an object with keys among ", joinedKeys(allowed), ", not ", excerpt(v.dump())));
  for (const auto& item : v.items())
    if (allowed.count(item.key()) == 0)
      throw InputError(cat(where_, ": unknown key \"", key, ".", excerpt(item.key()), "\"; \"", key, "\" takes ",
                           joinedKeys(allowed)));
  return JsonReader(v, where_, key + ".");
}

}  // namespace lenslab
