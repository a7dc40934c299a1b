#pragma once
// The bounded, typed, range-checked reader of one object of a user's JSON file (a camera file, a
// key of a camera path): every value it returns has the type and range its key takes, and every
// refusal is one line naming the file and the key ("<file>: \"distortion.k1\" must be a number,
// not \"x\""). Numbers go through core/NumberInput's rules (finite, in range; its words in
// messages). It is the KeyReader the lens-effect modules read their keys through
// (lens/effects/LensEffectModule.h), so their messages are the reader's.
#include "camera/Rotation.h"
#include "lens/effects/LensEffectModule.h"

#include <glm/glm.hpp>
#include "core/NumberInput.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <memory>

#include <set>
#include <string>

namespace lenslab {

// "a, b, c" for messages that list the keys an object takes.
std::string joinedKeys(const std::set<std::string>& keys);

class JsonReader final : public KeyReader {
 public:
  JsonReader(const nlohmann::json& object, std::string where, std::string prefix = "")
      : object_(object), where_(std::move(where)), prefix_(std::move(prefix)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& message) const override;
  // A number's problem (core/NumberInput's words): "<where>: \"key\": 1e+300 is out of range; ...".
  // `what`, when given, says what the key holds: "\"K\" (the focal length in pixels): -500 is ...".
  [[noreturn]] void failNumber(const std::string& key, const std::string& problem, const std::string& what = "") const;

  bool has(const std::string& key) const override { return object_.contains(key); }
  bool isArray(const std::string& key) const override { return object_.at(key).is_array(); }
  double number(const std::string& key) const override;
  double distance(const std::string& key) const override;  // a number, or the string "infinity"
  int integer(const std::string& key) const override;
  std::size_t arraySize(const std::string& key) const override { return object_.at(key).size(); }
  std::optional<double> element(const std::string& key, std::size_t i) const override;
  std::string text(const std::string& key) const override { return object_.at(key).dump(); }
  void require(const std::string& key, const std::string& form) const override;
  std::unique_ptr<KeyReader> object(const std::string& key, const std::set<std::string>& allowed) const override {
    return std::make_unique<JsonReader>(child(key, allowed));
  }

  // An array of N finite numbers.
  template <int N>
  glm::vec<N, double> vector(const std::string& key) const;
  // A 3×3 matrix given row by row, [[a, b, c], [d, e, f], [g, h, i]], of finite numbers; `shape`
  // shows the rows in messages.
  RotationRows matrix3(const std::string& key, const std::string& shape) const;
  std::string string(const std::string& key) const override;
  // The object under `key`, read with keys named "key.sub" in messages; unknown keys are errors.
  JsonReader child(const std::string& key, const std::set<std::string>& allowed) const;

  const std::string& where() const { return where_; }

 private:
  const nlohmann::json& object_;
  std::string where_;
  std::string prefix_;  // "distortion." inside a nested object
};

template <int N>
glm::vec<N, double> JsonReader::vector(const std::string& key) const {
  const nlohmann::json& v = object_.at(key);
  const auto bad = [&] {
    fail(key, "must be an array of " + std::to_string(N) + " numbers, not " + excerpt(v.dump()));
  };
  if (!v.is_array() || v.size() != N) bad();
  glm::vec<N, double> out;
  for (int i = 0; i < N; ++i) {
    if (!v[static_cast<std::size_t>(i)].is_number()) bad();
    out[i] = v[static_cast<std::size_t>(i)].get<double>();
    if (!std::isfinite(out[i])) fail(key, "must hold finite numbers");
  }
  return out;
}

}  // namespace lenslab
