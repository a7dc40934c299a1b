#pragma once
// A JSON document a user wrote (a camera file, a camera path), parsed with the checks every such
// file gets: nesting bounded (the messages quote values with dump(), which recurses once per
// level), a key given twice in one object refused (nlohmann keeps the last silently, so the value
// the user reads first would be ignored), and the parser's own message cut to its useful part.
#include <nlohmann/json.hpp>

#include <string>

namespace lenslab {

constexpr int kMaxJsonDepth = 64;

// Throws InputError "<where>: ..." in one line.
nlohmann::json parseJsonDocument(const std::string& text, const std::string& where);

}  // namespace lenslab
